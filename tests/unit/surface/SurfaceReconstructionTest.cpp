// The clouds fluidSurface reconstructs: pore fluid left out of the free surface, and a swollen porous body that
// stays a closed body of its swollen volume.

#include "surface/SurfaceReconstruction.hpp"

#include "physics/FieldNames.hpp"
#include "sph/ParticleSystem.hpp"
#include "surface/PorousVolumes.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

constexpr double kR = 0.01;

/// A porous lattice block of n^3 particles at [0, 2rn]^3 (objectId 1), rest positions X on the lattice and
/// current positions X scaled by `stretch` about the origin.
ParticleSet& addBlock(ParticleSystem& ps, int n, double stretch, double saturation) {
  ParticleSet& block = ps.add("foam", SetKind::Porous);
  block.resize(static_cast<std::size_t>(n * n * n));
  auto& rest = block.addVec3(field::restPosition, Restart);
  auto& s = block.addReal(field::saturation, Output);
  std::size_t p = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++p) {
        rest[p] = Vec3(kR, kR, kR) + 2.0 * kR * Vec3(i, j, k);
        block.x()[p] = stretch * rest[p];
        block.integer(field::id)[p] = static_cast<std::int64_t>(p);
        block.integer(field::objectId)[p] = 1;
        s[p] = saturation;
      }
  return block;
}

TEST(SurfaceReconstruction, PoreFluidIsNotFreeSurface) {
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  // Two fluid particles in the block's cells, one just outside, one far above.
  const std::vector<Vec3> x{{0.05, 0.05, 0.05}, {0.011, 0.03, 0.07}, {0.085, 0.05, 0.05}, {0.05, 0.5, 0.05}};
  fluid.resize(x.size());
  fluid.x() = x;
  addBlock(ps, 4, 1.0, 0.5);
  SurfaceSettings settings;
  const ParticleCloud excluded = fluidCloud(ps, settings);
  ASSERT_EQ(excluded.positions.size(), 2u);
  EXPECT_EQ(excluded.positions[0], x[2]);
  EXPECT_EQ(excluded.positions[1], x[3]);
  settings.poreFluid = PoreFluid::Include;
  EXPECT_EQ(fluidCloud(ps, settings).positions.size(), 4u);
}

TEST(SurfaceReconstruction, ASwollenBodyKeepsItsColourFieldAndIsClosed) {
  // Swollen by 20 % per axis (as bloating does): spacing 2.4 r, so with lattice volumes c would be
  // (1/1.2)^3 = 0.58 inside, barely above the surface. Deformed volumes give c = 1 again and the volume of the
  // swollen body.
  ParticleSystem ps(kR);
  const double stretch = 1.2;
  const ParticleSet& block = addBlock(ps, 8, stretch, 0.25);
  const std::vector<double> volumes = deformedVolumes(block, kR);
  const double lattice = 8.0 * kR * kR * kR;
  for (double v : volumes) ASSERT_NEAR(v / lattice, stretch * stretch * stretch, 1e-9) << "volume ratio"; // affine: exact
  const ParticleCloud cloud = porousCloud(ps);
  const Reconstruction made = reconstruct(cloud, ReconstructionSettings{}, kR);
  const Vec3 centre = Vec3::Constant(stretch * 8.0 * kR);
  EXPECT_NEAR(made.grid.sample(centre), 1.0, 0.05);
  EXPECT_TRUE(made.surface.defects().none());
  // The swollen block of edge 1.2 x 0.16 m, less its rounded edges (IsoSurfaceTest: under 1.2 r^2 per length).
  const double edge = stretch * 16.0 * kR;
  EXPECT_LT(made.surface.enclosedVolume(), edge * edge * edge);
  EXPECT_GT(made.surface.enclosedVolume(), edge * edge * edge - 12.0 * edge * 1.2 * (stretch * kR) * (stretch * kR));
  // The saturation reaches the surface as it is inside.
  const TriangleSurface::Field* s = made.surface.field(field::saturation);
  ASSERT_NE(s, nullptr);
  for (double value : s->values) ASSERT_NEAR(value, 0.25, 1e-4);
}

TEST(SurfaceReconstruction, WithoutRestPositionsVolumesAreTheLattices) {
  ParticleSet set("foam", SetKind::Porous);
  set.resize(3);
  for (double v : deformedVolumes(set, kR)) EXPECT_DOUBLE_EQ(v, 8.0 * kR * kR * kR);
}

} // namespace
} // namespace poro
