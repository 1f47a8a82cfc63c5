// XSPH smoothing of the fluid velocities (XsphSmoothing.hpp): what it does to momentum and kinetic energy.

#include "physics/XsphSmoothing.hpp"
#include "PorousTestSystems.hpp"

#include <gtest/gtest.h>

#include <random>

namespace poro {
namespace {

using namespace test;

constexpr double kDt = 1e-3;

/// A jittered fluid blob (no walls, no gravity) with random velocities, densities of a step computed.
class XsphBlob : public ::testing::Test {
protected:
  void SetUp() override {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> jitter(-0.3 * kR, 0.3 * kR), speed(-0.5, 0.5);
    std::vector<Vec3> x = sampleBox(Vec3::Zero(), Vec3(0.12, 0.1, 0.08), kR);
    for (Vec3& p : x) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
    ParticleSystem ps(kR);
    ParticleSet& set = addSet(ps, "fluid", SetKind::Fluid, x, 0);
    for (Vec3& v : set.v()) v = Vec3(speed(rng), speed(rng), speed(rng));
    solver_ = std::make_unique<Solver>(std::move(ps), weightless(), std::vector<PorousMaterial>{}, SolverSettings{},
                                       fixedStep(kDt), RunState{});
    ctx_ = std::make_unique<StepContext>(solver_->beginStep(kDt));
  }
  std::vector<Vec3>& v() { return solver_->particles()[0].v(); }
  Vec3 momentum() {
    Vec3 p = Vec3::Zero();
    for (const Vec3& vi : v()) p += vi;
    return solver_->particles()[0].mass * p;
  }
  double kineticEnergy() {
    double e = 0.0;
    for (const Vec3& vi : v()) e += 0.5 * solver_->particles()[0].mass * vi.squaredNorm();
    return e;
  }
  double momentumScale() {
    double s = 0.0;
    for (const Vec3& vi : v()) s += solver_->particles()[0].mass * vi.norm();
    return s;
  }
  std::unique_ptr<Solver> solver_;
  std::unique_ptr<StepContext> ctx_;
};

TEST_F(XsphBlob, ConservesMomentum) {
  const Vec3 before = momentum();
  const double scale = momentumScale();
  smoothFluidVelocities(*ctx_, 0.1);
  EXPECT_LT((momentum() - before).norm(), 1e-12 * scale);
}

TEST_F(XsphBlob, KineticEnergyFallsForEveryAdmittedStrength) {
  // One Jacobi sweep of a graph Laplacian: the energy never grows for eps up to 1 (the key's range).
  for (const double eps : {0.01, 0.1, 0.5, 1.0}) {
    const double before = kineticEnergy();
    smoothFluidVelocities(*ctx_, eps);
    EXPECT_LT(kineticEnergy(), before) << "eps " << eps;
  }
}

TEST_F(XsphBlob, LeavesUniformMotionAlone) {
  for (Vec3& vi : v()) vi = Vec3(0.3, -1.0, 2.0);
  smoothFluidVelocities(*ctx_, 0.5);
  for (const Vec3& vi : v()) EXPECT_LT((vi - Vec3(0.3, -1.0, 2.0)).norm(), 1e-14);
}

TEST_F(XsphBlob, ZeroStrengthChangesNothing) {
  const std::vector<Vec3> before = v();
  smoothFluidVelocities(*ctx_, 0.0);
  EXPECT_EQ(v(), before);
}

} // namespace
} // namespace poro
