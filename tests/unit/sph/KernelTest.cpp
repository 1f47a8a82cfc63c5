// Cubic spline kernel identities (METHOD.md §2.1): normalisation, gradient = derivative of W,
// continuity at the branch points q = 1/2 and q = 1, the documented special values.
#include "sph/Kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace poro {
namespace {

constexpr double kR = 0.01;     // particle radius r [m]
constexpr double kH = 4.0 * kR; // support radius H = 4r [m]

/// Composite Simpson rule on [a, b] with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + h * i);
  return sum * h / 3.0;
}

/// Radial integral 4 pi * int_0^{1.5 H} f(d) d^2 dd, split at the branch points H/2 and H so every piece is
/// a polynomial. Integrating past H also catches a kernel that does not vanish beyond its support.
double radialIntegral(const std::function<double(double)>& f, double h) {
  auto g = [&](double d) { return f(d) * d * d; };
  return 4.0 * M_PI * (simpson(g, 0.0, 0.5 * h, 2000) + simpson(g, 0.5 * h, h, 2000) + simpson(g, h, 1.5 * h, 2000));
}

Vec3 randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 e(n(rng), n(rng), n(rng));
  return e.normalized();
}

TEST(CubicKernel, SelfValueIsOneOverEightPiRCubed) {
  for (double r : {0.01, 0.025, 0.003}) {
    const CubicKernel k(4.0 * r);
    const double expected = 1.0 / (8.0 * M_PI * r * r * r);
    EXPECT_NEAR(k.w0(), expected, 1e-14 * expected);
    EXPECT_NEAR(k.w(0.0), expected, 1e-14 * expected);
    EXPECT_NEAR(k.w(Vec3::Zero()), expected, 1e-14 * expected);
    EXPECT_DOUBLE_EQ(k.supportRadius(), 4.0 * r);
  }
}

TEST(CubicKernel, IntegratesToOneRadially) {
  // Simpson on polynomial pieces of degree 5 with 2000 intervals: quadrature error ~1e-14, far below 1e-6.
  for (double r : {0.01, 0.025}) {
    const CubicKernel k(4.0 * r);
    EXPECT_NEAR(radialIntegral([&](double d) { return k.w(d); }, k.supportRadius()), 1.0, 1e-6) << "r = " << r;
  }
}

TEST(CubicKernel, GradientIntegralIsMinusThreeRadially) {
  // Integration by parts: int grad W . x dV = -3 int W dV = -3. Checks the normalisation of grad W
  // independently of W. grad W . x = gradFactor(d) d^2.
  const CubicKernel k(kH);
  const double integral = radialIntegral([&](double d) { return k.gradFactor(d) * d * d; }, kH);
  EXPECT_NEAR(integral, -3.0, 3e-6);
}

TEST(CubicKernel, IntegratesToOneOnAFineShiftedLattice) {
  // Lattice sum sum_b W(x_b) dx^3 of a C^2 kernel converges fast in dx: at dx = 2r = H/2 it is off by
  // 3e-5 (METHOD.md §2.2); at dx = H/16 the error is several orders below 1e-6.
  const CubicKernel k(kH);
  const double dx = kH / 16.0;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, dx);
  for (int trial = 0; trial < 3; ++trial) {
    const Vec3 shift(u(rng), u(rng), u(rng)); // arbitrary offset: the lattice need not contain the centre
    double sum = 0.0;
    for (int i = -17; i <= 17; ++i)
      for (int j = -17; j <= 17; ++j)
        for (int l = -17; l <= 17; ++l) sum += k.w(Vec3(i * dx, j * dx, l * dx) + shift);
    EXPECT_NEAR(sum * dx * dx * dx, 1.0, 1e-6) << "shift " << shift.transpose();
  }
}

TEST(CubicKernel, DocumentedBranchValues) {
  // Hand-evaluated formula values of METHOD.md §2.1 at q = 1/4 and q = 3/4 (one per branch).
  const CubicKernel k(kH);
  const double kW = 8.0 / (M_PI * kH * kH * kH);
  const double kG = 48.0 / (M_PI * kH * kH * kH);
  EXPECT_NEAR(k.w(0.25 * kH), kW * (6.0 / 64 - 6.0 / 16 + 1.0), 1e-13 * kW);
  EXPECT_NEAR(k.w(0.75 * kH), 2.0 * kW / 64.0, 1e-13 * kW);
  const Vec3 e = Vec3(1.0, -2.0, 2.0) / 3.0;
  // g(1/4) = 1/4 (3/4 - 2) = -5/16; g(3/4) = -(1/4)^2 = -1/16; grad W = kG g / H * e.
  EXPECT_LT((k.grad(0.25 * kH * e) - kG * (-5.0 / 16.0) / kH * e).norm(), 1e-13 * kG / kH);
  EXPECT_LT((k.grad(0.75 * kH * e) - kG * (-1.0 / 16.0) / kH * e).norm(), 1e-13 * kG / kH);
  // W is a decreasing radial function, so grad W(x) points against x.
  EXPECT_LT(k.grad(0.3 * kH * e).dot(e), 0.0);
}

TEST(CubicKernel, GradientEqualsCentralDifferencesOfW) {
  const CubicKernel k(kH);
  const double scale = 48.0 / (M_PI * kH * kH * kH) / kH; // magnitude scale of grad W [1/m^4]
  // Step h = 1e-6 H: truncation ~ h^2 W''' ~ 1e-12 and round-off ~ eps W / h ~ 1e-10, both relative to scale.
  const double h = 1e-6 * kH;
  const double tol = 1e-7 * scale;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> uq(0.0, 1.0);
  int inner = 0, outer = 0;
  for (int n = 0; n < 2000; ++n) {
    // Half the samples in each branch; a few right next to q = 1/2 and q = 1 where the stencil straddles them.
    double q;
    if (n % 10 == 0)
      q = (n % 20 == 0 ? 0.5 : 1.0) + (uq(rng) - 0.5) * 1e-5;
    else
      q = n % 2 ? 0.02 + 0.48 * uq(rng) : 0.5 + 0.5 * uq(rng);
    (q <= 0.5 ? inner : outer)++;
    const Vec3 x = q * kH * randomUnit(rng);
    Vec3 fd;
    for (int d = 0; d < 3; ++d) {
      Vec3 step = Vec3::Zero();
      step[d] = h;
      fd[d] = (k.w(x + step) - k.w(x - step)) / (2.0 * h);
    }
    ASSERT_LT((k.grad(x) - fd).norm(), tol) << "q = " << q << ", x = " << x.transpose();
  }
  EXPECT_GT(inner, 500);
  EXPECT_GT(outer, 500);
}

TEST(CubicKernel, ContinuousAtHalfAndAtSupport) {
  const CubicKernel k(kH);
  const double kW = k.w0();
  const double scale = 48.0 / (M_PI * kH * kH * kH) / kH;
  // Either side of a branch point at +-delta: a continuous W differs by at most 2 delta max|grad W| (< 2 delta
  // scale), a jump would be of order kW. Same for grad W with its second derivative (< 10 scale / H).
  const double delta = 1e-9 * kH;
  const Vec3 e = Vec3(2.0, 3.0, 6.0) / 7.0;
  for (double qb : {0.5, 1.0}) {
    const double below = qb * kH - delta, above = qb * kH + delta;
    EXPECT_NEAR(k.w(below), k.w(above), 2.0 * delta * scale) << "q = " << qb;
    EXPECT_LT((k.grad(below * e) - k.grad(above * e)).norm(), 20.0 * delta * scale / kH) << "q = " << qb;
  }
  // Branch values themselves: W(H/2) = kW/4 from both formulas, grad at H/2 has g = -1/4; W(H) = grad W(H) = 0.
  EXPECT_NEAR(k.w(0.5 * kH), 0.25 * kW, 1e-14 * kW);
  EXPECT_NEAR(k.gradFactor(0.5 * kH) * 0.5 * kH, -0.25 * scale, 1e-14 * scale);
  EXPECT_EQ(k.w(kH), 0.0);
  EXPECT_EQ(k.grad(kH * e).norm(), 0.0);
  // Approaching H the kernel vanishes like (1 - q)^3 and its gradient like (1 - q)^2.
  EXPECT_LT(k.w(kH * (1.0 - 1e-4)), 2.0 * kW * 1e-12 * 1.01);
  EXPECT_LT(k.grad(kH * (1.0 - 1e-4) * e).norm(), scale * 1e-8 * 1.01);
}

TEST(CubicKernel, GradientVanishesAtTheOriginAndBeyondSupport) {
  const CubicKernel k(kH);
  for (const Vec3& x : {Vec3(Vec3::Zero()), Vec3(1e-9, 0.0, 0.0), Vec3(0.0, -5e-10, 5e-10), Vec3(kH, 0.0, 0.0),
                        Vec3(0.0, 1.0000001 * kH, 0.0), Vec3(kH, kH, kH), Vec3(1e3, 0.0, 0.0)})
    EXPECT_EQ(k.grad(x), Vec3::Zero()) << x.transpose();
  EXPECT_EQ(k.gradFactor(0.0), 0.0);
  EXPECT_EQ(k.gradFactor(1e-9), 0.0);
  EXPECT_EQ(k.gradFactor(1.5 * kH), 0.0);
  EXPECT_EQ(k.w(1.0000001 * kH), 0.0);
  EXPECT_EQ(k.w(Vec3(kH, kH, 0.0)), 0.0);
  // Just above the 1e-9 m cut-off the gradient is the regular (linear in x) one again.
  EXPECT_NE(k.gradFactor(2e-9), 0.0);
}

TEST(CubicKernel, GradFactorConsistentWithGradAndSymmetric) {
  const CubicKernel k(kH);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uq(0.0, 1.2);
  for (int n = 0; n < 1000; ++n) {
    const Vec3 x = uq(rng) * kH * randomUnit(rng);
    const Vec3 g = k.grad(x);
    EXPECT_EQ(g, Vec3(k.gradFactor(x.norm()) * x));
    EXPECT_EQ(k.grad(-x), Vec3(-g)); // antisymmetric gradient, symmetric W
    EXPECT_EQ(k.w(-x), k.w(x));
    EXPECT_LE(k.gradFactor(x.norm()), 0.0); // W never increases outwards
  }
}

TEST(CubicKernel, BatchEvaluationIsTheScalarOneBitForBit) {
  // The density pass reads W and s from values() and gradientFactors(): at the distance the batch computes they
  // must be w() and gradFactor() exactly, on both pieces, at the branch points, at the support's edge, beyond it
  // and at the origin's cut-off. The distance itself is the norm to round-off only: with fused multiply-adds the
  // compiler may fuse a different product of dx² + dy² + dz² here than in Eigen's norm(). Each sum of squares is
  // within 3 eps of the exact one (three roundings at most on any term), so the two roots differ by at most
  // (3 + 3) / 2 eps, plus half an eps each for the roots' own rounding: 4 eps of the distance.
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const CubicKernel k(kH);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uq(0.0, 1.2);
  std::vector<Vec3> offsets = {Vec3::Zero(),         Vec3(1e-9, 0.0, 0.0),
                               Vec3(2e-9, 0.0, 0.0), Vec3(0.5 * kH, 0.0, 0.0),
                               Vec3(0.0, kH, 0.0),   Vec3(0.0, 0.0, 1.0000001 * kH)};
  for (int n = 0; n < 1001; ++n) offsets.push_back(uq(rng) * kH * randomUnit(rng)); // odd: a scalar remainder
  const std::size_t n = offsets.size();
  std::vector<double> dx(n), dy(n), dz(n), dist(n), w(n), s(n);
  std::vector<float> rounded(n);
  for (std::size_t i = 0; i < n; ++i) {
    dx[i] = offsets[i].x();
    dy[i] = offsets[i].y();
    dz[i] = offsets[i].z();
  }
  k.values(n, dx.data(), dy.data(), dz.data(), dist.data(), w.data());
  k.gradientFactors(n, dist.data(), s.data());
  k.gradientFactors(n, dist.data(), rounded.data());
  for (std::size_t i = 0; i < n; ++i) {
    const double d = offsets[i].norm();
    EXPECT_LE(std::abs(dist[i] - d), 4.0 * eps * d) << i;
    EXPECT_EQ(w[i], k.w(dist[i])) << i;
    EXPECT_EQ(s[i], k.gradFactor(dist[i])) << i;
    EXPECT_EQ(rounded[i], static_cast<float>(k.gradFactor(dist[i]))) << i;
  }
}

} // namespace
} // namespace poro
