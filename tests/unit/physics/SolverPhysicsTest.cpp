// Physics checks of one step on small particle systems (METHOD.md §4.3, §6.5, §6.7, §6.8).

#include "geometry/LatticeSampling.hpp"
#include "physics/FieldNames.hpp"
#include "physics/Solver.hpp"

#include <gtest/gtest.h>

#include <random>

namespace poro {
namespace {

constexpr double kR = 0.01;

ParticleSystem fluidBlob(const std::vector<Vec3>& points, const Vec3& velocity = Vec3::Zero()) {
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    fluid.x()[i] = points[i];
    fluid.v()[i] = velocity;
    fluid.integer(field::id)[i] = static_cast<std::int64_t>(i);
  }
  return ps;
}

TimeControl fixedStep(double dt) {
  TimeControl control;
  control.deltaT = dt;
  control.endTime = 1.0;
  control.writeInterval = 1.0;
  return control;
}

Vec3 momentum(const ParticleSet& set) {
  Vec3 p = Vec3::Zero();
  for (const Vec3& v : set.v()) p += set.mass * v;
  return p;
}

TEST(Integration, LoneParticleFallsExactlyAsSymplecticEuler) {
  // x_n = x_0 + g dt^2 n (n + 1) / 2 (METHOD.md §6.8), all fields finite (§4.3).
  const double dt = 1e-3;
  Solver solver(fluidBlob({Vec3(0.1, 2.0, 0.3)}), FluidProperties{}, {}, SolverSettings{}, fixedStep(dt), RunState{});
  const Vec3 g(0.0, -9.81, 0.0);
  for (int n = 1; n <= 50; ++n) {
    solver.step(dt);
    const Vec3 expected = Vec3(0.1, 2.0, 0.3) + g * dt * dt * n * (n + 1) / 2.0;
    ASSERT_NEAR((solver.particles()[0].x()[0] - expected).norm(), 0.0, 1e-12) << "step " << n;
  }
  const ParticleSet& fluid = solver.particles()[0];
  EXPECT_DOUBLE_EQ(fluid.real(field::density)[0], 1000.0 / M_PI); // V W(0) rho0 = rho0 / pi
  EXPECT_EQ(fluid.real(field::pi)[0], 0.0);
}

TEST(SolverFields, ArraysNamedLikeTheSolvesScratchStayFieldsOfTheirOwn) {
  // The solves share storage between scratch fields that a step uses one after the other. A time directory may
  // bring arrays of those names (a user's own): read as output fields, they keep their own storage, and the run goes
  // on instead of stopping on a name that is already a field, or on storage that is not scratch.
  const std::vector<const char*> names{"cgRhs", "cgQ", field::accelP, "pressureSweepState"};
  for (const std::vector<const char*>& read :
       {std::vector<const char*>{"cgRhs", "cgQ"}, std::vector<const char*>{field::accelP, "pressureSweepState"}}) {
    ParticleSystem ps = fluidBlob(sampleBox(Vec3::Zero(), Vec3::Constant(0.08), kR), Vec3(0.0, -1.0, 0.0));
    for (const char* name : read) ps[0].addVec3(name, Output);
    Solver solver(std::move(ps), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), RunState{});
    solver.step(1e-3);
    const ParticleSet& fluid = solver.particles()[0];
    for (std::size_t a = 0; a < names.size(); ++a)
      for (std::size_t b = a + 1; b < names.size(); ++b)
        EXPECT_NE(&fluid.vec3(names[a]), &fluid.vec3(names[b]))
            << names[a] << " and " << names[b] << " read: " << read[0];
  }
}

TEST(PressureSolve, CompressedBlobExpandsConservingMomentum) {
  // A blob at 0.9 x the lattice spacing is compressed; pressure pushes it apart with equal and opposite
  // pair forces (METHOD.md §6.7): total momentum stays zero, pi >= 0, the density error drops.
  std::vector<Vec3> points;
  for (const Vec3& p : sampleBox(Vec3::Zero(), Vec3::Constant(0.16), kR)) points.push_back(0.9 * p);
  FluidProperties fluid;
  fluid.gravity.setZero();
  SolverSettings settings;
  settings.pressure.maxIterations = 500;
  Solver solver(fluidBlob(points), fluid, {}, settings, fixedStep(1e-3), RunState{});
  solver.step(1e-3);
  const ParticleSet& set = solver.particles()[0];
  EXPECT_TRUE(solver.lastStep().pressure.converged);
  double scale = 0.0;
  for (const Vec3& v : set.v()) scale += set.mass * v.norm();
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(momentum(set).norm(), 1e-12 * scale);
  for (double pi : set.real(field::pi)) EXPECT_GE(pi, 0.0);
  // The outermost particles move outwards.
  const Vec3 centre = Vec3::Constant(0.9 * 0.08);
  const std::size_t corner = 0; // sampleBox starts at the min corner
  EXPECT_GT((set.x()[corner] - centre).norm(), (points[corner] - centre).norm());
}

class ViscosityOperator : public ::testing::Test {
protected:
  void SetUp() override {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.2 * kR, 0.2 * kR), speed(-1.0, 1.0);
    std::vector<Vec3> points = sampleBox(Vec3::Zero(), Vec3::Constant(0.1), kR);
    for (Vec3& p : points) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
    ParticleSystem ps = fluidBlob(points);
    for (Vec3& v : ps[0].v()) v = Vec3(speed(rng), speed(rng), speed(rng));
    fluid_.gravity.setZero();
    fluid_.viscosity = 5.0;
    settings_.implicit.tolerance = 1e-10;
    settings_.implicit.maxIterations = 500;
    solver_ = std::make_unique<Solver>(std::move(ps), fluid_, std::vector<PorousMaterial>{}, settings_, fixedStep(1e-3), RunState{});
  }
  FluidProperties fluid_;
  SolverSettings settings_;
  std::unique_ptr<Solver> solver_;
};

TEST_F(ViscosityOperator, ConservesMomentumAndDissipatesEnergy) {
  const ParticleSet& set = solver_->particles()[0];
  const Vec3 before = momentum(set);
  double energyBefore = 0.0, scale = 0.0;
  for (const Vec3& v : set.v()) energyBefore += 0.5 * set.mass * v.squaredNorm(), scale += set.mass * v.norm();
  solver_->step(1e-3);
  EXPECT_GT(solver_->lastStep().implicit.iterations, 0);
  EXPECT_TRUE(solver_->lastStep().implicit.converged);
  // Pair forces are equal and opposite (Eq. 18): momentum changes by the CG residual only.
  EXPECT_LT((momentum(set) - before).norm(), 1e-8 * scale);
  double energyAfter = 0.0;
  for (const Vec3& v : set.v()) energyAfter += 0.5 * set.mass * v.squaredNorm();
  EXPECT_LT(energyAfter, energyBefore);
}

TEST(Viscosity, RigidTranslationFeelsNoForce) {
  FluidProperties fluid;
  fluid.gravity.setZero();
  fluid.viscosity = 50.0;
  const Vec3 u(0.3, -0.2, 0.1);
  Solver solver(fluidBlob(sampleBox(Vec3::Zero(), Vec3::Constant(0.08), kR), u), fluid, {}, SolverSettings{},
                fixedStep(1e-3), RunState{});
  solver.step(1e-3);
  for (const Vec3& v : solver.particles()[0].v()) EXPECT_LT((v - u).norm(), 1e-12);
}

} // namespace
} // namespace poro
