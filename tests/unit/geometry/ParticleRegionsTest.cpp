// system/particleDict regions of shape sphere and surface (utilities/sampleParticles): their keys, the transform
// of a surface, wall bodies, and the errors of bad input. Boxes and containers are covered by the bad-input
// corpus (tests/data/bad/particleDict_*) and LatticeSamplingTest.
#include "ParticleRegions.hpp"
#include "../io/ScratchDirectory.hpp"
#include "TestSurfaces.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "geometry/Sphere.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace poro {
namespace {

using test::contains;

class ParticleRegions : public ::testing::Test {
protected:
  ParticleRegions() {
    log::setQuiet(true);
    std::filesystem::create_directories(surfaces());
    std::filesystem::create_directories(dir_ / "system");
    test::writeObj(surfaces() / "cube.obj", test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.1)));
  }
  ~ParticleRegions() override { log::setQuiet(false); }

  std::filesystem::path surfaces() const { return dir_ / "constant" / "triSurface"; }
  std::string dictPath() const { return (dir_ / "system" / "particleDict").string(); }

  /// particleDict with a fluid box first (a case needs one) and then `region`, at r = 1 cm.
  ParticleDict read(const std::string& region) const {
    const std::string text = "particleRadius: 0.01\n"
                             "regions:\n"
                             "  - {name: water, phase: fluid, shape: box, min: [0, 0, 0], max: [0.1, 0.1, 0.1]}\n"
                             "  - " +
                             region + "\n";
    return ParticleDict::read(Dictionary::parse(text, dictPath()), {}, surfaces());
  }

  /// The message of the InputError reading `region` throws.
  std::string error(const std::string& region) const {
    try {
      read(region);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  test::ScratchDirectory dir_;
};

TEST_F(ParticleRegions, Sphere) {
  const ParticleDict dict = read("{name: drop, phase: fluid, shape: sphere, centre: [1, 2, 3], radius: 0.15, "
                                 "velocity: [0, -1, 0]}");
  const ParticleRegion& drop = dict.regions[1];
  EXPECT_EQ(drop.shape, ParticleRegion::Shape::Sphere);
  const auto* sphere = dynamic_cast<const Sphere*>(drop.body.get());
  ASSERT_NE(sphere, nullptr);
  EXPECT_EQ(sphere->centre(), Vec3(1, 2, 3));
  EXPECT_EQ(sphere->radius(), 0.15);
  EXPECT_EQ(drop.velocity, Vec3(0, -1, 0));
  const double expected = 4.0 / 3.0 * test::kPi * std::pow(0.15 / 0.02, 3);
  EXPECT_NEAR(static_cast<double>(drop.sample(0.01).size()) / expected, 1.0, 0.03);
}

TEST_F(ParticleRegions, SurfaceWithTransform) {
  // Scale [2, 1, 1], rotate 90 degrees about z, translate: the cube [0, 0.1]^3 lands on [0.4, 0.5] x [0, 0.2] x
  // [0, 0.1], so the particles are those of that box.
  const ParticleDict dict = read("{name: block, phase: fluid, shape: surface, file: cube.obj, scale: [2, 1, 1], "
                                 "rotate: {axis: [0, 0, 1], angle: 90}, translate: [0.5, 0, 0]}");
  const ParticleRegion& block = dict.regions[1];
  EXPECT_EQ(block.shape, ParticleRegion::Shape::Surface);
  EXPECT_LT((block.body->boxMin() - Vec3(0.4, 0.0, 0.0)).norm(), 1e-15);
  EXPECT_LT((block.body->boxMax() - Vec3(0.5, 0.2, 0.1)).norm(), 1e-15);
  EXPECT_NEAR(block.body->volume(), 0.002, 1e-15);
  EXPECT_EQ(block.sample(0.01).size(), 5u * 10u * 5u);

  const ParticleDict uniform = read("{name: big, phase: fluid, shape: surface, file: cube.obj, scale: 3}");
  EXPECT_LT((uniform.regions[1].body->boxMax() - Vec3::Constant(0.3)).norm(), 1e-15);
}

TEST_F(ParticleRegions, WallBodies) {
  const ParticleDict dict =
      read("{name: bowl, phase: boundary, shape: surface, file: cube.obj, layers: 1, side: outside}");
  const ParticleRegion& bowl = dict.regions[1];
  EXPECT_EQ(bowl.layers, 1);
  EXPECT_EQ(bowl.side, WallSide::Outside);
  // The layer r outside each face, and the points (r, r) off an edge (sqrt(2) r < 2r) and (r, r, r) off a corner.
  EXPECT_EQ(bowl.sample(0.01).size(), 6u * 5u * 5u + 12u * 5u + 8u);
  const ParticleDict ball = read("{name: ball, phase: boundary, shape: sphere, centre: [0, 0, 0], radius: 0.1}");
  EXPECT_EQ(ball.regions[1].layers, 2);
  EXPECT_EQ(ball.regions[1].side, WallSide::Inside);
}

TEST_F(ParticleRegions, MissingSurfaceFile) {
  EXPECT_TRUE(contains(error("{name: b, phase: fluid, shape: surface, file: bunny.stl}"),
                       dictPath() + ":4: key 'regions[1].file': no surface file " +
                           (surfaces() / "bunny.stl").string() + "; " + surfaces().string() + " holds: cube.obj"));
}

TEST_F(ParticleRegions, BadTransforms) {
  const std::string cube = "{name: b, phase: fluid, shape: surface, file: cube.obj, ";
  EXPECT_TRUE(contains(error(cube + "rotate: {axis: [0, 0, 0], angle: 90}}"),
                       ":4: key 'regions[1].rotate.axis': expected a non-zero vector to rotate about, got [0, 0, 0]"));
  EXPECT_TRUE(contains(error(cube + "rotate: {axis: [0, 0, 1], angle: 90, centre: [1, 1, 1]}}"),
                       ":4: unknown key 'regions[1].rotate.centre'"));
  EXPECT_TRUE(contains(error(cube + "rotate: {axis: [0, 0, 1]}}"), "missing required key 'regions[1].rotate.angle'"));
  EXPECT_TRUE(contains(error(cube + "scale: -2}"), "key 'regions[1].scale': expected a number > 0, got '-2'"));
  EXPECT_TRUE(
      contains(error(cube + "scale: [1, 0, 1]}"),
               "key 'regions[1].scale': expected scale factors > 0 (mirroring is not supported), got [1, 0, 1]"));
  EXPECT_TRUE(contains(error(cube + "scale: [1, 2]}"), "key 'regions[1].scale': expected a sequence [x, y, z] of 3 "
                                                       "finite numbers, got a sequence of 2 elements, or a single "
                                                       "number > 0"));
  EXPECT_TRUE(contains(error(cube + "translate: 1}"), "key 'regions[1].translate': expected a sequence [x, y, z]"));
}

TEST_F(ParticleRegions, KeysThatDoNotBelong) {
  EXPECT_TRUE(contains(error("{name: d, phase: fluid, shape: sphere, centre: [0, 0, 0], radius: 1, side: outside}"),
                       "unknown key 'regions[1].side'"));
  EXPECT_TRUE(contains(error("{name: d, phase: fluid, shape: sphere, centre: [0, 0, 0], radius: 1, min: [0, 0, 0]}"),
                       "unknown key 'regions[1].min'"));
  EXPECT_TRUE(contains(error("{name: d, phase: fluid, shape: container, min: [0, 0, 0], max: [1, 1, 1]}"),
                       "key 'regions[1].shape': expected one of box, sphere, surface, got 'container'"));
  EXPECT_TRUE(contains(error("{name: d, phase: boundary, shape: sphere, centre: [0, 0, 0], radius: 1, side: in}"),
                       "key 'regions[1].side': expected one of inside, outside, got 'in'"));
}

TEST_F(ParticleRegions, BrokenSurfaceNamesTheSurfaceFile) {
  TriangleMesh open = test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.1));
  open.triangles.pop_back();
  test::writeObj(surfaces() / "open.obj", open);
  EXPECT_TRUE(contains(error("{name: b, phase: fluid, shape: surface, file: open.obj}"),
                       (surfaces() / "open.obj").string() + ": the surface is not closed: 3 open boundary edges"));
}

TEST_F(ParticleRegions, SphereWithoutParticles) {
  const ParticleDict dict = read("{name: speck, phase: fluid, shape: sphere, centre: [0, 0, 0], radius: 0.005}");
  try {
    dict.regions[1].sample(0.01);
    FAIL() << "a sphere smaller than the lattice spacing sampled particles";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), dictPath() + ":4: region 'speck' holds no particle: no point of the lattice of "
                                                "spacing 2 particleRadius = 0.02 m lies inside its surface"));
  }
}

} // namespace
} // namespace poro
