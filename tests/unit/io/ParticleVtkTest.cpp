#include "io/ParticleVtk.hpp"

#include "core/Error.hpp"
#include "sph/ParticleSet.hpp"
#include "ScratchDirectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

#include <unistd.h>

namespace poro {
namespace {

using test::contains;
using test::readAll;
using test::ScratchDirectory;

/// Random finite doubles drawn from all bit patterns: every exponent, subnormals, -0.0.
class RandomDoubles {
public:
  explicit RandomDoubles(std::uint64_t seed) : engine_(seed) {}
  double operator()() {
    for (;;) {
      const std::uint64_t bits = engine_();
      double value;
      std::memcpy(&value, &bits, sizeof value);
      if (std::isfinite(value)) return value;
    }
  }
  std::int64_t integer() { return static_cast<std::int64_t>(engine_()); }

private:
  std::mt19937_64 engine_;
};

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// How strictly expectBitEqual compares doubles.
enum class Exactness { Bits, BitsButZeroSign };

/// A fluid set with one field of every type and role, filled with random bit patterns.
ParticleSet makeSet(std::size_t n, std::uint64_t seed = 42) {
  ParticleSet set("fluid", SetKind::Fluid);
  set.addReal("p", Restart);
  set.addVec3("a", Output);
  set.addMat3("F", Restart);
  set.addInt("flag", Output);
  set.addReal("scratch", Scratch);
  set.resize(n);
  RandomDoubles random(seed);
  for (std::size_t i = 0; i < n; ++i) {
    set.integer(field::id)[i] = random.integer();
    set.integer(field::objectId)[i] = static_cast<std::int64_t>(i % 3);
    set.integer("flag")[i] = random.integer();
    set.real("p")[i] = random();
    set.real("scratch")[i] = random();
    for (int c = 0; c < 3; ++c) {
      set.x()[i][c] = random();
      set.v()[i][c] = random();
      set.vec3("a")[i][c] = random();
    }
    for (int k = 0; k < 9; ++k) set.mat3("F")[i](k / 3, k % 3) = random();
  }
  if (n >= 2) {
    // Values that stress a text format: extremes, smallest subnormal, signed zero.
    set.real("p")[0] = std::numeric_limits<double>::denorm_min();
    set.real("p")[1] = -0.0;
    set.vec3("a")[0] = Vec3(std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(), 0.1);
    set.integer("flag")[0] = std::numeric_limits<std::int64_t>::min();
    set.integer("flag")[1] = std::numeric_limits<std::int64_t>::max();
  }
  return set;
}

/// Counts the particles whose fields differ bit for bit, over every Output field of `expected`.
void expectBitEqual(const ParticleSet& expected, const ParticleSet& actual,
                    Exactness exactness = Exactness::Bits) {
  const auto same = [&](double a, double b) {
    return sameBits(a, b) || (exactness == Exactness::BitsButZeroSign && a == 0.0 && b == 0.0);
  };
  ASSERT_EQ(expected.size(), actual.size());
  for (const auto& info : expected.fields()) {
    if ((info.role & Output) == 0) continue;
    SCOPED_TRACE("field " + info.name);
    ASSERT_TRUE(actual.has(info.name));
    ASSERT_EQ(actual.info(info.name)->type, info.type);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      switch (info.type) {
      case FieldType::Real:
        if (!same(expected.real(info.name)[i], actual.real(info.name)[i])) {
          if (mismatches == 0)
            ADD_FAILURE() << "particle " << i << ": " << expected.real(info.name)[i] << " read as "
                          << actual.real(info.name)[i];
          ++mismatches;
        }
        break;
      case FieldType::Vec3:
        for (int c = 0; c < 3; ++c)
          mismatches += !same(expected.vec3(info.name)[i][c], actual.vec3(info.name)[i][c]);
        break;
      case FieldType::Mat3:
        for (int k = 0; k < 9; ++k)
          mismatches += !same(expected.mat3(info.name)[i](k / 3, k % 3), actual.mat3(info.name)[i](k / 3, k % 3));
        break;
      case FieldType::Int: mismatches += expected.integer(info.name)[i] != actual.integer(info.name)[i]; break;
      }
    }
    EXPECT_EQ(mismatches, 0u);
  }
}

/// An ascii .vtp with three points and the given <PointData> content.
std::string handWrittenVtp(const std::string& pointData) {
  return R"(<?xml version="1.0"?>
<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <PolyData>
    <Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="0">
      <PointData>
)" + pointData + R"(
      </PointData>
      <Points>
        <DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">
          0 0 0 1 0 0 0 1 0
        </DataArray>
      </Points>
    </Piece>
  </PolyData>
</VTKFile>
)";
}

TEST(ParticleVtk, BinaryRoundTripIsBitExact) {
  ScratchDirectory dir;
  const ParticleSet written = makeSet(1000);
  writeParticleSet(written, dir / "fluid.vtp", true);

  ParticleSet read("fluid", SetKind::Fluid);
  readParticleSet(read, dir / "fluid.vtp");
  expectBitEqual(written, read);
  // Arrays the set did not know are registered for output.
  EXPECT_EQ(read.info("p")->role, Output);
  EXPECT_EQ(read.info(field::x)->role, Restart);
  EXPECT_FALSE(read.has("scratch"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"fluid.vtp"}) << "temporary file left behind";
}

TEST(ParticleVtk, BinaryFileIsAppendedAndCompressed) {
  ScratchDirectory dir;
  writeParticleSet(makeSet(100), dir / "fluid.vtp", true);
  const std::string text = readAll(dir / "fluid.vtp");
  EXPECT_TRUE(contains(text, "compressor=\"vtkZLibDataCompressor\""));
  EXPECT_TRUE(contains(text, "<AppendedData encoding=\"raw\">"));
}

TEST(ParticleVtk, AsciiRoundTripIsBitExactUpToTheSignOfZero) {
  // VTK 9.1 prints doubles with the shortest digits that round-trip, so random bit patterns, subnormals
  // and DBL_MAX survive the text format; it prints -0.0 as "0", though.
  ScratchDirectory dir;
  const ParticleSet written = makeSet(300, 7);
  writeParticleSet(written, dir / "fluid.vtp", false);
  EXPECT_FALSE(contains(readAll(dir / "fluid.vtp"), "<AppendedData"));

  ParticleSet read("fluid", SetKind::Fluid);
  readParticleSet(read, dir / "fluid.vtp");
  expectBitEqual(written, read, Exactness::BitsButZeroSign);
  EXPECT_EQ(read.real("p")[0], std::numeric_limits<double>::denorm_min());
  EXPECT_FALSE(std::signbit(read.real("p")[1])) << "VTK's ascii keeps -0.0 now: tighten this test";
}

TEST(ParticleVtk, ReadIntoRegisteredFieldsKeepsTheirRoles) {
  ScratchDirectory dir;
  const ParticleSet written = makeSet(50);
  writeParticleSet(written, dir / "fluid.vtp", true);

  ParticleSet read("fluid", SetKind::Fluid);
  read.addReal("p", Restart);
  read.addVec3("a", Scratch);
  read.addReal("notInFile", Restart);
  read.resize(7);
  read.real("notInFile").assign(7, 3.0);
  readParticleSet(read, dir / "fluid.vtp");
  expectBitEqual(written, read);
  EXPECT_EQ(read.info("p")->role, Restart);
  EXPECT_EQ(read.info("a")->role, Scratch);
  // A field the file lacks is zero, not a stale value from before the read.
  ASSERT_EQ(read.real("notInFile").size(), 50u);
  for (double value : read.real("notInFile")) EXPECT_EQ(value, 0.0);
}

TEST(ParticleVtk, ScratchFieldsAndPositionsAreNotPointData) {
  ScratchDirectory dir;
  writeParticleSet(makeSet(10), dir / "fluid.vtp", false);
  const std::string text = readAll(dir / "fluid.vtp");
  EXPECT_FALSE(contains(text, "Name=\"scratch\""));
  EXPECT_FALSE(contains(text, "Name=\"x\""));
  EXPECT_TRUE(contains(text, "Name=\"p\""));
  EXPECT_TRUE(contains(text, "Name=\"F\" NumberOfComponents=\"9\""));
  EXPECT_TRUE(contains(text, "type=\"Int64\" Name=\"flag\""));
  EXPECT_TRUE(contains(text, "type=\"Float64\" Name=\"Points\""));
  // One vertex cell per particle so ParaView draws the points.
  EXPECT_TRUE(contains(text, "NumberOfVerts=\"10\""));
  EXPECT_TRUE(contains(text, "Name=\"setName\""));
  EXPECT_TRUE(contains(text, "Name=\"kind\""));
}

TEST(ParticleVtk, Mat3IsRowMajorInTheFile) {
  ScratchDirectory dir;
  ParticleSet set("porous", SetKind::Porous);
  auto& F = set.addMat3("F", Output);
  set.resize(1);
  F[0] << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  writeParticleSet(set, dir / "porous.vtp", false);
  const std::string text = readAll(dir / "porous.vtp");
  const auto start = text.find("Name=\"F\"");
  ASSERT_NE(start, std::string::npos);
  std::istringstream values(text.substr(text.find('>', start) + 1));
  std::vector<double> first(9);
  for (double& value : first) values >> value;
  EXPECT_EQ(first, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(ParticleVtk, EmptySetRoundTrips) {
  ScratchDirectory dir;
  const ParticleSet written = makeSet(0);
  writeParticleSet(written, dir / "fluid.vtp", true);
  ParticleSet read("fluid", SetKind::Fluid);
  read.resize(5);
  readParticleSet(read, dir / "fluid.vtp");
  EXPECT_EQ(read.size(), 0u);
  EXPECT_TRUE(read.has("F"));
}

TEST(ParticleVtk, TruncatedFileIsAnInputErrorNamingTheFile) {
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    ScratchDirectory dir;
    const auto file = dir / "fluid.vtp";
    writeParticleSet(makeSet(500), file, binary);
    const auto size = std::filesystem::file_size(file);
    std::filesystem::resize_file(file, size / 2);

    ParticleSet read("fluid", SetKind::Fluid);
    try {
      readParticleSet(read, file);
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
      EXPECT_TRUE(contains(e.what(), "not a readable VTK PolyData file"));
    }
    EXPECT_EQ(read.size(), 0u) << "a failed read must leave the set unchanged";
  }
}

TEST(ParticleVtk, GarbageFileIsAnInputError) {
  ScratchDirectory dir;
  const auto file = dir / "garbage.vtp";
  test::writeAll(file, "this is not XML at all \x01\x02\x03\n");
  ParticleSet read("fluid", SetKind::Fluid);
  try {
    readParticleSet(read, file);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file.string() + ": ", 0), 0u) << e.what();
  }
}

TEST(ParticleVtk, EmptyFileIsAnInputError) {
  ScratchDirectory dir;
  test::writeAll(dir / "empty.vtp", "");
  ParticleSet read("fluid", SetKind::Fluid);
  EXPECT_THROW(readParticleSet(read, dir / "empty.vtp"), InputError);
}

TEST(ParticleVtk, OtherVtkDataTypeIsAnInputError) {
  ScratchDirectory dir;
  test::writeAll(dir / "grid.vtu", R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">
  <UnstructuredGrid><Piece NumberOfPoints="0" NumberOfCells="0"></Piece></UnstructuredGrid>
</VTKFile>
)");
  ParticleSet read("fluid", SetKind::Fluid);
  EXPECT_THROW(readParticleSet(read, dir / "grid.vtu"), InputError);
}

TEST(ParticleVtk, MissingFileIsAnInputErrorWithTheOsReason) {
  ScratchDirectory dir;
  ParticleSet read("fluid", SetKind::Fluid);
  try {
    readParticleSet(read, dir / "missing.vtp");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), (dir / "missing.vtp").string()));
    EXPECT_TRUE(contains(e.what(), std::strerror(ENOENT)));
  }
}

TEST(ParticleVtk, HandWrittenAsciiFileIsRead) {
  ScratchDirectory dir;
  test::writeAll(dir / "hand.vtp", handWrittenVtp(R"(
        <DataArray type="Float32" Name="rho" format="ascii">1000 1001 1002</DataArray>
        <DataArray type="Int32" Name="id" format="ascii">5 6 7</DataArray>)"));
  ParticleSet read("fluid", SetKind::Fluid);
  readParticleSet(read, dir / "hand.vtp");
  ASSERT_EQ(read.size(), 3u);
  EXPECT_EQ(read.real("rho")[2], 1002.0);
  EXPECT_EQ(read.integer(field::id)[1], 6);
  EXPECT_EQ(read.x()[1], Vec3(1, 0, 0));
}

TEST(ParticleVtk, ShortArrayIsAnInputErrorNamingTheArray) {
  ScratchDirectory dir;
  const auto file = dir / "short.vtp";
  test::writeAll(file, handWrittenVtp(
                           R"(<DataArray type="Float64" Name="shortPressure" format="ascii">1 2</DataArray>)"));
  ParticleSet read("fluid", SetKind::Fluid);
  try {
    readParticleSet(read, file);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ":6: array 'shortPressure' holds 2 values, expected 3 "
                                                     "(NumberOfPoints 3 times 1 component)");
  }
}

/// The message of the InputError reading `vtp` gives, or "" (a test failure) if there is none.
std::string readError(const ScratchDirectory& dir, const std::string& vtp) {
  const auto file = dir / "hand.vtp";
  test::writeAll(file, vtp);
  ParticleSet read("fluid", SetKind::Fluid);
  try {
    readParticleSet(read, file);
  } catch (const InputError& e) {
    EXPECT_EQ(read.size(), 0u) << "a failed read must leave the set unchanged";
    return std::string(e.what()).substr(file.string().size());
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(ParticleVtk, AsciiArraysAreCheckedValueByValueWithTheirLine) {
  ScratchDirectory dir;
  // Too long is as wrong as too short (VTK alone would read the first three values and drop the rest).
  EXPECT_EQ(readError(dir, handWrittenVtp(R"(<DataArray type="Int64" Name="id" format="ascii">0 1 2 3</DataArray>)")),
            ":6: array 'id' holds 4 values, expected 3 (NumberOfPoints 3 times 1 component)");
  EXPECT_EQ(readError(dir, handWrittenVtp(R"(
        <DataArray type="Float64" Name="v" NumberOfComponents="3" format="ascii">
          0 0 0
          0 abc 0
          0 0 0
        </DataArray>)")),
            ":9: array 'v': value 'abc' (particle 1) is not a number");
  EXPECT_EQ(
      readError(dir, handWrittenVtp(R"(<DataArray type="Float64" Name="p" format="ascii">1 1e400 2</DataArray>)")),
      ":6: array 'p': value '1e400' (particle 1) is out of the range of Float64");
  EXPECT_EQ(readError(dir, handWrittenVtp(R"(<DataArray type="Float32" Name="p" format="ascii">1 2 1e39</DataArray>)")),
            ":6: array 'p': value '1e39' (particle 2) is out of the range of Float32");
  EXPECT_EQ(readError(dir, handWrittenVtp(R"(<DataArray type="Int32" Name="id" format="ascii">1 2.5 3</DataArray>)")),
            ":6: array 'id': value '2.5' (particle 1) is not a whole number (the array is Int32)");
  EXPECT_EQ(readError(dir, handWrittenVtp(R"(<DataArray type="UInt8" Name="flag" format="ascii">1 256 3</DataArray>)")),
            ":6: array 'flag': value '256' (particle 1) is out of the range of UInt8");
  // The coordinates: handWrittenVtp puts their DataArray on line 9.
  std::string shortPoints = handWrittenVtp("");
  shortPoints.replace(shortPoints.find("0 0 0 1 0 0 0 1 0"), 17, "0 0 0 1 0 0 0 1");
  EXPECT_EQ(readError(dir, shortPoints), ":9: array 'Points' of point coordinates holds 8 values, expected 9 "
                                         "(NumberOfPoints 3 times 3 components)");
}

TEST(ParticleVtk, ImpossiblePointCountsAreRefusedBeforeAllocating) {
  ScratchDirectory dir;
  std::string vtp = handWrittenVtp("");
  const std::string three = "NumberOfPoints=\"3\"";
  vtp.replace(vtp.find(three), three.size(), "NumberOfPoints=\"99999999999\"");
  const std::string huge = readError(dir, vtp);
  EXPECT_TRUE(contains(huge, ": Piece NumberOfPoints=\"99999999999\" cannot be right for a file of ")) << huge;
  vtp.replace(vtp.find("99999999999"), 11, "-5");
  EXPECT_EQ(readError(dir, vtp), ": Piece NumberOfPoints=\"-5\" is negative");
}

TEST(ParticleVtk, CorruptBinaryBlockIsAnInputError) {
  // 0xFF over a compressed block header: VTK would try to allocate what the corrupt sizes say.
  ScratchDirectory dir;
  const auto file = dir / "fluid.vtp";
  writeParticleSet(makeSet(500), file, true);
  std::string bytes = readAll(file);
  const std::size_t data = bytes.find("<AppendedData");
  ASSERT_NE(data, std::string::npos);
  for (std::size_t k = 0; k < 16; ++k) bytes[(data + bytes.size()) / 2 + k] = '\xFF';
  const std::string message = readError(dir, bytes);
  EXPECT_TRUE(contains(message, "not a readable VTK PolyData file")) << message;
}

TEST(ParticleVtk, TypeMismatchIsAnInputErrorNamingTheArray) {
  ScratchDirectory dir;
  const auto file = dir / "mismatch.vtp";
  test::writeAll(file, handWrittenVtp(
                           R"(<DataArray type="Float64" Name="p" format="ascii">1 2 3</DataArray>)"));
  ParticleSet read("fluid", SetKind::Fluid);
  read.addVec3("p", Restart);
  try {
    readParticleSet(read, file);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "array 'p'"));
  }
  // Float data into an Int field is a mismatch too.
  test::writeAll(file, handWrittenVtp(
                           R"(<DataArray type="Float64" Name="id" format="ascii">1 2 3</DataArray>)"));
  EXPECT_THROW(readParticleSet(read, file), InputError);
}

TEST(ParticleVtk, UnsupportedComponentCountIsAnInputError) {
  ScratchDirectory dir;
  const auto file = dir / "twoComponents.vtp";
  test::writeAll(file, handWrittenVtp(R"(<DataArray type="Float64" Name="uv" NumberOfComponents="2" format="ascii">
          1 2 3 4 5 6</DataArray>)"));
  ParticleSet read("fluid", SetKind::Fluid);
  try {
    readParticleSet(read, file);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "array 'uv'"));
  }
}

TEST(ParticleVtk, NanInRestartFieldIsAnInputErrorNamingArrayAndParticle) {
  ScratchDirectory dir;
  ParticleSet written = makeSet(20);
  written.real("p")[7] = std::numeric_limits<double>::quiet_NaN();
  writeParticleSet(written, dir / "fluid.vtp", true);

  ParticleSet restart("fluid", SetKind::Fluid);
  restart.addReal("p", Restart);
  try {
    readParticleSet(restart, dir / "fluid.vtp");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "array 'p'"));
    EXPECT_TRUE(contains(e.what(), "particle 7"));
  }
  EXPECT_EQ(restart.size(), 0u);

  // Viewing (p not a restart field) accepts it.
  ParticleSet view("fluid", SetKind::Fluid);
  readParticleSet(view, dir / "fluid.vtp");
  EXPECT_TRUE(std::isnan(view.real("p")[7]));
}

TEST(ParticleVtk, InfiniteVelocityIsAnInputError) {
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    ScratchDirectory dir;
    ParticleSet written = makeSet(20);
    written.v()[12].y() = std::numeric_limits<double>::infinity();
    writeParticleSet(written, dir / "fluid.vtp", binary);
    ParticleSet read("fluid", SetKind::Fluid);
    try {
      readParticleSet(read, dir / "fluid.vtp");
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_TRUE(contains(e.what(), "array 'v'"));
      EXPECT_TRUE(contains(e.what(), "particle 12"));
    }
  }
}

TEST(ParticleVtk, NonFiniteValuesOfOutputFieldsRoundTrip) {
  // A diverged run must still be viewable: NaN and inf in output-only fields survive both formats.
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    ScratchDirectory dir;
    ParticleSet written("fluid", SetKind::Fluid);
    auto& p = written.addReal("p", Output);
    auto& a = written.addVec3("a", Output);
    auto& F = written.addMat3("F", Output);
    written.resize(4);
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    p = {inf, -inf, nan, 1.0};
    a[0] = Vec3(inf, 0, 0);
    a[1] = Vec3(nan, 1, 2);
    F[2](1, 2) = -inf;
    F[3](0, 0) = nan;
    writeParticleSet(written, dir / "fluid.vtp", binary);
    // VTK cannot read NaN/inf from ascii, so such a set is written binary whatever was asked.
    EXPECT_TRUE(contains(readAll(dir / "fluid.vtp"), "<AppendedData"));
    ParticleSet read("fluid", SetKind::Fluid);
    readParticleSet(read, dir / "fluid.vtp");
    EXPECT_EQ(read.real("p")[0], inf);
    EXPECT_EQ(read.real("p")[1], -inf);
    EXPECT_TRUE(std::isnan(read.real("p")[2]));
    EXPECT_EQ(read.vec3("a")[0].x(), inf);
    EXPECT_TRUE(std::isnan(read.vec3("a")[1].x()));
    EXPECT_EQ(read.vec3("a")[1].z(), 2.0);
    EXPECT_EQ(read.mat3("F")[2](1, 2), -inf);
    EXPECT_TRUE(std::isnan(read.mat3("F")[3](0, 0)));
  }
}

TEST(ParticleVtk, NanPositionIsAnInputError) {
  ScratchDirectory dir;
  ParticleSet written = makeSet(20);
  written.x()[3].z() = std::numeric_limits<double>::quiet_NaN();
  writeParticleSet(written, dir / "fluid.vtp", true);
  ParticleSet read("fluid", SetKind::Fluid);
  try {
    readParticleSet(read, dir / "fluid.vtp");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "particle 3"));
  }
}

TEST(ParticleVtk, OtherSetKindIsAnInputError) {
  ScratchDirectory dir;
  writeParticleSet(makeSet(5), dir / "fluid.vtp", true);
  ParticleSet porous("porous", SetKind::Porous);
  try {
    readParticleSet(porous, dir / "fluid.vtp");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "'fluid'"));
    EXPECT_TRUE(contains(e.what(), "'porous'"));
  }
}

TEST(ParticleVtk, RewriteReplacesTheFile) {
  ScratchDirectory dir;
  writeParticleSet(makeSet(100, 1), dir / "fluid.vtp", true);
  const ParticleSet second = makeSet(30, 2);
  writeParticleSet(second, dir / "fluid.vtp", true);
  ParticleSet read("fluid", SetKind::Fluid);
  readParticleSet(read, dir / "fluid.vtp");
  expectBitEqual(second, read);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"fluid.vtp"});
}

TEST(ParticleVtk, MissingDirectoryIsAnOutputError) {
  ScratchDirectory dir;
  const auto file = dir / "0.1" / "fluid.vtp";
  try {
    writeParticleSet(makeSet(5), file, true);
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_TRUE(contains(e.what(), file.string()));
    EXPECT_TRUE(contains(e.what(), std::strerror(ENOENT)));
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ParticleVtk, ReadOnlyDirectoryIsAnOutputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  ScratchDirectory dir;
  const auto readOnly = dir / "0.1";
  std::filesystem::create_directory(readOnly);
  std::filesystem::permissions(readOnly, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  try {
    writeParticleSet(makeSet(5), readOnly / "fluid.vtp", true);
    FAIL() << "expected OutputError";
  } catch (const OutputError& e) {
    EXPECT_TRUE(contains(e.what(), (readOnly / "fluid.vtp").string()));
    EXPECT_TRUE(contains(e.what(), std::strerror(EACCES)));
  }
}

TEST(ParticleVtk, UnwritableTargetIsAnOutputErrorAndLeavesNoTemporary) {
  // Works as root too: a directory cannot be replaced by a file.
  ScratchDirectory dir;
  std::filesystem::create_directories(dir / "fluid.vtp" / "occupied");
  EXPECT_THROW(writeParticleSet(makeSet(5), dir / "fluid.vtp", true), OutputError);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"fluid.vtp"});
}

} // namespace
} // namespace poro
