// Solid damping: the viscosity pair form inside one porous object and at walls (METHOD.md §6.5.3).

#include "PorousTestSystems.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace poro {
namespace {

using namespace test;

const char* const kU = "testU";
const char* const kAu = "testAu";
const char* const kW = "testW";
const char* const kAw = "testAw";
constexpr double kDt = 1e-3;

/// Two damped porous objects side by side (no fluid, no walls, no gravity), the operator of a step prepared.
class DampedBodies : public ::testing::Test {
protected:
  void SetUp() override {
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> jitter(-0.2 * kR, 0.2 * kR);
    std::vector<Vec3> left = sampleBox(Vec3::Zero(), Vec3(0.08, 0.08, 0.08), kR);
    std::vector<Vec3> right = sampleBox(Vec3(0.08, 0, 0), Vec3(0.16, 0.08, 0.08), kR);
    for (auto* block : {&left, &right})
      for (Vec3& p : *block) p += Vec3(jitter(rng), jitter(rng), jitter(rng));
    ParticleSystem ps(kR);
    ParticleSet& set = addSet(ps, "foam", SetKind::Porous, left, 0);
    appendObject(set, right, 1);
    PorousMaterial foam = material("foam", 0.6, 2000.0, false);
    foam.dampingViscosity = 20.0;
    solver_ = std::make_unique<Solver>(std::move(ps), weightless(), std::vector<PorousMaterial>{foam}, SolverSettings{},
                                       fixedStep(kDt), RunState{});
    ctx_ = std::make_unique<StepContext>(solver_->beginStep(kDt));
    for (const char* name : {kU, kAu, kW, kAw}) set_().addVec3(name);
    solver_->implicitSolver().prepare(*ctx_);
  }
  ParticleSet& set_() { return solver_->particles()[0]; }
  linalg::BlockVector view(const char* name) const { return ImplicitSolver::view(*ctx_, name); }
  /// The damping force F(u) per particle for the velocity field u(x, object).
  template <class Field> std::vector<Vec3> forces(const Field& velocity) {
    const auto u = view(kU), au = view(kAu);
    const auto& x = set_().x();
    const auto& object = set_().integer(field::objectId);
    for (std::size_t i = 0; i < u[0].size; ++i) u[0].data[i] = velocity(x[i], object[i]);
    solver_->implicitSolver().apply(u, au);
    std::vector<Vec3> f(u[0].size);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = -(au[0].data[i] - set_().mass * u[0].data[i]) / kDt;
    return f;
  }
  static double largest(const std::vector<Vec3>& f) {
    double m = 0.0;
    for (const Vec3& v : f) m = std::max(m, v.norm());
    return m;
  }
  std::unique_ptr<Solver> solver_;
  std::unique_ptr<StepContext> ctx_;
};

TEST_F(DampedBodies, ShearInsideABodyIsDampedAndForcesCancel) {
  const auto f = forces([](const Vec3& x, std::int64_t) { return Vec3(0.0, 10.0 * x.x(), 0.0); });
  Vec3 total = Vec3::Zero();
  double scale = 0.0;
  for (const Vec3& v : f) {
    total += v;
    scale += v.norm();
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(total.norm(), 1e-12 * scale);
}

TEST_F(DampedBodies, RigidMotionOfEachBodyIsNotDamped) {
  // Each object translates and spins on its own: no damping inside, none across the objects either.
  const double shear = largest(forces([](const Vec3& x, std::int64_t) { return Vec3(0.0, 10.0 * x.x(), 0.0); }));
  const Vec3 omega(0.3, -1.0, 2.0);
  const auto f = forces([&](const Vec3& x, std::int64_t object) {
    return object == 0 ? Vec3(omega.cross(x) + Vec3(1, 0, 0)) : Vec3(-2.0 * omega.cross(x) - Vec3(0, 3, 0));
  });
  EXPECT_LT(largest(f), 1e-12 * shear * 100.0);
}

TEST_F(DampedBodies, OperatorIsSymmetricWithExactDiagonal) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  for (const char* name : {kU, kW})
    for (auto& part : view(name))
      for (std::size_t i = 0; i < part.size; ++i) part.data[i] = Vec3(value(rng), value(rng), value(rng));
  const ImplicitSolver& op = solver_->implicitSolver();
  op.apply(view(kU), view(kAu));
  op.apply(view(kW), view(kAw));
  const double wAu = linalg::dot(view(kW), view(kAu)), awU = linalg::dot(view(kAw), view(kU));
  EXPECT_NEAR(wAu, awU, 1e-12 * std::abs(wAu));

  set_().addMat3("testD");
  linalg::BlockDiagonal d{{set_().mat3("testD").data(), set_().size()}};
  op.diagonal(d);
  const auto u = view(kU), au = view(kAu);
  for (std::size_t i = 0; i < u[0].size; i += 11)
    for (int c = 0; c < 3; ++c) {
      for (std::size_t j = 0; j < u[0].size; ++j) u[0].data[j].setZero();
      u[0].data[i][c] = 1.0;
      op.apply(u, au);
      EXPECT_LT((au[0].data[i] - d[0].data[i].col(c)).norm(), 1e-12 * au[0].data[i].norm());
      EXPECT_GT(d[0].data[i](c, c), set_().mass) << "damping adds to the diagonal";
    }
}

} // namespace
} // namespace poro
