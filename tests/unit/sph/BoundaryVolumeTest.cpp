// Akinci boundary volumes (METHOD.md §6.2) and the flat-wall densities of METHOD.md §2.2.
#include "sph/BoundaryVolume.hpp"

#include "sph/Kernel.hpp"
#include "sph/NeighbourSearch.hpp"
#include "sph/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace poro {
namespace {

constexpr double kR = 0.01;
constexpr double kSpacing = 2.0 * kR;
constexpr double kV = kSpacing * kSpacing * kSpacing;
constexpr int kLateral = 20; // 20 x 20 lattice: the centre particle is 10 spacings (5 H) from the edges

/// Fills `set` with a lateral 20 x 20 lattice of `layers` layers at heights z0 - 2r l (l = 0 .. layers - 1),
/// starting at index offset `first`. Returns the index of the centre particle of the top layer.
std::size_t addWall(ParticleSet& set, int layers, double z0, std::int64_t body, const Vec3& shift = Vec3::Zero()) {
  const std::size_t first = set.size();
  set.resize(first + static_cast<std::size_t>(kLateral * kLateral * layers));
  std::size_t n = first, centre = 0;
  for (int l = 0; l < layers; ++l)
    for (int j = 0; j < kLateral; ++j)
      for (int i = 0; i < kLateral; ++i, ++n) {
        set.x()[n] = shift + Vec3(kSpacing * i, kSpacing * j, z0 - kSpacing * l);
        set.integer(field::objectId)[n] = body;
        set.integer(field::id)[n] = static_cast<std::int64_t>(n);
        if (l == 0 && i == kLateral / 2 && j == kLateral / 2) centre = n;
      }
  return centre;
}

TEST(BoundaryVolume, TopLayerOfATwoLayerWall) {
  // Wall surface at z = 0, layers r and 3r below it (METHOD.md §2.3).
  ParticleSet wall("wall", SetKind::Boundary);
  const std::size_t top = addWall(wall, 2, -kR, 1);
  computeBoundaryVolumes(wall, CubicKernel(4.0 * kR));
  ASSERT_TRUE(wall.has(kBoundaryVolumeField));
  const auto& vk = wall.real(kBoundaryVolumeField);
  EXPECT_NEAR(vk[top] / kV, 1.176, 2e-3);
  // The bottom layer sees the mirror image of the same neighbourhood.
  EXPECT_NEAR(vk[top + kLateral * kLateral] / kV, 1.176, 2e-3);
  // Volumes are positive and never exceed 1/W(0) = pi V (an isolated particle).
  for (double v : vk) {
    EXPECT_GT(v, 0.0);
    EXPECT_LE(v, M_PI * kV * (1.0 + 1e-12));
  }
}

/// rho~ = sum_fluid V W + sum_k V_k W of the centre particle of the first fluid layer (at z = r, i.e. 2r above
/// the top wall layer at z = -r), with `wallLayers` Akinci layers below.
double firstLayerDensity(int wallLayers) {
  const CubicKernel kernel(4.0 * kR);
  ParticleSet wall("wall", SetKind::Boundary);
  addWall(wall, wallLayers, -kR, 1);
  computeBoundaryVolumes(wall, kernel);
  ParticleSet fluid("fluid", SetKind::Fluid);
  const std::size_t centre = addWall(fluid, 4, 7.0 * kR, 0) + 3 * kLateral * kLateral; // layers 7r, 5r, 3r, r
  EXPECT_NEAR(fluid.x()[centre].z(), kR, 1e-15);

  NeighbourSearch search(kernel.supportRadius());
  search.update({&fluid.x(), &wall.x()}, {{true, true}, {false, false}});
  const auto& vk = wall.real(kBoundaryVolumeField);
  double rho = kV * kernel.w0();
  for (Index j : search.list(0, 0).of(centre))
    rho += kV * kernel.w(fluid.x()[centre] - fluid.x()[static_cast<std::size_t>(j)]);
  for (Index k : search.list(0, 1).of(centre))
    rho += vk[static_cast<std::size_t>(k)] * kernel.w(fluid.x()[centre] - wall.x()[static_cast<std::size_t>(k)]);
  return rho;
}

TEST(BoundaryVolume, FirstFluidLayerOnAFlatWall) {
  // METHOD.md §2.2: 1.026 for >= 2 Akinci layers, 1.064 for 1 layer.
  EXPECT_NEAR(firstLayerDensity(2), 1.026, 2e-3);
  EXPECT_NEAR(firstLayerDensity(3), 1.026, 2e-3);
  EXPECT_NEAR(firstLayerDensity(1), 1.064, 2e-3);
}

TEST(BoundaryVolume, BodiesDoNotSeeEachOther) {
  // Two 2-layer plates of different bodies, one spacing apart (well inside H): each must get the volumes it
  // would have alone.
  const CubicKernel kernel(4.0 * kR);
  const Vec3 shift(0.5 * kSpacing, 0.0, 0.0); // not on the same lattice, to make the overlap generic
  ParticleSet alone1("a", SetKind::Boundary), alone2("b", SetKind::Boundary), both("ab", SetKind::Boundary);
  addWall(alone1, 2, -kR, 1);
  addWall(alone2, 2, -kR + 2.0 * kSpacing, 2, shift); // bottom layer one spacing above the first plate's top
  addWall(both, 2, -kR, 1);
  addWall(both, 2, -kR + 2.0 * kSpacing, 2, shift);
  computeBoundaryVolumes(alone1, kernel);
  computeBoundaryVolumes(alone2, kernel);
  computeBoundaryVolumes(both, kernel);
  const auto& v1 = alone1.real(kBoundaryVolumeField);
  const auto& v2 = alone2.real(kBoundaryVolumeField);
  const auto& v = both.real(kBoundaryVolumeField);
  ASSERT_EQ(v.size(), v1.size() + v2.size());
  for (std::size_t n = 0; n < v1.size(); ++n) ASSERT_NEAR(v[n], v1[n], 1e-12 * v1[n]) << n;
  for (std::size_t n = 0; n < v2.size(); ++n) ASSERT_NEAR(v[v1.size() + n], v2[n], 1e-12 * v2[n]) << n;

  // Control: as one body the plates do interact, so the test above is not vacuous.
  std::vector<std::int64_t>& body = both.integer(field::objectId);
  for (auto& b : body) b = 7;
  computeBoundaryVolumes(both, kernel);
  const std::size_t centreTopOfLower = kLateral / 2 + kLateral * (kLateral / 2);
  EXPECT_LT(both.real(kBoundaryVolumeField)[centreTopOfLower], 0.9 * v1[centreTopOfLower]);
}

} // namespace
} // namespace poro
