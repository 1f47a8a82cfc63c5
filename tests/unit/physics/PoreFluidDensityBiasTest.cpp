// The kernel's excess over the number density of sparse fluid, b(phi) (PoreFluidDensityBias.hpp).

#include "physics/PoreFluidDensityBias.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace poro {
namespace {

constexpr double kR = 0.01;
const double kVolume = 8.0 * kR * kR * kR;

/// sum V W over the simple cubic lattice of spacing d, at a lattice site, summed here independently.
double latticeSum(double d) {
  const CubicKernel kernel(4.0 * kR);
  double sum = 0.0;
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j)
      for (int k = -6; k <= 6; ++k) sum += kernel.w(d * std::sqrt(double(i * i + j * j + k * k)));
  return kVolume * sum;
}

TEST(PoreFluidDensityBias, VanishesWhereNoSolidIs) {
  const PoreFluidDensityBias bias(CubicKernel(4.0 * kR), kVolume);
  EXPECT_EQ(bias(1.0), 0.0);
  EXPECT_EQ(bias(1.2), 0.0);
}

TEST(PoreFluidDensityBias, IsTheLatticeSumAtTheIdealPoreSpacingMinusPhi) {
  // b(phi) = S(2r phi^(-1/3)) - phi S(2r); S(2r) = 0.99997 (METHOD.md §2.2). phi = 0.4: S = 0.4456.
  const PoreFluidDensityBias bias(CubicKernel(4.0 * kR), kVolume);
  const double dense = latticeSum(2.0 * kR);
  EXPECT_NEAR(dense, 0.99997, 1e-5);
  EXPECT_NEAR(bias(0.4), 0.4456 - 0.4 * dense, 1e-4);
  for (double phi = 0.05; phi < 1.0; phi += 0.0437) // off the table's points: checks the interpolation
    EXPECT_NEAR(bias(phi), latticeSum(2.0 * kR / std::cbrt(phi)) - phi * dense, 1e-5) << "phi " << phi;
}

TEST(PoreFluidDensityBias, IsTheSelfTermOnceTheSpacingExceedsTheSupport) {
  // phi < V / H^3 = 1/8: no neighbour within H, S = V W(0) = 1/pi.
  const PoreFluidDensityBias bias(CubicKernel(4.0 * kR), kVolume);
  for (const double phi : {0.02, 0.06, 0.12})
    EXPECT_NEAR(bias(phi), 1.0 / M_PI - phi * latticeSum(2.0 * kR), 1e-5) << "phi " << phi;
  EXPECT_NEAR(bias(0.0), bias(PoreFluidDensityBias::kMinShare), 1e-15); // clamped below
}

TEST(PoreFluidDensityBias, IsTheSameForEveryParticleSize) {
  // b depends on phi only: V W scales as V / H^3, and the spacing with r.
  const PoreFluidDensityBias small(CubicKernel(4.0 * 0.002), 8.0 * 0.002 * 0.002 * 0.002);
  const PoreFluidDensityBias large(CubicKernel(4.0 * kR), kVolume);
  for (const double phi : {0.1, 0.4, 0.7}) EXPECT_NEAR(small(phi), large(phi), 1e-12);
}

TEST(PoreFluidDensityBias, UncorrectedFillIsWhereTheFluidsOwnSumMeetsThePoreShare) {
  // Without the correction pore fluid rests where its own kernel sum is phi (rho~ = 1 with the solids' 1 - phi):
  // the lattice spacing d with S(d) = phi, found here by bisection on the independent sum, fills (2r / d)^3 / phi.
  // phi = 0.4: 0.83 on the lattice (the disordered seepage fluid holds 0.87 at r = 2 cm, 0.90 at 1 cm);
  // phi = 0.3 < 1/pi holds nothing.
  const PoreFluidDensityBias bias(CubicKernel(4.0 * kR), kVolume);
  for (const double phi : {0.4, 0.5, 0.6, 0.8}) {
    double lo = 1.5 * kR, hi = 4.0 * kR; // S falls with the spacing
    for (int it = 0; it < 60; ++it) (latticeSum(0.5 * (lo + hi)) > phi ? lo : hi) = 0.5 * (lo + hi);
    const double expected = std::pow(2.0 * kR / lo, 3) / phi;
    // b is taken relative to S(2r) = 0.99997, so the share is off by 3e-5 phi at most; the table by 1e-5.
    EXPECT_NEAR(bias.uncorrectedFill(phi), expected, 1e-3) << "phi " << phi;
  }
  EXPECT_EQ(bias.uncorrectedFill(0.3), 0.0);
  EXPECT_EQ(bias.uncorrectedFill(1.0), 1.0);
}

} // namespace
} // namespace poro
