// Implicit porous drag (METHOD.md §6.5.5, Eq. 16) inside the momentum operator (§6.5.1, §6.5.8).

#include "physics/PorousDrag.hpp"
#include "PorousTestSystems.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace poro {
namespace {

using namespace test;

const char* const kU = "testU";
const char* const kAu = "testAu";
const char* const kW = "testW";
const char* const kAw = "testAw";

/// Jittered fluid streaming through two porous materials with drag (no walls, no Fixed particles), with
/// the implicit operator of the step prepared.
class DragOperator : public ::testing::Test {
protected:
  void SetUp() override {
    std::mt19937 rng(21);
    const double a = 0.3 * kR;
    ParticleSystem ps(kR);
    addSet(ps, "fluid", SetKind::Fluid, jittered(sampleBox(Vec3::Zero(), Vec3(0.16, 0.1, 0.1), kR), rng, a));
    addSet(ps, "sand", SetKind::Porous, jittered(sampleBox(Vec3::Zero(), Vec3(0.08, 0.1, 0.1), kR), rng, a));
    addSet(ps, "foam", SetKind::Porous, jittered(sampleBox(Vec3(0.08, 0, 0), Vec3(0.16, 0.1, 0.1), kR), rng, a));
    solver_ = std::make_unique<Solver>(std::move(ps), weightless(),
                                       std::vector<PorousMaterial>{material("sand", 0.4, 2650.0, false, 20.0),
                                                                   material("foam", 0.7, 800.0, true, 50.0)},
                                       SolverSettings{}, fixedStep(1e-3), RunState{});
    ctx_ = std::make_unique<StepContext>(solver_->beginStep(1e-3));
    for (std::size_t a : ctx_->dynamicSets)
      for (const char* name : {kU, kAu, kW, kAw}) solver_->particles()[a].addVec3(name);
    solver_->implicitSolver().prepare(*ctx_);
  }
  linalg::BlockVector view(const char* name) const { return ImplicitSolver::view(*ctx_, name); }
  void randomise(const char* name, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (auto& part : view(name))
      for (std::size_t i = 0; i < part.size; ++i) part.data[i] = Vec3(value(rng), value(rng), value(rng));
  }
  double mass(std::size_t part) const { return solver_->particles()[ctx_->dynamicSets[part]].mass; }
  std::unique_ptr<Solver> solver_;
  std::unique_ptr<StepContext> ctx_;
};

TEST_F(DragOperator, IsSymmetricPositiveDefinite) {
  randomise(kU, 1);
  randomise(kW, 2);
  const ImplicitSolver& op = solver_->implicitSolver();
  op.apply(view(kU), view(kAu));
  op.apply(view(kW), view(kAw));
  const double wAu = linalg::dot(view(kW), view(kAu)), awU = linalg::dot(view(kAw), view(kU));
  EXPECT_NEAR(wAu, awU, 1e-12 * std::abs(wAu));
  EXPECT_GT(linalg::dot(view(kU), view(kAu)), 0.0);
}

TEST_F(DragOperator, PairForcesCancel) {
  // With no walls sum_a F_a(u) = 0: sum_a (A u - M u)_a vanishes to round-off (one coefficient per pair).
  randomise(kU, 3);
  solver_->implicitSolver().apply(view(kU), view(kAu));
  Vec3 total = Vec3::Zero();
  double scale = 0.0;
  const auto u = view(kU), au = view(kAu);
  for (std::size_t p = 0; p < u.size(); ++p)
    for (std::size_t i = 0; i < u[p].size; ++i) {
      const Vec3 force = au[p].data[i] - mass(p) * u[p].data[i];
      total += force;
      scale += force.norm();
    }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(total.norm(), 1e-13 * scale);
}

TEST_F(DragOperator, DiagonalBlocksEqualProbes) {
  // D_a equals the operator applied to the three unit vectors of particle a (METHOD.md §6.5.8).
  const ImplicitSolver& op = solver_->implicitSolver();
  for (std::size_t a : ctx_->dynamicSets) solver_->particles()[a].addMat3("testD");
  linalg::BlockDiagonal d;
  for (std::size_t a : ctx_->dynamicSets) {
    auto& f = solver_->particles()[a].mat3("testD");
    d.push_back({f.data(), f.size()});
  }
  op.diagonal(d);
  const auto u = view(kU), au = view(kAu);
  for (std::size_t p = 0; p < u.size(); ++p)
    for (std::size_t i = 0; i < u[p].size; i += 13)
      for (int c = 0; c < 3; ++c) {
        for (const auto& part : u)
          for (std::size_t j = 0; j < part.size; ++j) part.data[j].setZero();
        u[p].data[i][c] = 1.0;
        op.apply(u, au);
        const Vec3 column = au[p].data[i];
        EXPECT_LT((column - d[p].data[i].col(c)).norm(), 1e-12 * column.norm()) << "part " << p << " particle " << i;
      }
}

/// Total drag force on the fluid streaming at w through a resting porous lattice (METHOD.md §6.5.5 test).
Vec3 streamingForce(const Vec3& w, bool bodyCentred) {
  ParticleSystem ps(kR);
  // Body-centred: one particle fewer per axis, shifted by r, so both lattices share the block's centre.
  const double inset = bodyCentred ? kR : 0.0;
  const std::vector<Vec3> fluid = sampleBox(Vec3::Constant(inset), Vec3::Constant(0.12 - inset), kR);
  addSet(ps, "fluid", SetKind::Fluid, fluid, 0, w);
  addSet(ps, "sand", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3::Constant(0.12), kR), 1);
  Solver solver(std::move(ps), weightless(), {material("sand", 0.5, 2000.0, false, 10.0)}, SolverSettings{},
                fixedStep(1e-3), RunState{});
  const StepContext ctx = solver.beginStep(1e-3);
  for (std::size_t a : ctx.dynamicSets) solver.particles()[a].addVec3(kAu);
  ImplicitSolver& op = solver.implicitSolver();
  op.prepare(ctx);
  const auto v = ImplicitSolver::view(ctx, "v"), au = ImplicitSolver::view(ctx, kAu);
  op.apply(v, au);
  Vec3 force = Vec3::Zero(); // F = -(A u - M u)/dt over the fluid
  const ParticleSet& f = solver.particles()[0];
  for (std::size_t i = 0; i < f.size(); ++i) force -= (au[0].data[i] - f.mass * v[0].data[i]) / 1e-3;
  return force;
}

TEST(DragStreaming, LinearAndIsotropicForCoincidentAndBodyCentredLattices) {
  // A cubic block is invariant under the cubic group, so the summed drag tensor is a multiple of I: the
  // force opposes w and has the same size along an axis and a diagonal; it doubles when w doubles.
  for (const bool offset : {false, true}) {
    const Vec3 axis(0.1, 0.0, 0.0), diagonal = Vec3(1.0, 1.0, 1.0).normalized() * 0.1;
    const Vec3 fa = streamingForce(axis, offset), fd = streamingForce(diagonal, offset);
    ASSERT_GT(fa.norm(), 0.0);
    EXPECT_LT((fa.normalized() + axis.normalized()).norm(), 1e-10);
    EXPECT_LT((fd.normalized() + diagonal.normalized()).norm(), 1e-10);
    EXPECT_NEAR(fd.norm(), fa.norm(), 1e-10 * fa.norm());
    EXPECT_LT((streamingForce(2.0 * axis, offset) - 2.0 * fa).norm(), 1e-10 * fa.norm());
  }
}

TEST(DragRelaxation, RelativeVelocityDecaysAsImplicitEuler) {
  // VALIDATION.md "Relative-velocity decay": saturated block, no gravity, no walls, fluid streaming at w0
  // relative to the solid. The relative velocity of interior particles decays per step by 1/(1 + dt/tau),
  // tau = 1/(K (1/(phi rho_f) + 1/((1 - phi) rho_s0))), K the drag coefficient per unit volume computed from
  // the lattice neighbourhood of an interior fluid particle. Total momentum is conserved.
  const double phi = 0.5, rhoS = 2000.0, mu = 2.0, dt = 1e-3, w0 = 0.05;
  // Fluid fills the pores slightly below rest density, so the pressure solve stays out of the way.
  const double d = 1.05 * 2.0 * kR * std::cbrt(1.0 / phi);
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, latticeOfSpacing(Vec3::Zero(), Vec3::Constant(0.3), d), 0, Vec3(w0, 0, 0));
  addSet(ps, "sand", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3::Constant(0.3), kR), 1);
  SolverSettings settings;
  settings.implicit.tolerance = 1e-10;
  settings.implicit.maxIterations = 500;
  Solver solver(std::move(ps), weightless(), {material("sand", phi, rhoS, false, mu)}, settings, fixedStep(dt),
                RunState{});
  const ParticleSet& fluid = solver.particles()[0];
  const ParticleSet& sand = solver.particles()[1];
  const Vec3 centre = Vec3::Constant(0.15);
  auto interiorMean = [&](const ParticleSet& set) {
    Vec3 sum = Vec3::Zero();
    int n = 0;
    for (std::size_t i = 0; i < set.size(); ++i)
      if ((set.x()[i] - centre).lpNorm<Eigen::Infinity>() < 0.06) sum += set.v()[i], ++n;
    return Vec3(sum / n);
  };
  auto momentum = [&] {
    Vec3 p = Vec3::Zero();
    for (const ParticleSet* set : {&fluid, &sand})
      for (const Vec3& v : set->v()) p += set->mass * v;
    return p;
  };

  // K per unit volume: an interior fluid particle's sum_t K_it |s| |x|^2 / 3 times the fluid number density.
  const StepContext ctx = solver.beginStep(dt);
  const std::size_t i = nearest(fluid.x(), centre);
  const NeighbourList& list = ctx.search.list(0, 1);
  const double v = 8.0 * kR * kR * kR, h = 4.0 * kR;
  double k = 0.0;
  for (Index t : list.of(i)) {
    const Vec3 x = fluid.x()[i] - sand.x()[static_cast<std::size_t>(t)];
    const double kit =
        PorousDrag::coefficient(mu, 1000.0 * v, fluid.real(field::density)[i] * phi, (1.0 - phi) * rhoS * v,
                                (1.0 - phi) * rhoS, x.squaredNorm(), 0.01 * h * h);
    k += -kit * ctx.kernel.gradFactor(x.norm()) * x.squaredNorm() / 3.0;
  }
  const double kVolume = k * phi / v;
  const double tau = 1.0 / (kVolume * (1.0 / (phi * 1000.0) + 1.0 / ((1.0 - phi) * rhoS)));
  const double factor = 1.0 / (1.0 + dt / tau);
  ASSERT_LT(factor, 0.9); // the test must see real decay
  ASSERT_GT(factor, 0.1);

  const Vec3 p0 = momentum();
  double relative = w0;
  for (int n = 1; n <= 5; ++n) {
    solver.step(dt);
    const double now = (interiorMean(fluid) - interiorMean(sand)).x();
    EXPECT_NEAR(now / relative, factor, 0.1 * factor) << "step " << n;
    relative = now;
  }
  EXPECT_LT((momentum() - p0).norm(), 1e-6 * p0.norm());
}

} // namespace
} // namespace poro
