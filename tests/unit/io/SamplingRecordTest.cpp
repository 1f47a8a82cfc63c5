// uniform/sampling: what the particles of a time directory were sampled from, carried into every later time
// directory, and the checks that refuse a run when system/particleDict's regions or the materials' order changed.
// The refusals of whole cases are in the bad-input corpus (tests/data/bad/*AfterSampling, *_materialsReordered).

#include "io/SamplingRecord.hpp"

#include "ScratchDirectory.hpp"
#include "core/Error.hpp"
#include "io/TimeDirectory.hpp"
#include "physics/FieldNames.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

using test::contains;
using test::ScratchDirectory;

const std::string kParticleDict = "particleRadius: 0.01\n"
                                  "regions:\n"
                                  "  - {name: water, phase: fluid, shape: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}\n"
                                  "  - name: piston\n"
                                  "    phase: boundary\n"
                                  "    shape: box\n"
                                  "    min: [0, 0.3, 0]\n"
                                  "    max: [0.2, 0.34, 0.2]\n"
                                  "    motion: {velocity: [0, -0.1, 0]}\n";

std::vector<PorousMaterial> materials(const std::vector<std::string>& names) {
  std::vector<PorousMaterial> result(names.size());
  for (std::size_t m = 0; m < names.size(); ++m) result[m].name = names[m];
  return result;
}

/// A case whose 0/ was sampled from kParticleDict, with one porous set of material "b" of {a, b}.
class SamplingRecord : public ::testing::Test {
protected:
  SamplingRecord() {
    std::filesystem::create_directories(dir_ / "system");
    std::filesystem::create_directories(dir_ / "constant");
    test::writeAll(dir_ / "system/particleDict", kParticleDict);
    test::writeAll(dir_ / "constant/porosityProperties", "a: {}\nb: {}\n");
    particles_.add("fluid", SetKind::Fluid);
    ParticleSet& porous = particles_.add("b", SetKind::Porous);
    porous.addInt(field::materialId, Restart);
    record_ = samplingRecord(Dictionary::read((dir_ / "system/particleDict").string()), dir_ / "constant/triSurface",
                             particles_, materials({"a", "b"}));
    TimeWriter::writeAll(dir_.path(), particles_, RunState{}, false, record_);
  }

  void edit(const std::string& from, const std::string& to) {
    std::string text = test::readAll(dir_ / "system/particleDict");
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    test::writeAll(dir_ / "system/particleDict", text.replace(at, from.size(), to));
  }

  /// The message of the InputError checkSampledRegions throws for 0/, or "no error".
  std::string regionError() const {
    try {
      checkSampledRegions(dir_.path(), dir_ / "0");
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  ScratchDirectory dir_;
  ParticleSystem particles_{0.01};
  std::string record_;
};

TEST_F(SamplingRecord, HoldsTheRegionsWithoutMotionAndTheSampledMaterials) {
  EXPECT_TRUE(contains(record_, "  - {name: water, phase: fluid, shape: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}\n"));
  EXPECT_TRUE(contains(record_, "  - {name: piston, phase: boundary, shape: box, min: [0, 0.3, 0], max: [0.2, 0.34, "
                                "0.2]}\n"));
  EXPECT_FALSE(contains(record_, "velocity"));
  EXPECT_TRUE(contains(record_, "  - {materialId: 1, name: \"b\"}\n"));
  EXPECT_EQ(test::readAll(dir_ / "0/uniform/sampling"), record_);
  EXPECT_EQ(regionError(), "no error");
}

TEST_F(SamplingRecord, MotionCommentsAndLayoutMayChange) {
  // A wall's motion is read at run time (tests/data/bad/particleDict_motionAddedAfterSampling refuses only a moving
  // wall that was not sampled).
  edit("motion: {velocity: [0, -0.1, 0]}", "motion: {velocity: [0, -0.5, 0]}  # faster");
  edit("max: [0.2, 0.2, 0.2]}", "max: [0.20, 2e-1, 0.2]}  # same box");
  edit("    min: [0, 0.3, 0]\n", "    min:\n      - 0\n      - 0.3\n      - 0\n");
  EXPECT_EQ(regionError(), "no error");
}

TEST_F(SamplingRecord, RefusesChangedAddedRemovedAndReorderedRegions) {
  edit("max: [0.2, 0.2, 0.2]", "max: [0.2, 0.3, 0.2]");
  std::string e = regionError();
  EXPECT_TRUE(contains(e, "particleDict:3: key 'regions[0].max': [0.2, 0.3, 0.2] differs from [0.2, 0.2, 0.2], the "
                          "value the particles of " +
                              (dir_ / "0").string() + " were sampled with (" + (dir_ / "0/uniform/sampling").string() +
                              ":5); set it back, or run sampleParticles again"));
  edit("max: [0.2, 0.3, 0.2]", "max: [0.2, 0.2, 0.2], velocity: [1, 0, 0]");
  EXPECT_TRUE(contains(regionError(), "key 'regions[0].velocity': added after the particles of"));
  edit(", velocity: [1, 0, 0]", "");
  test::writeAll(dir_ / "system/particleDict", kParticleDict + "  - {name: drop, phase: fluid, shape: sphere, "
                                                               "centre: [0.1, 0.5, 0.1], radius: 0.05}\n");
  EXPECT_TRUE(contains(regionError(), "particleDict:10: key 'regions[2].name': region 'drop' was added after the "
                                      "particles of"));
  test::writeAll(dir_ / "system/particleDict", kParticleDict.substr(0, kParticleDict.find("  - name: piston")));
  EXPECT_TRUE(contains(regionError(), "key 'regions': region 'piston' was removed after the particles of"));
  test::writeAll(dir_ / "system/particleDict",
                 "particleRadius: 0.01\nregions:\n" + kParticleDict.substr(kParticleDict.find("  - name: piston")) +
                     "  - {name: water, phase: fluid, shape: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}\n");
  EXPECT_TRUE(contains(regionError(), "the regions are listed as piston, water, but the particles of"));
}

TEST_F(SamplingRecord, LaterTimeDirectoriesCarryIt) {
  TimeWriter writer(dir_.path(), OutputSettings{}, "0");
  writer.write(particles_, RunState{0.5, 10, 1e-3});
  EXPECT_EQ(test::readAll(dir_ / "0.5/uniform/sampling"), record_);
  edit("max: [0.2, 0.2, 0.2]", "max: [0.2, 0.3, 0.2]");
  EXPECT_THROW(checkSampledRegions(dir_.path(), dir_ / "0.5"), InputError);
}

TEST_F(SamplingRecord, OldTimeDirectoriesWithoutItAreNotChecked) {
  std::filesystem::remove(dir_ / "0/uniform/sampling");
  edit("max: [0.2, 0.2, 0.2]", "max: [0.2, 0.3, 0.2]");
  EXPECT_EQ(regionError(), "no error");
  EXPECT_NO_THROW(checkSampledMaterials(dir_.path(), dir_ / "0", materials({"b", "a"})));
  TimeWriter writer(dir_.path(), OutputSettings{}, "0");
  writer.write(particles_, RunState{0.5, 10, 1e-3});
  EXPECT_FALSE(std::filesystem::exists(dir_ / "0.5/uniform/sampling"));
}

TEST_F(SamplingRecord, RefusesAMaterialIdThatNamesAnotherMaterial) {
  EXPECT_NO_THROW(checkSampledMaterials(dir_.path(), dir_ / "0", materials({"a", "b", "c"}))); // appended: fine
  test::writeAll(dir_ / "constant/porosityProperties", "b: {}\na: {}\n");
  try {
    checkSampledMaterials(dir_.path(), dir_ / "0", materials({"b", "a"}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "porosityProperties:1: key 'b': the porous particles of " + (dir_ / "0").string() +
                                       " with materialId 1 were sampled as material 'b'"));
    EXPECT_TRUE(contains(e.what(), "now names 'a'; 'b' is now materialId 0: put the materials back in their order"));
  }
  test::writeAll(dir_ / "constant/porosityProperties", "a: {}\nsand: {}\n");
  EXPECT_THROW(checkSampledMaterials(dir_.path(), dir_ / "0", materials({"a", "sand"})), InputError);
}

TEST(SamplingRecordWithoutPorousRegions, IsReadWithMaterialsDefined) {
  // A fluid case whose constant/porosityProperties defines materials no region uses: the record's empty list must be
  // a list, not a comment, or every reader of the case refuses it.
  ScratchDirectory dir;
  std::filesystem::create_directories(dir / "system");
  test::writeAll(dir / "system/particleDict", kParticleDict);
  ParticleSystem particles(0.01);
  particles.add("fluid", SetKind::Fluid);
  const std::string record = samplingRecord(Dictionary::read((dir / "system/particleDict").string()),
                                            dir / "constant/triSurface", particles, materials({"a"}));
  TimeWriter::writeAll(dir.path(), particles, RunState{}, false, record);
  EXPECT_TRUE(contains(record, "porousMaterials: []  # materialId")) << record;
  EXPECT_NO_THROW(checkSampledMaterials(dir.path(), dir / "0", materials({"a"})));
}

} // namespace
} // namespace poro
