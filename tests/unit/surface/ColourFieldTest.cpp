// The colour field c = sum V W on a grid: 1 inside a lattice, 1/2 on its faces, 0 on the grid's border, and the
// same for any thread count.

#include "surface/ColourField.hpp"

#include "LatticeClouds.hpp"
#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

constexpr double kR = 0.01;

TEST(ColourField, IsOneInsideALatticeAndHalfOnItsFaces) {
  // A 16^3 lattice fills [0, 0.32]^3; grid points every r.
  const ScalarGrid grid = colourField(test::latticeCloud(kR, 16, 16, 16), 4.0 * kR, kR, "test");
  const auto at = [&](const Vec3& x) { return grid.sample(x); };
  // Deep inside: the lattice sum of the cubic kernel with H = 2 spacings is 1 within its ripple (sph LatticeSum).
  EXPECT_NEAR(at(Vec3(0.16, 0.16, 0.16)), 1.0, 0.01);
  EXPECT_NEAR(at(Vec3(0.15, 0.16, 0.17)), 1.0, 0.01);
  // Midway between the last layer and the first empty one the half lattice gives half the full sum.
  EXPECT_NEAR(at(Vec3(0.32, 0.16, 0.16)), 0.5, 0.01);
  EXPECT_NEAR(at(Vec3(0.16, 0.0, 0.16)), 0.5, 0.01);
  // One support radius outside nothing is left.
  EXPECT_EQ(at(Vec3(0.16, 0.16, 0.32 + 4.0 * kR + 1e-9)), 0.0);
}

TEST(ColourField, IsZeroOnTheGridsBorderSoContoursClose) {
  const ScalarGrid grid = colourField(test::latticeCloud(kR, 5, 7, 3), 4.0 * kR, 0.7 * kR, "test");
  for (std::int64_t k = 0; k < grid.dims[2]; ++k)
    for (std::int64_t j = 0; j < grid.dims[1]; ++j)
      for (std::int64_t i = 0; i < grid.dims[0]; ++i) {
        const bool border = i == 0 || j == 0 || k == 0 || i == grid.dims[0] - 1 || j == grid.dims[1] - 1 ||
                            k == grid.dims[2] - 1;
        if (border) {
          ASSERT_EQ(grid.values[grid.index(i, j, k)], 0.0f) << i << " " << j << " " << k;
        }
      }
}

TEST(ColourField, DoesNotDependOnTheThreadCount) {
  const ParticleCloud cloud = test::latticeCloud(kR, 20, 9, 30, Vec3(1, 2, 3));
  const int threads = parallel::threads();
  parallel::setThreads(1);
  const ScalarGrid one = colourField(cloud, 4.0 * kR, kR, "test");
  parallel::setThreads(3);
  const ScalarGrid three = colourField(cloud, 4.0 * kR, kR, "test");
  parallel::setThreads(threads);
  EXPECT_EQ(one.values, three.values);
}

TEST(ColourField, NoParticlesGiveAnEmptyGridAndTooFineAGridIsAnInputError) {
  EXPECT_EQ(colourField(ParticleCloud{}, 0.04, 0.01, "test").points(), 0u);
  ParticleCloud far = test::latticeCloud(kR, 1, 1, 1);
  far.positions.push_back(Vec3(100.0, 100.0, 100.0));
  far.volumes.push_back(8e-6);
  far.fields.front().values.insert(far.fields.front().values.end(), 3, 0.0);
  try {
    colourField(far, 4.0 * kR, kR, "system/surfaceDict:3");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("system/surfaceDict:3: key 'gridSpacing': expected a spacing that gives at most", 0), 0u)
        << e.what();
  }
}

} // namespace
} // namespace poro
