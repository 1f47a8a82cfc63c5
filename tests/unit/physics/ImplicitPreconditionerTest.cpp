// The implicit solve's block-Jacobi preconditioner (METHOD.md §6.5.8) is formed a window of particles at a time:
// every term must give a particle the same diagonal block in any window as in the whole.

#include "PorousTestSystems.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <random>

namespace poro {
namespace {

using namespace test;

TEST(ImplicitPreconditioner, BlocksFormedInWindowsAreTheWholeDiagonals) {
  // Fluid with viscosity at a floor, seeping into an elastic, damped, dragging, adhering porous block whose
  // lowest particles are Fixed: every implicit term has a diagonal part here.
  std::mt19937 rng(5);
  const double a = 0.2 * kR;
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, jittered(sampleBox(Vec3(0, 0.06, 0), Vec3(0.1, 0.12, 0.1), kR), rng, a));
  ParticleSet& soil =
      addSet(ps, "soil", SetKind::Porous, jittered(sampleBox(Vec3::Zero(), Vec3(0.1, 0.08, 0.1), kR), rng, a));
  addSet(ps, "floor", SetKind::Boundary, sampleBox(Vec3(-0.04, -0.04, -0.04), Vec3(0.14, 0.0, 0.14), kR));
  auto& fixed = soil.addInt(field::fixed, Restart);
  for (std::size_t i = 0; i < soil.size(); ++i) fixed[i] = soil.x()[i].y() < 0.01 ? 1 : 0;
  FluidProperties fluid = weightless();
  fluid.viscosity = 1.0;
  fluid.boundaryViscosity = 2.0;
  PorousMaterial m = material("soil", 0.5, 2000.0, false, 5.0);
  m.youngsModulus = 1e5;
  m.dampingViscosity = 3.0;
  m.boundaryDampingViscosity = 4.0;
  m.capillaryStrength = 500.0;
  m.capillaryFalloff = 0.5;
  Solver solver(std::move(ps), fluid, {m}, SolverSettings{}, fixedStep(1e-3), RunState{});
  const StepContext ctx = solver.beginStep(1e-3);
  const ImplicitSolver& op = solver.implicitSolver();
  solver.implicitSolver().prepare(ctx);

  const std::size_t parts = ctx.dynamicSets.size();
  ASSERT_EQ(parts, 2u);
  std::vector<std::vector<Mat3>> whole(parts);
  linalg::BlockDiagonal all;
  for (std::size_t p = 0; p < parts; ++p) {
    whole[p].resize(solver.particles()[ctx.dynamicSets[p]].size());
    all.push_back({whole[p].data(), whole[p].size()});
  }
  op.diagonal(all);
  std::size_t fixedRows = 0;
  for (std::size_t p = 0; p < parts; ++p) {
    const double mass = solver.particles()[ctx.dynamicSets[p]].mass;
    std::size_t coupled = 0;
    for (const Mat3& block : whole[p]) {
      coupled += (block - mass * Mat3::Identity()).norm() > 1e-6 * mass ? 1 : 0;
      fixedRows += block == mass * Mat3::Identity() ? 1 : 0;
    }
    EXPECT_GT(coupled, whole[p].size() / 2) << "part " << p << ": the terms add to most blocks";
  }
  EXPECT_GT(fixedRows, 0u) << "Fixed rows keep m I";

  for (const std::size_t width : {std::size_t(1), std::size_t(7), std::size_t(100)}) {
    std::vector<Mat3> scratch(parts * width);
    const std::size_t largest = std::max(whole[0].size(), whole[1].size());
    std::size_t mismatches = 0;
    for (std::size_t first = 0; first < largest; first += width) {
      linalg::BlockDiagonal window;
      for (std::size_t p = 0; p < parts; ++p) {
        const std::size_t size = whole[p].size();
        window.push_back({scratch.data() + p * width, first < size ? std::min(width, size - first) : 0, first});
      }
      op.diagonal(window);
      for (std::size_t p = 0; p < parts; ++p)
        for (std::size_t k = 0; k < window[p].size; ++k) mismatches += window[p].data[k] == whole[p][first + k] ? 0 : 1;
    }
    EXPECT_EQ(mismatches, 0u) << "windows of " << width;
  }
}

TEST(ImplicitPreconditioner, SymmetricBlockKeepsASymmetricMatrixToSinglePrecision) {
  Mat3 m;
  m << 4.0, 0.5, -0.25, 0.5, 3.0, 0.125, -0.25, 0.125, 2.0;
  const linalg::SymmetricBlock block(m.inverse());
  const Vec3 v(0.3, -1.2, 2.5);
  const Vec3 exact = m.inverse() * v;
  EXPECT_LT((block * v - exact).norm(), 4.0 * 0x1p-24 * m.inverse().norm() * v.norm());
  EXPECT_EQ(block.matrix(), block.matrix().transpose());
  EXPECT_LT((block.matrix() - m.inverse()).norm(), 2.0 * 0x1p-24 * m.inverse().norm());
}

} // namespace
} // namespace poro
