// Chebyshev acceleration of the relaxed Jacobi pressure sweeps (PressureSolver.hpp, METHOD.md §6.7): the same
// solution in fewer sweeps, and nothing changed for a step that converges before the acceleration begins.

#include "PorousTestSystems.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace poro {
namespace {

using namespace test;

constexpr double kDt = 1e-3;

struct Solved {
  std::vector<double> pi;
  PressureStats stats;
};

/// Water filling [0, 0.2]^3 (10^3 particles) in a closed two-layer tank standing 0.1 r off it, squeezed towards
/// its centre at 0.6 % per step, weightless: the pressure that stops the squeeze is smooth across the whole tank,
/// the kind of solution plain Jacobi sweeps approach slowly.
Solved solveSqueezedTank(bool chebyshev, double maxDensityErrorPercent) {
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, sampleBox(Vec3::Zero(), Vec3::Constant(0.2), kR));
  addSet(ps, "tank", SetKind::Boundary,
         sampleContainer(Vec3::Constant(-0.1 * kR), Vec3::Constant(0.2 + 0.1 * kR), kR, 2, FaceFlags{}), 1);
  SolverSettings settings;
  settings.pressure.chebyshev = chebyshev;
  settings.pressure.maxDensityError = maxDensityErrorPercent;
  settings.pressure.maxIterations = 100000;
  Solver solver(std::move(ps), weightless(), {}, settings, fixedStep(kDt), RunState{});
  const StepContext ctx = solver.beginStep(kDt);
  ParticleSet& water = solver.particles()[0];
  const Vec3 centre = Vec3::Constant(0.1);
  for (std::size_t i = 0; i < water.size(); ++i) water.v()[i] = -2.0 * (water.x()[i] - centre); // [m/s]
  solver.pressureSolver().predictDensities(ctx);
  const PressureStats stats = solver.pressureSolver().solve(ctx);
  return {water.real(field::pi), stats};
}

double largest(const std::vector<double>& values) { return *std::max_element(values.begin(), values.end()); }

TEST(ChebyshevPressure, ReachesTheJacobiSolutionInFewerSweeps) {
  // Converged to a mean compression of 1e-8, far below the 6e-3 the pressure removes. Two solutions that both
  // leave at most that residual differ by the residual times the inverse operator's gain, about the tank's
  // width squared in spacings (10^2) times 1e-8/6e-3 relative to pi: 2e-4, hence 1e-3.
  const double tolerance = 1e-6; // [%]
  const Solved jacobi = solveSqueezedTank(false, tolerance);
  const Solved chebyshev = solveSqueezedTank(true, tolerance);
  ASSERT_TRUE(jacobi.stats.converged);
  ASSERT_TRUE(chebyshev.stats.converged);
  const double scale = largest(jacobi.pi);
  ASSERT_GT(scale, 0.0);
  double difference = 0.0;
  for (std::size_t i = 0; i < jacobi.pi.size(); ++i)
    difference = std::max(difference, std::abs(chebyshev.pi[i] - jacobi.pi[i]));
  EXPECT_LT(difference, 1e-3 * scale);
  // The acceleration at the default rho = 0.9 cuts the sweeps of this smooth problem by more than half (a broken weight
  // schedule either diverges or falls back to Jacobi's count).
  EXPECT_LT(2 * chebyshev.stats.iterations, jacobi.stats.iterations)
      << "Chebyshev " << chebyshev.stats.iterations << " sweeps, Jacobi " << jacobi.stats.iterations;
}

TEST(ChebyshevPressure, AStepConvergedWithinThreeSweepsIsPlainJacobiBitForBit) {
  const double loose = 0.5; // [%]: converged after the two sweeps minIterations asks for
  const Solved jacobi = solveSqueezedTank(false, loose);
  const Solved chebyshev = solveSqueezedTank(true, loose);
  ASSERT_TRUE(jacobi.stats.converged);
  ASSERT_LE(jacobi.stats.iterations, 3);
  EXPECT_EQ(chebyshev.stats.iterations, jacobi.stats.iterations);
  EXPECT_EQ(chebyshev.pi, jacobi.pi);
}

} // namespace
} // namespace poro
