// Porous sets on disk: one porous.vtp per time directory, split back into one set per material by materialId.

#include "io/PorousSets.hpp"

#include "ScratchDirectory.hpp"
#include "core/Error.hpp"
#include "io/ParticleVtk.hpp"
#include "io/PvdSeries.hpp"
#include "io/TimeDirectory.hpp"
#include "physics/FieldNames.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <optional>
#include <random>
#include <stdexcept>

namespace poro {
namespace {

using test::contains;
using test::ScratchDirectory;

constexpr double kRadius = 0.01;

std::vector<PorousMaterial> materials(const std::vector<std::string>& names) {
  std::vector<PorousMaterial> result;
  for (const std::string& name : names) {
    PorousMaterial m;
    m.name = name;
    m.porosity = 0.4;
    m.solidDensity = 2650.0;
    m.bulkDensity = 0.6 * 2650.0;
    result.push_back(m);
  }
  return result;
}

/// Fills every field of `set` with random values; ids continue from `nextId`.
void fillRandomly(ParticleSet& set, std::size_t n, std::int64_t& nextId, std::mt19937_64& random) {
  std::uniform_real_distribution<double> real(-10.0, 10.0);
  set.resize(n);
  for (const auto& f : set.fields())
    for (std::size_t i = 0; i < n; ++i) switch (f.type) {
      case FieldType::Real:
        set.real(f.name)[i] = real(random);
        break;
      case FieldType::Vec3:
        set.vec3(f.name)[i] = Vec3(real(random), real(random), real(random));
        break;
      case FieldType::Mat3:
        for (int k = 0; k < 9; ++k) set.mat3(f.name)[i](k / 3, k % 3) = real(random);
        break;
      case FieldType::Int:
        set.integer(f.name)[i] = static_cast<std::int64_t>(random() % 1000);
        break;
      }
  for (std::size_t i = 0; i < n; ++i) set.integer(field::id)[i] = nextId++;
}

/// A porous set of material `id` with restart fields of every type, an output field and a scratch field.
void addPorousSet(ParticleSystem& ps, const std::string& name, std::int64_t materialId, std::size_t n,
                  std::int64_t& nextId, std::mt19937_64& random) {
  ParticleSet& set = ps.add(name, SetKind::Porous);
  set.addInt(field::materialId, Restart);
  set.addInt(field::fixed, Restart);
  set.addVec3(field::restPosition, Restart);
  set.addMat3("R", Restart);
  set.addReal(field::pi, Restart);
  set.addReal(field::saturation, Output);
  set.addReal("scratch", Scratch);
  fillRandomly(set, n, nextId, random);
  for (auto& m : set.integer(field::materialId)) m = materialId;
}

/// fluid, porous sets of materials a (3 particles) and b (5), boundary (4).
ParticleSystem makeSystem(std::mt19937_64& random) {
  std::int64_t nextId = 0;
  ParticleSystem ps(kRadius);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.addReal(field::pi, Restart);
  fillRandomly(fluid, 6, nextId, random);
  addPorousSet(ps, "a", 0, 3, nextId, random);
  addPorousSet(ps, "b", 1, 5, nextId, random);
  fillRandomly(ps.add("boundary", SetKind::Boundary), 4, nextId, random);
  return ps;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Every Output/Restart field of `expected` is in `actual` with the same type and the same bits.
void expectSameSet(const ParticleSet& expected, const ParticleSet& actual) {
  SCOPED_TRACE("set " + expected.name());
  EXPECT_EQ(actual.name(), expected.name());
  EXPECT_EQ(actual.kind(), expected.kind());
  ASSERT_EQ(actual.size(), expected.size());
  for (const auto& f : expected.fields()) {
    if (f.role == Scratch) continue;
    SCOPED_TRACE("field " + f.name);
    ASSERT_TRUE(actual.has(f.name));
    ASSERT_EQ(actual.info(f.name)->type, f.type);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) switch (f.type) {
      case FieldType::Real:
        mismatches += !sameBits(expected.real(f.name)[i], actual.real(f.name)[i]);
        break;
      case FieldType::Vec3:
        for (int c = 0; c < 3; ++c) mismatches += !sameBits(expected.vec3(f.name)[i][c], actual.vec3(f.name)[i][c]);
        break;
      case FieldType::Mat3:
        for (int k = 0; k < 9; ++k)
          mismatches += !sameBits(expected.mat3(f.name)[i](k / 3, k % 3), actual.mat3(f.name)[i](k / 3, k % 3));
        break;
      case FieldType::Int:
        mismatches += expected.integer(f.name)[i] != actual.integer(f.name)[i];
        break;
      }
    EXPECT_EQ(mismatches, 0u);
  }
}

std::vector<std::string> partsOf(const std::filesystem::path& pvd) {
  std::vector<std::string> parts;
  const PvdSeries series = PvdSeries::read(pvd);
  for (const auto& e : series.entries()) parts.push_back(e.part);
  return parts;
}

class PorousRoundTrip : public ::testing::TestWithParam<bool /* binary */> {};

TEST_P(PorousRoundTrip, WriteAllThenReadGivesTheSameSetsBitForBit) {
  ScratchDirectory dir;
  std::mt19937_64 random(7);
  const ParticleSystem written = makeSystem(random);
  TimeWriter::writeAll(dir.path(), written, RunState{}, GetParam());

  EXPECT_TRUE(std::filesystem::exists(dir / "0/porous.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir / "0/a.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir / "0/b.vtp"));
  EXPECT_EQ(partsOf(dir / "case.pvd"), (std::vector<std::string>{"fluid", "porous", "boundary"}));

  const ParticleSystem read = readParticles(dir.path(), "0", kRadius, materials({"a", "b"}));
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t s = 0; s < written.size(); ++s) expectSameSet(written[s], read[s]);
  EXPECT_EQ(read.find("a")->info(field::materialId)->role, Restart);
}

TEST_P(PorousRoundTrip, OnePorousSetIsWrittenFromItsOwnStorageAndReadsBackBitForBit) {
  ScratchDirectory dir;
  std::mt19937_64 random(17);
  std::int64_t nextId = 0;
  ParticleSystem written(kRadius);
  fillRandomly(written.add("fluid", SetKind::Fluid), 4, nextId, random);
  addPorousSet(written, "b", 1, 6, nextId, random); // material 1 of two, as a case with one material in use
  TimeWriter::writeAll(dir.path(), written, RunState{}, GetParam());

  const ParticleSystem read = readParticles(dir.path(), "0", kRadius, materials({"a", "b"}));
  ASSERT_EQ(read.size(), written.size());
  for (std::size_t s = 0; s < written.size(); ++s) expectSameSet(written[s], read[s]);
}

INSTANTIATE_TEST_SUITE_P(Formats, PorousRoundTrip, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "binary" : "ascii"; });

TEST(PorousSets, PorousFileListsTheSetsInSystemOrderWithoutScratchFields) {
  std::mt19937_64 random(1);
  const ParticleSystem ps = makeSystem(random);
  const ParticleFile file = porousFile(ps);
  EXPECT_EQ(file.name, "porous");
  EXPECT_EQ(file.kind, SetKind::Porous);
  EXPECT_EQ(file.parts, (std::vector<const ParticleSet*>{&ps[1], &ps[2]}));
  const auto role = [&](const std::string& name) {
    for (const auto& f : file.fields)
      if (f.name == name) return std::optional<FieldRole>(f.role);
    return std::optional<FieldRole>();
  };
  EXPECT_FALSE(role("scratch"));
  EXPECT_EQ(role(field::saturation), Output);
  EXPECT_EQ(role("R"), Restart);
}

TEST(PorousSets, SplitFollowsMaterialOrderAndKeepsFileOrderWithinAMaterial) {
  // Particles of b and a interleaved in the file; a third material without particles gets no set.
  ParticleSet merged("porous", SetKind::Porous);
  merged.addInt(field::materialId, Output);
  merged.resize(5);
  const std::int64_t material[] = {1, 0, 1, 0, 1};
  for (std::size_t i = 0; i < 5; ++i) {
    merged.integer(field::id)[i] = static_cast<std::int64_t>(10 + i);
    merged.integer(field::materialId)[i] = material[i];
    merged.x()[i] = Vec3(double(i), 0.0, 0.0);
  }
  ParticleSystem ps(kRadius);
  splitPorousSet(std::move(merged), materials({"a", "b", "c"}), ps, "0/porous.vtp");
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[0].name(), "a");
  EXPECT_EQ(ps[1].name(), "b");
  EXPECT_EQ(ps[0].kind(), SetKind::Porous);
  EXPECT_EQ(ps[0].integer(field::id), (std::vector<std::int64_t>{11, 13}));
  EXPECT_EQ(ps[1].integer(field::id), (std::vector<std::int64_t>{10, 12, 14}));
  EXPECT_EQ(ps[1].x()[2], Vec3(4.0, 0.0, 0.0));
  EXPECT_EQ(ps[1].info(field::materialId)->role, Restart);
}

TEST(PorousSets, TimeWriterWritesOnePorousFileAndPart) {
  ScratchDirectory dir;
  std::mt19937_64 random(3);
  const ParticleSystem ps = makeSystem(random);
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  TimeWriter writer(dir.path(), OutputSettings{}, "0");
  writer.write(ps, RunState{0.5, 10, 1e-3});
  EXPECT_TRUE(std::filesystem::exists(dir / "0.5/porous.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir / "0.5/a.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir / "0.5/boundary.vtp"));
  EXPECT_EQ(partsOf(dir / "case.pvd"), (std::vector<std::string>{"fluid", "porous", "boundary", "fluid", "porous"}));
  const ParticleSystem read = readParticles(dir.path(), "0.5", kRadius, materials({"a", "b"}));
  ASSERT_EQ(read.size(), 4u);
  for (std::size_t s = 0; s < ps.size(); ++s) expectSameSet(ps[s], read[s]);
}

TEST(PorousSets, SurfacesInATimeDirectoryAreNotParticles) {
  // fluidSurface adds them; a restart and the analysis read the same particles as without them.
  ScratchDirectory dir;
  std::mt19937_64 random(5);
  const ParticleSystem ps = makeSystem(random);
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  for (const char* surface : {kFluidSurfaceFile, kPorousSurfaceFile})
    std::filesystem::copy_file(dir / "0/fluid.vtp", dir / "0" / surface);
  const ParticleSystem read = readParticles(dir.path(), "0", kRadius, materials({"a", "b"}));
  ASSERT_EQ(read.size(), ps.size());
  for (std::size_t s = 0; s < ps.size(); ++s) expectSameSet(ps[s], read[s]);
}

/// The message of the InputError `f` throws; a test failure if it throws nothing.
template <class F> std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(PorousSets, MaterialIdOutOfRangeNamesFileAndParticle) {
  ScratchDirectory dir;
  std::mt19937_64 random(5);
  ParticleSystem ps = makeSystem(random);
  ps[2].integer(field::materialId)[3] = 2; // only a and b exist
  const auto badId = ps[2].integer(field::id)[3];
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  const std::string message = errorOf([&] { readParticles(dir.path(), "0", kRadius, materials({"a", "b"})); });
  EXPECT_TRUE(contains(message, (dir / "0/porous.vtp").string() + ":"));
  EXPECT_TRUE(contains(message, "particle id " + std::to_string(badId) + " has materialId 2"));
  EXPECT_TRUE(contains(message, "a, b"));

  ps[2].integer(field::materialId)[3] = -1;
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  EXPECT_TRUE(contains(errorOf([&] {
                         readParticles(dir.path(), "0", kRadius, materials({"a", "b"}));
                       }),
                       "has materialId -1"));
}

TEST(PorousSets, PorousFileWithoutMaterialsOrMaterialIdIsAnInputError) {
  ScratchDirectory dir;
  std::mt19937_64 random(9);
  const ParticleSystem ps = makeSystem(random);
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  const std::string noMaterials = errorOf([&] { readParticles(dir.path(), "0", kRadius, {}); });
  EXPECT_TRUE(contains(noMaterials, (dir / "0/porous.vtp").string() + ":"));
  EXPECT_TRUE(contains(noMaterials, "constant/porosityProperties"));

  ParticleSet withoutId("porous", SetKind::Porous);
  withoutId.resize(2);
  writeParticleSet(withoutId, dir / "0/porous.vtp", true);
  const std::string noId = errorOf([&] { readParticles(dir.path(), "0", kRadius, materials({"a", "b"})); });
  EXPECT_TRUE(contains(noId, (dir / "0/porous.vtp").string() + ":"));
  EXPECT_TRUE(contains(noId, "materialId"));
}

TEST(PorousSets, OtherParticleFilesAreAnInputError) {
  ScratchDirectory dir;
  std::mt19937_64 random(11);
  const ParticleSystem ps = makeSystem(random);
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  writeParticleSet(ps[1], dir / "0/a.vtp", true); // a porous set in a layout of its own
  const std::string message = errorOf([&] { readParticles(dir.path(), "0", kRadius, materials({"a", "b"})); });
  EXPECT_TRUE(contains(message, (dir / "0/a.vtp").string() + ":"));
  EXPECT_TRUE(contains(message, "porous.vtp"));
}

// Materials differ in their fields (an elastic one has rotations, one with wall contact its contact pressure): the
// file holds every field any set has, a set without one written as zeros there, and each set reads its own back.
TEST(PorousSets, SetsWithDifferentFieldsShareTheFileTheMissingOnesWrittenAsZeros) {
  std::mt19937_64 random(13);
  ParticleSystem ps = makeSystem(random);
  auto& extra = ps[2].addReal("contactPressure", Restart); // set b only
  for (std::size_t i = 0; i < extra.size(); ++i) extra[i] = 1.0 + static_cast<double>(i);
  ps[1].drop("R"); // set a only lacks it
  const ParticleFile file = porousFile(ps);
  const auto holds = [&](const char* name) {
    return std::any_of(file.fields.begin(), file.fields.end(), [&](const auto& f) { return f.name == name; });
  };
  EXPECT_TRUE(holds("contactPressure"));
  EXPECT_TRUE(holds("R"));

  ScratchDirectory dir;
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  const ParticleSystem read = readParticles(dir.path(), "0", kRadius, materials({"a", "b"}));
  expectSameSet(ps[1], read[1]);
  expectSameSet(ps[2], read[2]);
  EXPECT_EQ(read[1].real("contactPressure"), std::vector<Real>(3, 0.0));
  for (const Mat3& r : read[1].mat3("R")) EXPECT_TRUE(r.isZero());

  ps[1].addInt("contactPressure", Output); // one name, another type: no file can hold both
  EXPECT_THROW(porousFile(ps), std::logic_error);
}

} // namespace
} // namespace poro
