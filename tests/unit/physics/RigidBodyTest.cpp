// Rigid bodies (physics/RigidBody.hpp, RigidBodyForces.hpp): mass and inertia from the sampled particles, the
// Newton-Euler integration and its constraints, the force and torque fluid pressure exerts, input checks.

#include "physics/RigidBody.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "geometry/LatticeSampling.hpp"
#include "geometry/ShapeSampling.hpp"
#include "geometry/Sphere.hpp"
#include "physics/FieldNames.hpp"
#include "physics/RigidBodyForces.hpp"
#include "physics/Solver.hpp"
#include "sph/BoundaryVolume.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace poro {
namespace {

constexpr const char* kFile = "system/particleDict";

RigidBody::Spec parse(const std::string& text) {
  return RigidBody::read(Dictionary::parse("name: block\nphase: rigid\n" + text, kFile), 3);
}

std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

RigidBody::Spec withDensity(double density) {
  RigidBody::Spec spec;
  spec.name = "block";
  spec.density = density;
  return spec;
}

TEST(RigidBody, SampledBoxHasTheAnalyticMassCentreAndInertia) {
  // A box filled by the lattice: N (2r)^3 is its volume, and particles as cubes of side 2r make the inertia exact.
  const double r = 0.01, rho = 500.0;
  const Vec3 lo(0.1, 0.2, 0.3), hi(0.3, 0.26, 0.34); // 10 x 3 x 2 particles
  const RigidBody body(withDensity(rho), sampleBox(lo, hi, r), r);
  const Vec3 size = hi - lo;
  const double mass = rho * size.prod();
  EXPECT_NEAR(body.mass(), mass, 1e-12 * mass);
  EXPECT_LE((body.restCentre() - 0.5 * (lo + hi)).norm(), 1e-15);
  const Mat3 I = body.bodyInertia();
  const double a = size.x(), b = size.y(), c = size.z();
  const Vec3 expected = mass / 12.0 * Vec3(b * b + c * c, a * a + c * c, a * a + b * b);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(I(d, d), expected[d], 1e-12 * expected.maxCoeff()) << d;
  EXPECT_LE((I - Mat3(I.diagonal().asDiagonal())).norm(), 1e-12 * expected.maxCoeff());
}

TEST(RigidBody, SampledSphereInertiaIsTheAnalyticOneWithinTheLatticeError) {
  // With `mass` given, I = 2/5 M R^2 up to the staircase of the lattice. At R = 10 r (5 spacings) the lattice
  // holds 552 points, 5.4 % more volume than the sphere, so I is 5.2 % above 2/5 M R^2 (bound 6 %); against the
  // ball of the sampled volume, R_eq = (3 N / 4 pi)^(1/3) 2r, the shape error left is 1.6 % (bound 2 %).
  const double r = 0.01, R = 0.1, mass = 3.0;
  RigidBody::Spec spec;
  spec.mass = mass;
  const RigidBody body(spec, sampleInside(Sphere(Vec3(0.5, 0.5, 0.5), R), r), r);
  EXPECT_NEAR(body.mass(), mass, 1e-15);
  EXPECT_LE((body.restCentre() - Vec3(0.5, 0.5, 0.5)).norm(), 1e-12);
  const double expected = 0.4 * mass * R * R;
  const double n = static_cast<double>(sampleInside(Sphere(Vec3(0.5, 0.5, 0.5), R), r).size());
  const double equalVolume = 0.4 * mass * std::pow(std::cbrt(3.0 * n / (4.0 * M_PI)) * 2.0 * r, 2);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(body.bodyInertia()(d, d), expected, 0.06 * expected) << d;
    EXPECT_NEAR(body.bodyInertia()(d, d), equalVolume, 0.02 * equalVolume) << d;
  }
  EXPECT_LE(std::abs(body.bodyInertia()(0, 1)) + std::abs(body.bodyInertia()(1, 2)), 1e-12 * expected);
}

TEST(RigidBody, FreeRotationConservesAngularMomentumExactlyAndEnergyClosely) {
  // A torque-free asymmetric top spinning mostly about its middle axis (the unstable one: the hardest case).
  const double r = 0.01;
  RigidBody::Spec spec = withDensity(1000.0);
  spec.angularVelocity = Vec3(0.1, 5.0, 0.2);
  const RigidBody spinning(spec, sampleBox(Vec3::Zero(), Vec3(0.2, 0.12, 0.06), r), r);
  RigidBodyState s = spinning.initialState();
  const Vec3 L0 = s.angularMomentum;
  const double E0 = spinning.kineticEnergy(s);
  double worst = 0.0;
  const double dt = 1e-4;
  for (int n = 0; n < 20000; ++n) { // 2 s, about 1.6 turns
    spinning.integrate(s, Vec3::Zero(), Vec3::Zero(), dt);
    worst = std::max(worst, std::abs(spinning.kineticEnergy(s) / E0 - 1.0));
  }
  EXPECT_EQ(s.angularMomentum, L0); // untouched without torque
  EXPECT_LE((s.rotation * s.rotation.transpose() - Mat3::Identity()).norm(), 1e-14);
  // The first-order rotation update lets the energy wander by O(dt): measured 3.7e-4 at dt = 1e-4 s.
  EXPECT_LT(worst, 1e-3) << "energy drift of the first-order rotation update";
  EXPECT_LE((s.centre - spinning.restCentre()).norm(), 0.0);
}

TEST(RigidBody, ConstraintsHoldTranslationAndRotation) {
  const double r = 0.01;
  const auto points = sampleBox(Vec3::Zero(), Vec3(0.1, 0.06, 0.04), r);
  RigidBody::Spec spec = parse("density: 800\nfixedTranslation: [x, z]\nfixedAxis: [0, 0, 2]\n");
  const RigidBody hinge(spec, points, r);
  RigidBodyState s = hinge.initialState();
  const Vec3 force(3.0, -2.0, 1.0), torque(0.4, -0.3, 0.02);
  for (int n = 0; n < 100; ++n) hinge.integrate(s, force, torque, 1e-3);
  EXPECT_EQ(s.velocity.x(), 0.0);
  EXPECT_EQ(s.velocity.z(), 0.0);
  EXPECT_NEAR(s.velocity.y(), -2.0 / hinge.mass() * 0.1, 1e-12);
  EXPECT_EQ(s.angularVelocity.x(), 0.0);
  EXPECT_EQ(s.angularVelocity.y(), 0.0);
  EXPECT_NEAR(s.angularVelocity.z(), 0.02 * 0.1 / hinge.bodyInertia()(2, 2), 1e-12); // L_z / I_zz
  EXPECT_LE((s.rotation * Vec3::UnitZ() - Vec3::UnitZ()).norm(), 1e-15);             // turned about z only

  const RigidBody still(parse("mass: 2\nfixedRotation: true\n"), points, r);
  RigidBodyState t = still.initialState();
  for (int n = 0; n < 10; ++n) still.integrate(t, force, torque, 1e-3);
  EXPECT_EQ(t.rotation, Mat3::Identity());
  EXPECT_NEAR(t.velocity.x(), 3.0 / 2.0 * 0.01, 1e-14);
}

TEST(RigidBody, PoseDrivesParticlesAsAWallPoseAndChordVelocitiesLandOnTheNextPose) {
  const double r = 0.01;
  RigidBody::Spec spec = withDensity(700.0);
  spec.velocity = Vec3(0.1, -0.2, 0.05);
  spec.angularVelocity = Vec3(1.0, 2.0, -3.0);
  const auto points = sampleBox(Vec3::Zero(), Vec3(0.1, 0.06, 0.04), r);
  const RigidBody body(spec, points, r);
  RigidBodyState s = body.initialState();
  s.rotation = rotationOf(Vec3(0.3, -0.2, 0.5));
  s.angularVelocity = body.angularVelocityOf(s);
  const double dt = 1e-3;
  const WallMotion wall({{0.0, Vec3::Zero(), 0.0}}, body.restCentre(), Vec3::UnitZ());
  RigidBodyState next = s;
  body.integrate(next, Vec3::Zero(), Vec3::Zero(), dt); // torque-free: L kept, omega at the start drives the step
  for (const Vec3& X : points) {
    EXPECT_LE((body.place(s, X) - wall.place(body.pose(s), X)).norm(), 1e-15);
    const Vec3 landed = body.place(s, X) + dt * body.chordVelocity(s, X, dt);
    EXPECT_LE((landed - body.place(next, X)).norm(), 1e-13);
  }
}

TEST(RigidBody, BadInputNamesFileLineKeyAndWhatWasExpected) {
  EXPECT_NE(errorOf("shape: box\n").find("system/particleDict:1: key 'density'"), std::string::npos)
      << errorOf("shape: box\n");
  EXPECT_NE(errorOf("density: 500\nmass: 2\n").find("mass"), std::string::npos);
  EXPECT_NE(errorOf("mass: 0\n").find("system/particleDict:3: key 'mass'"), std::string::npos) << errorOf("mass: 0\n");
  EXPECT_NE(errorOf("density: -5\n").find("density"), std::string::npos);
  EXPECT_NE(errorOf("density: 5\nfixedTranslation: [x, w]\n").find("fixedTranslation"), std::string::npos);
  EXPECT_NE(errorOf("density: 5\nfixedAxis: [0, 0, 0]\n").find("system/particleDict:4: key 'fixedAxis'"),
            std::string::npos)
      << errorOf("density: 5\nfixedAxis: [0, 0, 0]\n");
  EXPECT_NE(errorOf("density: 5\nfixedRotation: true\nfixedAxis: [0, 0, 1]\n").find("fixedAxis"), std::string::npos);
  EXPECT_EQ(errorOf("density: 5\nfixedTranslation: [y]\nfixedAxis: [1, 0, 0]\n"), "no error");
  EXPECT_NE(errorOf("density: 5\nreleaseTime: -1\n").find("system/particleDict:4: key 'releaseTime'"),
            std::string::npos)
      << errorOf("density: 5\nreleaseTime: -1\n");
  EXPECT_EQ(parse("density: 5\nreleaseTime: 1.5\n").releaseTime, 1.5);
}

TEST(RigidBody, TemplateDictionaryRigidRegionIsValid) {
  // etc/caseDicts/particleDict documents a rigid region with every key.
  const Dictionary dict = Dictionary::read(std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/particleDict");
  int rigid = 0;
  for (const Dictionary& region : dict.getDictList("regions"))
    if (region.getString("phase") == "rigid") {
      const RigidBody::Spec spec = RigidBody::read(region, 0);
      EXPECT_GT(spec.density, 0.0);
      EXPECT_TRUE(spec.fixedTranslation[2]);
      ASSERT_TRUE(spec.fixedAxis.has_value());
      ++rigid;
    }
  EXPECT_EQ(rigid, 1);
}

// --- forces from the fluid ---------------------------------------------------------------------------------

constexpr double kR = 0.01;

void append(ParticleSet& set, const std::vector<Vec3>& points, std::int64_t object, std::int64_t& id) {
  const std::size_t first = set.size();
  set.resize(first + points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    set.x()[first + i] = points[i];
    set.integer(field::objectId)[first + i] = object;
    set.integer(field::id)[first + i] = id++;
  }
}

/// A cube of boundary particles (object 1) inside a block of fluid on the same lattice, with walls of object 0
/// far away (a second body, which must get nothing).
ParticleSystem cubeInFluid() {
  ParticleSystem ps(kR);
  std::int64_t id = 0;
  const Vec3 lo(0.06, 0.06, 0.06), hi(0.14, 0.14, 0.14);
  std::vector<Vec3> fluid;
  for (const Vec3& p : sampleBox(Vec3::Zero(), Vec3(0.2, 0.2, 0.2), kR))
    if (!((p.array() > lo.array()).all() && (p.array() < hi.array()).all())) fluid.push_back(p);
  append(ps.add("fluid", SetKind::Fluid), fluid, 0, id);
  ParticleSet& walls = ps.add("boundary", SetKind::Boundary);
  append(walls, sampleBox(lo, hi, kR), 1, id);
  append(walls, sampleBox(Vec3(0.5, 0.5, 0.5), Vec3(0.54, 0.54, 0.54), kR), 0, id);
  return ps;
}

TimeControl fixedStep(double dt) {
  TimeControl control;
  control.deltaT = dt;
  control.endTime = 10.0;
  control.writeInterval = 10.0;
  return control;
}

TEST(RigidBodyForces, UniformPressureOnAClosedBodyGivesNoForceOrTorque) {
  SolverSettings settings;
  settings.health.leavingDomain = HealthAction::Warn;
  Solver solver(cubeInFluid(), FluidProperties{}, {}, settings, fixedStep(1e-3), RunState{});
  const StepContext ctx = solver.beginStep(1e-3);
  auto& pi = solver.particles()[0].real(field::pi);
  std::fill(pi.begin(), pi.end(), 50.0);
  const Vec3 centre(0.1, 0.1, 0.1);
  const auto w = rigidBodyWrenches(ctx, {1, 0}, {centre, Vec3(0.52, 0.52, 0.52)});
  // The push on one face: m pi sum V_k gradW ~ pressure times area; the sum over the closed cube cancels to
  // round-off of it.
  const ParticleSet& fluid = solver.particles()[0];
  const double face = fluid.mass * 50.0 / fluid.particleVolume * std::pow(0.08, 2); // rho pi A, order of a face
  EXPECT_LT(w[0].force.norm(), 1e-12 * face) << w[0].force.transpose();
  EXPECT_LT(w[0].torque.norm(), 1e-12 * face * 0.04) << w[0].torque.transpose();
  EXPECT_EQ(w[1].force, Vec3::Zero());

  // Pressure on the +x half of the fluid only pushes the cube towards -x, the whole push of that side.
  const auto& x = fluid.x();
  for (std::size_t i = 0; i < pi.size(); ++i) pi[i] = x[i].x() > 0.1 ? 50.0 : 0.0;
  const auto half = rigidBodyWrenches(ctx, {1}, {centre});
  EXPECT_LT(half[0].force.x(), -0.5 * face) << half[0].force.transpose();
  EXPECT_LT(std::abs(half[0].force.y()) + std::abs(half[0].force.z()), 1e-12 * face);
}

TEST(RigidBody, HeldUntilItsReleaseTimeThenFallsFreely) {
  // Far from the fluid nothing but gravity acts: held (wall velocity 0) until 0.05 s, then v = g n dt and the
  // symplectic Euler drop g dt^2 n (n + 1) / 2 after n free steps.
  SolverSettings settings;
  settings.health.leavingDomain = HealthAction::Warn;
  RigidBody::Spec weight = withDensity(2000.0);
  weight.objectId = 0; // the far box of cubeInFluid
  weight.releaseTime = 0.05;
  const double dt = 1e-3;
  Solver solver(cubeInFluid(), FluidProperties{}, {}, settings, fixedStep(dt), RunState{}, {}, {weight});
  const Vec3 start = solver.state().rigidBodies[0].centre;
  for (int n = 1; n <= 50; ++n) {
    solver.step(dt);
    EXPECT_EQ(solver.state().rigidBodies[0].centre, start) << "step " << n;
  }
  const ParticleSet& walls = solver.particles()[1];
  for (std::size_t k = 0; k < walls.size(); ++k) {
    if (walls.integer(field::objectId)[k] == 0) {
      EXPECT_EQ(walls.v()[k], Vec3::Zero());
    }
  }
  for (int n = 1; n <= 30; ++n) solver.step(dt);
  const RigidBodyState& s = solver.state().rigidBodies[0];
  EXPECT_NEAR(s.velocity.y(), -9.81 * 30 * dt, 1e-12);
  EXPECT_NEAR(s.centre.y(), start.y() - 9.81 * dt * dt * 30 * 31 / 2.0, 1e-12);
}

/// cubeInFluid's far box (object 0) as a body shot down at 100 m/s, past the fluid, out of a domain whose floor is
/// at y = -0.5: its centre (0.52 at the start) is above it after 10 steps of 1 ms and below it from step 11 on.
Solver bodyShotOutOfTheDomain(HealthAction action, int steps) {
  SolverSettings settings;
  settings.health.startDensity = 2.0; // cubeInFluid's fluid touches the cube
  settings.health.leavingDomain = action;
  settings.health.domain = Domain{Vec3(-1.0, -0.5, -1.0), Vec3(1.0, 1.0, 1.0)};
  RigidBody::Spec body = withDensity(2000.0);
  body.objectId = 0;
  body.velocity = Vec3(0.0, -100.0, 0.0);
  TimeControl control = fixedStep(1e-3);
  control.endTime = steps * 1e-3;
  return Solver(cubeInFluid(), FluidProperties{}, {}, settings, control, RunState{}, {}, {body});
}

TEST(RigidBody, ABodyLeavingTheDomainStopsTheRunAsItCannotBeDeleted) {
  Solver solver = bodyShotOutOfTheDomain(HealthAction::Remove, 15);
  try {
    solver.run([](const Solver&) {});
    ADD_FAILURE() << "the run went on with its body outside the domain";
  } catch (const NumericalError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("step 11 (time 0.011 s): rigid body 'block' left the domain"), std::string::npos) << message;
    EXPECT_NE(message.find("health.leavingDomain warn in system/solverDict keeps it"), std::string::npos) << message;
  }
  EXPECT_EQ(solver.state().step, 11);
}

TEST(RigidBody, ABodyLeavingTheDomainIsWarnedOfOnceAndCountedWhenKept) {
  Solver solver = bodyShotOutOfTheDomain(HealthAction::Warn, 15);
  testing::internal::CaptureStderr();
  solver.run([](const Solver&) {});
  const std::string log = testing::internal::GetCapturedStderr();
  EXPECT_EQ(solver.state().step, 15);
  EXPECT_NE(log.find("step 11 (time 0.011 s): rigid body 'block' left the domain"), std::string::npos) << log;
  const std::string left = "rigid body 'block' left the domain";
  EXPECT_EQ(log.find(left, log.find(left) + 1), std::string::npos) << log;          // once
  EXPECT_EQ(solver.warnings().steps(RunWarnings::Kind::RigidBodiesOutsideKept), 5); // steps 11 to 15
  EXPECT_EQ(solver.warnings().particles(RunWarnings::Kind::RigidBodiesOutsideKept), 1u);
}

TEST(RigidBody, ABodyDoesNotMakeTheDefaultDomainWallsDo) {
  // Without static walls there is no default domain: fluid far from the body is not "outside" the body's box. With
  // them, the body's own box does not count: the far body sits outside the cube's domain and stops the run.
  RigidBody::Spec body = withDensity(2000.0);
  body.objectId = 0;
  ParticleSystem bodyAndFluid(kR);
  std::int64_t id = 0;
  append(bodyAndFluid.add("fluid", SetKind::Fluid), sampleBox(Vec3::Zero(), Vec3(0.2, 0.2, 0.2), kR), 0, id);
  append(bodyAndFluid.add("boundary", SetKind::Boundary), sampleBox(Vec3(0.5, 0.5, 0.5), Vec3(0.54, 0.54, 0.54), kR), 0,
         id);
  EXPECT_NO_THROW(Solver(std::move(bodyAndFluid), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), RunState{},
                         {}, {body}));
  TimeControl oneStep = fixedStep(1e-3);
  oneStep.endTime = 1e-3;
  SolverSettings touching;
  touching.health.startDensity = 2.0; // cubeInFluid's fluid touches the cube
  Solver withCube(cubeInFluid(), FluidProperties{}, {}, touching, oneStep, RunState{}, {}, {body});
  EXPECT_THROW(withCube.run([](const Solver&) {}), NumericalError);
}

TEST(RigidBodyForces, WallViscosityPullsTheBodyBackSoMomentumIsConserved) {
  // A cube pushed through still water without gravity: the wall pressure and the wall viscosity are the only
  // forces between them, each with its reaction on the body, so water + cube keep the cube's start momentum to
  // the implicit solve's tolerance. Without the viscous reaction the water gains what the cube never loses.
  SolverSettings settings;
  settings.health.leavingDomain = HealthAction::Warn;
  settings.implicit.tolerance = 1e-12;
  FluidProperties water;
  water.gravity.setZero();
  water.boundaryViscosity = 2.0;
  RigidBody::Spec cube = withDensity(1000.0);
  cube.objectId = 1;
  cube.velocity = Vec3(0.2, 0.05, 0.0);
  Solver solver(cubeInFluid(), water, {}, settings, fixedStep(1e-3), RunState{}, {}, {cube});
  const double M = solver.rigidBodies()[0].mass();
  const Vec3 start = M * cube.velocity;
  const auto waterMomentum = [&] {
    const ParticleSet& fluid = solver.particles()[0];
    Vec3 p = Vec3::Zero();
    for (const Vec3& v : fluid.v()) p += fluid.mass * v;
    return p;
  };
  for (int n = 0; n < 20; ++n) solver.step(1e-3);
  const Vec3 total = waterMomentum() + M * solver.state().rigidBodies[0].velocity;
  EXPECT_LE((total - start).norm(), 1e-9 * start.norm()) << total.transpose() << " against " << start.transpose();
  EXPECT_GT(waterMomentum().norm(), 0.05 * start.norm()) << "the cube must drag water along for the test to bite";
}

TEST(RigidBodyForces, OneParticlesPushHasTheKnownForceAndLeverArm) {
  SolverSettings settings;
  settings.health.leavingDomain = HealthAction::Warn;
  Solver solver(cubeInFluid(), FluidProperties{}, {}, settings, fixedStep(1e-3), RunState{});
  const StepContext ctx = solver.beginStep(1e-3);
  ParticleSet& fluid = solver.particles()[0];
  const ParticleSet& walls = solver.particles()[1];
  auto& pi = fluid.real(field::pi);
  std::fill(pi.begin(), pi.end(), 0.0);
  // The fluid particle next to the middle of the cube's +y face at its +x edge.
  std::size_t a = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i)
    if ((fluid.x()[i] - Vec3(0.13, 0.15, 0.13)).norm() < 1e-9) a = i;
  ASSERT_LT((fluid.x()[a] - Vec3(0.13, 0.15, 0.13)).norm(), 1e-9);
  pi[a] = 7.0;
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  double forceScale = 0.0, torqueScale = 0.0; // the sums of the pushes' sizes: each has the rounding of its s_ak
  const Vec3 centre(0.1, 0.1, 0.1), elsewhere(0.0, 0.3, 0.0);
  for (std::size_t k = 0; k < walls.size(); ++k) {
    if (walls.integer(field::objectId)[k] != 1) continue;
    const Vec3 d = fluid.x()[a] - walls.x()[k];
    if (d.norm() >= 2.0 * kR * 2.0) continue; // H = 4 r
    const Vec3 f = fluid.mass * 7.0 * walls.real(kBoundaryVolumeField)[k] * ctx.kernel.grad(d);
    force += f;
    torque += (walls.x()[k] - elsewhere).cross(f);
    forceScale += f.norm();
    torqueScale += (walls.x()[k] - elsewhere).cross(f).norm();
  }
  const auto w = rigidBodyWrenches(ctx, {1}, {elsewhere});
  // The solver's s_ak are stored in single precision (kPairFactorRounding).
  EXPECT_LE((w[0].force - force).norm(), 2.0 * kPairFactorRounding * forceScale);
  EXPECT_LE((w[0].torque - torque).norm(), 2.0 * kPairFactorRounding * torqueScale);
  EXPECT_LT(force.y(), 0.0); // pushed into the body
  (void)centre;
}

} // namespace
} // namespace poro
