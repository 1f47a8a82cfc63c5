// Kernel sums on a simple cubic lattice of spacing 2r: the reference values of METHOD.md §2.2 and
// VALIDATION.md "Kernel and sampling".
#include "core/Parallel.hpp"
#include "sph/Kernel.hpp"
#include "sph/NeighbourSearch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace poro {
namespace {

/// Lattice sums seen by particle a at `centre`, over the lattice points centre + 2r (i, j, l) with
/// |i|, |j|, |l| <= 3 that `keep` accepts (3 spacings = 6r > H, so the neighbourhood is complete).
struct LatticeSums {
  double shepard = 0.0;        ///< sum_b V W_ab including b = a
  Vec3 gradSum = Vec3::Zero(); ///< G = sum_b V grad W_ab
  double gradSumScale = 0.0;   ///< sum_b |V grad W_ab|, the size of the round-off of gradSum
  double q = 0.0;              ///< Q = sum_b V^2 |grad W_ab|^2
  Mat3 gradX = Mat3::Zero();   ///< sum_b V grad W_ab (x_b - x_a)^T
};

LatticeSums latticeSums(double r, const Vec3& centre, const std::function<bool(int, int, int)>& keep) {
  const CubicKernel k(4.0 * r);
  const double spacing = 2.0 * r, volume = spacing * spacing * spacing;
  LatticeSums s;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int l = -3; l <= 3; ++l) {
        if (!keep(i, j, l)) continue;
        const Vec3 xb = centre + spacing * Vec3(i, j, l);
        const Vec3 xab = centre - xb;
        s.shepard += volume * k.w(xab);
        const Vec3 g = volume * k.grad(xab);
        s.gradSum += g;
        s.gradSumScale += g.norm();
        s.q += g.squaredNorm();
        s.gradX += g * (xb - centre).transpose();
      }
  return s;
}

bool interior(int, int, int) { return true; }
bool face(int, int, int l) { return l >= 0; }             // half-space below z_a is empty
bool edge(int, int j, int l) { return j >= 0 && l >= 0; } // quarter-space
bool corner(int i, int j, int l) { return i >= 0 && j >= 0 && l >= 0; }

constexpr double kR = 0.01; // r = 1 cm
// A centre away from the origin, so that x_a - x_b carries real round-off.
const Vec3 kCentre(0.3137, -0.1234, 0.0571);

TEST(LatticeSum, SelfTermIsOneOverPi) {
  for (double r : {0.01, 0.005, 0.025}) {
    const CubicKernel k(4.0 * r);
    EXPECT_NEAR(std::pow(2.0 * r, 3) * k.w0(), 1.0 / M_PI, 1e-14);
  }
}

TEST(LatticeSum, ShepardSumsInteriorFaceEdgeCorner) {
  EXPECT_NEAR(latticeSums(kR, kCentre, interior).shepard, 0.99997, 1e-4);
  EXPECT_NEAR(latticeSums(kR, kCentre, face).shepard, 0.850, 2e-3);
  EXPECT_NEAR(latticeSums(kR, kCentre, edge).shepard, 0.720, 2e-3);
  EXPECT_NEAR(latticeSums(kR, kCentre, corner).shepard, 0.607, 2e-3);
}

TEST(LatticeSum, ShepardRestVolumes) {
  // V0/V = 1 / sum_b V W_ab: 1.00003 / 1.176 / 1.390 / 1.649 (METHOD.md §2.2), same tolerances as the sums.
  EXPECT_NEAR(1.0 / latticeSums(kR, kCentre, interior).shepard, 1.00003, 1e-4);
  EXPECT_NEAR(1.0 / latticeSums(kR, kCentre, face).shepard, 1.176, 2e-3);
  EXPECT_NEAR(1.0 / latticeSums(kR, kCentre, edge).shepard, 1.390, 2e-3);
  EXPECT_NEAR(1.0 / latticeSums(kR, kCentre, corner).shepard, 1.649, 2e-3);
}

TEST(LatticeSum, SumsDoNotDependOnTheParticleRadius) {
  // V W and V grad W (x_b - x_a) are dimensionless: the same lattice at another r gives the same sums.
  const LatticeSums a = latticeSums(0.01, kCentre, interior), b = latticeSums(0.0037, kCentre, interior);
  EXPECT_NEAR(a.shepard, b.shepard, 1e-12);
  EXPECT_LT((a.gradX - b.gradX).norm(), 1e-10);
}

TEST(LatticeSum, GradientSumVanishesInTheInterior) {
  const LatticeSums s = latticeSums(kR, kCentre, interior);
  ASSERT_GT(s.gradSumScale, 100.0); // the terms themselves are O(10) 1/m each
  // Pairs cancel exactly up to the round-off of x_a - x_b (a few ulps of each term).
  EXPECT_LT(s.gradSum.norm(), 1e-12 * s.gradSumScale) << s.gradSum.transpose();
  // At a face the sum does not vanish: grad W_ab (derivative in x_a) points from a towards b, so the sum
  // points towards the present half-space (+z).
  const LatticeSums f = latticeSums(kR, kCentre, face);
  EXPECT_GT(f.gradSum.z(), 0.1 * f.gradSumScale / 26.0);
  EXPECT_LT(std::abs(f.gradSum.x()) + std::abs(f.gradSum.y()), 1e-12 * f.gradSumScale);
}

TEST(LatticeSum, UncorrectedGradientOfPositionIsIsotropic) {
  // sum_b V grad W_ab (x_b - x_a)^T = 1.020 I in the interior (METHOD.md §2.2).
  const LatticeSums s = latticeSums(kR, kCentre, interior);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(s.gradX(d, d), 1.020, 1e-3) << "d = " << d;
    for (int e = 0; e < 3; ++e)
      if (e != d) {
        EXPECT_NEAR(s.gradX(d, e), 0.0, 1e-12) << d << ", " << e;
      }
  }
}

TEST(LatticeSum, PressureDiagonalOfAnInteriorParticle) {
  // ||G||^2 + Q = 1062 1/m^2 at r = 1 cm (METHOD.md §2.2, §6.3); G = 0 in the interior.
  const LatticeSums a = latticeSums(0.01, kCentre, interior);
  const double atCm = a.gradSum.squaredNorm() + a.q;
  EXPECT_NEAR(atCm, 1062.0, 1.0);
  // V^2 |grad W|^2 ~ r^6 r^-8 = r^-2: halving r quadruples it.
  const LatticeSums b = latticeSums(0.005, kCentre, interior);
  const double atHalfCm = b.gradSum.squaredNorm() + b.q;
  EXPECT_NEAR(atHalfCm / atCm, 4.0, 1e-9);
  EXPECT_NEAR(atHalfCm, 4.0 * 1062.0, 4.0);
}

TEST(LatticeSum, InteriorParticleHasTwentySixNeighbours) {
  // A 7^3 lattice whose centre particle sits at the origin, so the 6 second neighbours are at exactly
  // 2 * 2r = H in floating point (4r is exact when H = 4r) and must not count (strict < H).
  const double r = kR, spacing = 2.0 * r;
  std::vector<Vec3> x;
  for (int l = -3; l <= 3; ++l)
    for (int j = -3; j <= 3; ++j)
      for (int i = -3; i <= 3; ++i) x.emplace_back(spacing * i, spacing * j, spacing * l);
  const std::size_t centre = 3 + 7 * (3 + 7 * 3);
  ASSERT_EQ(x[centre], Vec3::Zero());
  const int threadsBefore = parallel::threads();
  for (int threads : {1, 2}) {
    parallel::setThreads(threads);
    NeighbourSearch search(4.0 * r);
    search.update({&x}, {{true}});
    const auto& list = search.list(0, 0);
    EXPECT_EQ(list.of(centre).size(), 26u);
    const CubicKernel k(4.0 * r);
    for (Index b : list.of(centre)) {
      const double d = (x[centre] - x[static_cast<std::size_t>(b)]).norm();
      EXPECT_LT(d, 4.0 * r);
      EXPECT_GT(k.w(d), 0.0); // every listed neighbour has a non-zero weight
    }
  }
  parallel::setThreads(threadsBefore);
}

} // namespace
} // namespace poro
