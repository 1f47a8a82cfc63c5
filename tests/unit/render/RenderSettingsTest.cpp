// system/renderDict: defaults that suit a tutorial without it, every key read, errors naming file, line and key.

#include "render/RenderSettings.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace poro {
namespace {

namespace fs = std::filesystem;

class RenderSettingsTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("porosph-renderDict-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "system");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& text) { std::ofstream(dir_ / "system" / "renderDict") << text; }
  std::string errorOf() {
    try {
      readRenderSettings(dir_, true);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  std::string file() const { return (dir_ / "system" / "renderDict").string(); }
  fs::path dir_;
};

TEST_F(RenderSettingsTest, DefaultsShowWaterAndWetness) {
  const RenderSettings s = readRenderSettings(dir_, true);
  EXPECT_EQ(s.width, 1280);
  EXPECT_EQ(s.height, 720);
  EXPECT_EQ(s.fluid.show, SetStyle::Show::Surface);
  EXPECT_TRUE(s.fluid.colourBy.empty());
  EXPECT_LT(s.fluid.opacity, 0.5); // translucent: the bodies show through
  EXPECT_EQ(s.porous.colourBy, "saturation");
  EXPECT_EQ(s.porous.colourMap, "wetness");
  ASSERT_TRUE(s.porous.range);
  EXPECT_EQ((*s.porous.range)[1], 1.0);
  EXPECT_FALSE(s.clip);
  EXPECT_GT(readRenderSettings(dir_, false).fluid.opacity, 0.5); // nothing to see through it
}

TEST_F(RenderSettingsTest, ReadsEveryKey) {
  write("imageSize: [640, 360]\nbackground: [0, 0, 0]\nframeRate: 25\ntimeLabel: false\nlegend: false\n"
        "camera:\n  position: [1, 2, 3]\n  focalPoint: [0, 0, 0]\n  viewUp: [0, 0, 1]\n  viewAngle: 40\n"
        "fluid:\n  show: particles\n  colourBy: density\n  colourMap: coolToWarm\n  range: [990, 1010]\n"
        "  opacity: 0.5\nporous:\n  show: surface\n  colourBy: none\n  colour: [1, 0, 0]\n"
        "boundary:\n  show: none\nclip:\n  origin: [0.1, 0.2, 0.3]\n  normal: [0, 0, 2]\n  sets: [porous, fluid]\n");
  const RenderSettings s = readRenderSettings(dir_, true);
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.frameRate, 25.0);
  EXPECT_FALSE(s.timeLabel);
  EXPECT_EQ(*s.camera.viewUp, Vec3::UnitZ());
  EXPECT_EQ(s.camera.viewAngle, 40.0);
  EXPECT_EQ(s.fluid.show, SetStyle::Show::Particles);
  EXPECT_EQ(s.fluid.colourBy, "density");
  EXPECT_EQ((*s.fluid.range)[0], 990.0);
  EXPECT_TRUE(s.porous.colourBy.empty());
  EXPECT_EQ(s.porous.colour, Vec3(1, 0, 0));
  EXPECT_EQ(s.boundary.show, SetStyle::Show::None);
  ASSERT_TRUE(s.clip);
  EXPECT_EQ(s.clip->normal, Vec3::UnitZ());
  EXPECT_EQ(s.clip->sets, (std::vector<std::string>{"porous", "fluid"}));
}

TEST_F(RenderSettingsTest, ErrorsNameFileLineAndKey) {
  write("porous:\n  colourBy: pressure\n");
  EXPECT_EQ(errorOf().rfind(file() + ":2: key 'porous.colourBy': expected one of none, saturation, got 'pressure'", 0),
            0u);
  write("fluid:\n  colourMap: jet\n");
  EXPECT_EQ(errorOf().rfind(file() + ":2: key 'fluid.colourMap': expected one of wetness, blues, viridis", 0), 0u);
  write("imageSize: [640.5, 360]\n");
  EXPECT_EQ(errorOf(), file() + ":1: key 'imageSize': expected whole numbers of pixels");
  write("camera:\n  postion: [1, 2, 3]\n");
  EXPECT_EQ(errorOf(), file() + ":2: unknown key 'camera.postion'; did you mean 'position'?");
  write("clip:\n  origin: [0, 0, 0]\n  normal: [0, 0, 0]\n");
  EXPECT_EQ(errorOf(), file() + ":3: key 'clip.normal': expected a non-zero direction");
  write("fluid:\n  range: [1, 0]\n");
  EXPECT_EQ(errorOf(), file() + ":2: key 'fluid.range': expected [min, max] with min < max");
}

TEST_F(RenderSettingsTest, ColoursOutsideTheUnitRangeAreRefused) {
  write("background: [0, 0, 255]\n");
  EXPECT_EQ(errorOf(), file() + ":1: key 'background': expected red, green and blue in [0, 1]");
  write("background: [-0.1, 0, 0]\n");
  EXPECT_EQ(errorOf(), file() + ":1: key 'background': expected red, green and blue in [0, 1]");
  write("porous:\n  colour: [0, 1.5, 0]\n");
  EXPECT_EQ(errorOf(), file() + ":2: key 'porous.colour': expected red, green and blue in [0, 1]");
}

TEST_F(RenderSettingsTest, AViewUpAlongTheViewDirectionIsRefused) {
  write("camera:\n  position: [0, 5, 0]\n  focalPoint: [0, 1, 0]\n  viewUp: [0, 2, 0]\n");
  EXPECT_EQ(errorOf().rfind(file() + ":4: key 'camera.viewUp': expected a direction not parallel to the view "
                                     "direction focalPoint - position = [ 0 -4  0], got [0 2 0]",
                            0),
            0u)
      << errorOf();
  write("camera:\n  position: [0, 5, 0]\n  focalPoint: [0, 1, 0]\n  viewUp: [0, 0, 1]\n");
  EXPECT_EQ(errorOf(), "no error");
  // Without position or focal point the view direction is renderCase's default one, checked there.
  write("camera:\n  viewUp: [0, 1, 0]\n");
  const RenderSettings s = readRenderSettings(dir_, true);
  EXPECT_EQ(s.camera.viewUpWhere, file() + ":2");
  EXPECT_TRUE(viewUpProblem(Vec3(0, 1, 0), Vec3(0, 0, -1)).empty());
  EXPECT_FALSE(viewUpProblem(Vec3(0, 1, 0), Vec3(0, -3, 0)).empty());
  EXPECT_FALSE(viewUpProblem(Vec3(0, 1, 0), Vec3(1e-5, 1, 0)).empty());
}

TEST_F(RenderSettingsTest, AColourMapOrRangeWithoutColourByIsRefused) {
  write("porous:\n  colourBy: none\n  range: [0, 0.5]\n");
  EXPECT_EQ(errorOf().rfind(file() + ":3: key 'porous.range': given, but colourBy is none, so the set is drawn in its "
                                     "solid colour",
                            0),
            0u)
      << errorOf();
  write("fluid:\n  colourMap: blues\n"); // the fluid's default colourBy is none
  EXPECT_EQ(errorOf().rfind(file() + ":2: key 'fluid.colourMap': given, but colourBy is none (the default here)", 0),
            0u)
      << errorOf();
  write("fluid:\n  colourBy: v\n  colourMap: blues\n  range: [0, 2]\n");
  EXPECT_EQ(errorOf(), "no error");
}

TEST_F(RenderSettingsTest, TheTemplateReadsWithEveryKey) {
  fs::copy_file(fs::path(POROSPH_TEST_DATA) / ".." / ".." / "etc" / "caseDicts" / "renderDict",
                dir_ / "system" / "renderDict");
  EXPECT_NO_THROW(readRenderSettings(dir_, true));
}

} // namespace
} // namespace poro
