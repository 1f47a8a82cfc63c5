// system/surfaceDict: defaults without it, every key read, and errors that name file, line and key.

#include "surface/SurfaceSettings.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace poro {
namespace {

namespace fs = std::filesystem;

class SurfaceSettingsTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("porosph-surfaceDict-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                        "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "system");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& text) { std::ofstream(dir_ / "system" / "surfaceDict") << text; }
  std::string errorOf() {
    try {
      readSurfaceSettings(dir_);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  fs::path dir_;
};

TEST_F(SurfaceSettingsTest, DefaultsWithoutTheFile) {
  const SurfaceSettings s = readSurfaceSettings(dir_);
  EXPECT_TRUE(s.writeFluid);
  EXPECT_TRUE(s.writePorous);
  EXPECT_EQ(s.fluid.kernelRadius, 4.0);
  EXPECT_EQ(s.fluid.isoValue, 0.5);
  EXPECT_EQ(s.fluid.gridSpacing, 1.0);
  EXPECT_EQ(s.poreFluid, PoreFluid::Exclude);
}

TEST_F(SurfaceSettingsTest, ReadsEveryKey) {
  write("fluid:\n  write: false\n  kernelRadius: 5\n  isoValue: 0.4\n  gridSpacing: 0.5\n  smoothingIterations: 10\n"
        "  poreFluid: include\nporous:\n  write: true\n  kernelRadius: 3\n  isoValue: 0.6\n  gridSpacing: 2\n");
  const SurfaceSettings s = readSurfaceSettings(dir_);
  EXPECT_FALSE(s.writeFluid);
  EXPECT_EQ(s.fluid.kernelRadius, 5.0);
  EXPECT_EQ(s.fluid.isoValue, 0.4);
  EXPECT_EQ(s.fluid.gridSpacing, 0.5);
  EXPECT_EQ(s.fluid.smoothingIterations, 10);
  EXPECT_EQ(s.poreFluid, PoreFluid::Include);
  EXPECT_EQ(s.porous.kernelRadius, 3.0);
  EXPECT_EQ(s.porous.isoValue, 0.6);
  EXPECT_EQ(s.porous.gridSpacing, 2.0);
  EXPECT_EQ(s.porous.where, (dir_ / "system" / "surfaceDict").string() + ":12");
}

TEST_F(SurfaceSettingsTest, ErrorsNameFileLineAndKey) {
  const std::string file = (dir_ / "system" / "surfaceDict").string();
  write("fluid:\n  isoValue: 1.5\n");
  EXPECT_EQ(errorOf(), file + ":2: key 'fluid.isoValue': expected a number in (0, 1), got '1.5'");
  write("porous:\n  kernelRaduis: 4\n");
  EXPECT_EQ(errorOf(), file + ":2: unknown key 'porous.kernelRaduis'; did you mean 'kernelRadius'?");
  write("fluid:\n  poreFluid: keep\n");
  EXPECT_EQ(errorOf().rfind(file + ":2: key 'fluid.poreFluid': expected one of exclude, include, got 'keep'", 0), 0u);
  write("fluids:\n  isoValue: 0.5\n");
  EXPECT_EQ(errorOf(), file + ":1: unknown key 'fluids'; did you mean 'fluid'?");
  write("porous:\n  kernelRadius: 3\n  gridSpacing: 4\n");
  EXPECT_EQ(errorOf(), file + ":3: key 'porous.gridSpacing': expected gridSpacing (4) at most kernelRadius (3): a grid "
                              "coarser than the kernel's support cannot resolve the colour field");
  write("fluid:\n  gridSpacing: 4\n"); // kernelRadius 4 by default: as coarse as allowed
  EXPECT_EQ(errorOf(), "no error");
}

TEST_F(SurfaceSettingsTest, TheTemplateReadsWithEveryKey) {
  fs::copy_file(fs::path(POROSPH_TEST_DATA) / ".." / ".." / "etc" / "caseDicts" / "surfaceDict",
                dir_ / "system" / "surfaceDict");
  EXPECT_NO_THROW(readSurfaceSettings(dir_));
}

} // namespace
} // namespace poro
