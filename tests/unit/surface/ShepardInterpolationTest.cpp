// Fields read off at points: a uniform field exactly, any field within the particles' values, nothing far away.

#include "surface/ShepardInterpolation.hpp"

#include "LatticeClouds.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace poro {
namespace {

constexpr double kR = 0.01;

TEST(ShepardInterpolation, UniformExactlyAndOtherwiseBounded) {
  ParticleCloud cloud = test::latticeCloud(kR, 6, 6, 6, Vec3(1.0, -2.0, 0.5));
  ParticleField height{"height", 1, {}};
  for (const Vec3& x : cloud.positions) height.values.push_back(x.y());
  const ShepardInterpolation interpolation(cloud, 4.0 * kR);
  const std::vector<Vec3> points{{0.06, 0.06, 0.06}, {0.0, 0.13, 0.02}, {0.125, -0.01, 0.1}, {1.0, 1.0, 1.0}};
  const std::vector<double> v = interpolation.at(points, cloud.fields.front());
  for (std::size_t p = 0; p < 3; ++p) {
    EXPECT_NEAR(v[3 * p], 1.0, 1e-12);
    EXPECT_NEAR(v[3 * p + 1], -2.0, 1e-12);
  }
  EXPECT_EQ(v[9], 0.0); // out of every particle's reach
  const std::vector<double> h = interpolation.at(points, height);
  for (std::size_t p = 0; p < 3; ++p) {
    EXPECT_GE(h[p], kR);
    EXPECT_LE(h[p], 11.0 * kR);
  }
  EXPECT_NEAR(h[0], 0.06, 1e-3); // a linear field at the lattice's centre, by symmetry
}

TEST(ShepardInterpolation, TooManyCellsAreRefusedBeforeAllocating) {
  // Two particles a diverged run flung 1 km apart: (1000 m / 0.04 m)^3 = 1.6e13 cells of the support.
  ParticleCloud cloud;
  cloud.positions = {Vec3(0, 0, 0), Vec3(1000, 1000, 1000)};
  cloud.volumes = {8e-6, 8e-6};
  try {
    const ShepardInterpolation interpolation(cloud, 4.0 * kR, "system/surfaceDict:3");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("system/surfaceDict:3: the particles span", 0), 0u) << message;
    EXPECT_NE(message.find("diverged"), std::string::npos) << message;
  }
}

TEST(ShepardInterpolation, FieldsOfOtherWidthsAreRefusedNotTruncated) {
  ParticleCloud cloud = test::latticeCloud(kR, 2, 2, 2, Vec3(1.0, 0.0, 0.0));
  const ShepardInterpolation interpolation(cloud, 4.0 * kR);
  const std::vector<Vec3> points{{0.02, 0.02, 0.02}};
  ParticleField tensor{"stress", 9, std::vector<double>(9 * cloud.positions.size(), 1.0)};
  EXPECT_THROW(interpolation.at(points, tensor), std::invalid_argument);
  ParticleField short_{"saturation", 1, {1.0}};
  EXPECT_THROW(interpolation.at(points, short_), std::invalid_argument);
}

} // namespace
} // namespace poro
