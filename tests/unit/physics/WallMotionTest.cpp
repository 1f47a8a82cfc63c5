// Prescribed wall motion (physics/WallMotion.hpp, METHOD.md §6.2): the displacement law, its input checks, and
// walls moved by the Solver exactly as prescribed, pushing the fluid in front of them.

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "geometry/LatticeSampling.hpp"
#include "physics/FieldNames.hpp"
#include "physics/Solver.hpp"
#include "physics/WallMotion.hpp"
#include "sph/BoundaryVolume.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace poro {
namespace {

constexpr const char* kFile = "system/particleDict";

WallMotion parse(const std::string& text) { return WallMotion::read(Dictionary::parse(text, kFile)); }

std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

void expectVec(const Vec3& actual, const Vec3& expected, double tolerance = 1e-15) {
  EXPECT_LE((actual - expected).norm(), tolerance) << actual.transpose() << " vs " << expected.transpose();
}

TEST(WallMotion, VelocityFormRestsMovesAndStops) {
  const WallMotion m = parse("velocity: [0, -0.2, 0]\nstartTime: 1\nendTime: 3\n");
  expectVec(m.displacement(0.0), Vec3::Zero());
  expectVec(m.displacement(1.0), Vec3::Zero());
  expectVec(m.displacement(2.0), Vec3(0, -0.2, 0));
  expectVec(m.displacement(3.0), Vec3(0, -0.4, 0));
  expectVec(m.displacement(10.0), Vec3(0, -0.4, 0));
  EXPECT_DOUBLE_EQ(m.maxSpeed(), 0.2);
  // A step across the start moves the wall for the part of the step after it: mean velocity -0.2 * 0.75.
  expectVec(m.meanVelocity(0.999, 0.004), Vec3(0, -0.15, 0), 1e-12);
  expectVec(m.meanVelocity(5.0, 0.001), Vec3::Zero());
}

TEST(WallMotion, VelocityWithoutEndTimeKeepsMoving) {
  const WallMotion m = parse("velocity: [0.5, 0, 0]\n");
  expectVec(m.displacement(4.0), Vec3(2.0, 0, 0));
  expectVec(m.meanVelocity(7.0, 0.01), Vec3(0.5, 0, 0), 1e-12);
}

TEST(WallMotion, TableIsInterpolatedLinearlyAndHeldAfterItsEnd) {
  const WallMotion m = parse("table:\n"
                             "  - {time: 1, displacement: [0, 0, 0]}\n"
                             "  - {time: 2, displacement: [0, -0.1, 0]}\n"
                             "  - {time: 4, displacement: [0, 0.1, 0.2]}\n");
  expectVec(m.displacement(0.5), Vec3::Zero());
  expectVec(m.displacement(1.5), Vec3(0, -0.05, 0));
  expectVec(m.displacement(3.0), Vec3(0, 0.0, 0.1), 1e-15);
  expectVec(m.displacement(9.0), Vec3(0, 0.1, 0.2));
  EXPECT_DOUBLE_EQ(m.maxSpeed(), std::sqrt(0.2 * 0.2 + 0.2 * 0.2) / 2.0);
  // Mean velocity over a step carries the wall exactly from d(t) to d(t + dt), also across a corner.
  const double t = 1.9, dt = 0.3;
  expectVec(m.displacement(t) + dt * m.meanVelocity(t, dt), m.displacement(t + dt), 1e-15);
}

TEST(WallMotion, RotationCarriesAPointAtDistanceRAlongItsCircle) {
  // About the z axis through (1, 2, 0) at 2 rad/s: a point sampled R = 0.3 m from the axis (and 0.5 m along
  // it) is at angle 2 t from where it started, at the same height; its speed is omega R.
  const WallMotion m = parse("angularVelocity: [0, 0, 2]\norigin: [1, 2, 0]\n");
  ASSERT_TRUE(m.rotates());
  const Vec3 c(1, 2, 0), X = c + Vec3(0.3, 0, 0.5);
  EXPECT_DOUBLE_EQ(m.distanceFromAxis(X), 0.3);
  for (const double t : {0.0, 0.25, 0.7, 3.0}) {
    const double theta = 2.0 * t;
    EXPECT_DOUBLE_EQ(m.angle(t), theta);
    expectVec(m.position(X, t), c + Vec3(0.3 * std::cos(theta), 0.3 * std::sin(theta), 0.5), 1e-15);
  }
  // A quarter turn (t = pi / 4 s) takes the point from +x to +y of the axis (right-handed).
  expectVec(m.position(X, std::atan(1.0)), c + Vec3(0, 0.3, 0.5), 1e-15);
  EXPECT_DOUBLE_EQ(m.maxSpeed(0.3), 2.0 * 0.3);
  // The step velocity tends to omega x r for short steps: speed omega R, tangent to the circle.
  const double t = 0.7, dt = 1e-6;
  const Vec3 v = m.meanVelocity(m.pose(t), m.pose(t + dt), X, dt);
  const Vec3 r = m.position(X, t) - c;
  expectVec(v, Vec3(0, 0, 2).cross(Vec3(r.x(), r.y(), 0)), 1e-6);
  EXPECT_NEAR(v.norm(), 0.6, 1e-9);
}

TEST(WallMotion, AnyAxisTurnsRightHanded) {
  // 120 degrees about (1, 1, 1) through the origin cycles the coordinate axes: x -> y -> z -> x.
  const WallMotion m(std::vector<WallMotion::Point>{{0.0, Vec3::Zero(), 0.0}, {1.0, Vec3::Zero(), 2.0 * M_PI / 3.0}},
                     Vec3::Zero(), Vec3(2, 2, 2));
  expectVec(m.position(Vec3(1, 0, 0), 1.0), Vec3(0, 1, 0), 1e-15);
  expectVec(m.position(Vec3(0, 1, 0), 1.0), Vec3(0, 0, 1), 1e-15);
  expectVec(m.position(Vec3(0, 0, 3), 5.0), Vec3(3, 0, 0), 1e-14);
  EXPECT_NEAR(m.distanceFromAxis(Vec3(1, 1, 1)), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(m.distanceFromAxis(Vec3(1, -1, 0)), std::sqrt(2.0));
}

TEST(WallMotion, RotationTableIsInterpolatedLinearlyAndHeldAfterItsEnd) {
  const WallMotion m = parse("axis: [0, 3, 0]\n" // any length: only the direction counts
                             "origin: [0.5, 0, 0.5]\n"
                             "table:\n"
                             "  - {time: 1, angle: 0}\n"
                             "  - {time: 2, angle: 1.5}\n"
                             "  - {time: 4, angle: -0.5}\n");
  EXPECT_DOUBLE_EQ(m.angle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(m.angle(1.5), 0.75);
  EXPECT_DOUBLE_EQ(m.angle(3.0), 0.5);
  EXPECT_DOUBLE_EQ(m.angle(9.0), -0.5);
  expectVec(m.displacement(3.0), Vec3::Zero());
  // About +y: a point at +x of the axis goes towards -z.
  const Vec3 X(0.7, 0.1, 0.5);
  expectVec(m.position(X, 3.0), Vec3(0.5 + 0.2 * std::cos(0.5), 0.1, 0.5 - 0.2 * std::sin(0.5)), 1e-15);
  EXPECT_DOUBLE_EQ(m.maxSpeed(0.2), 1.5 * 0.2);
  EXPECT_DOUBLE_EQ(m.maxSpeed(0.2, 2.5, 3.0), 1.0 * 0.2); // only the second piece
  EXPECT_DOUBLE_EQ(m.maxSpeed(0.2, 5.0, 6.0), 0.0);       // held after the end
}

TEST(WallMotion, RotationAndTranslationTogetherCarryTheAxisAlong) {
  // x(t) = c0 + v t + R(omega t) (X - c0): the axis moves with the translation, the body turns about it.
  const WallMotion m = parse("velocity: [0.1, 0, 0]\nangularVelocity: [0, 0, -1]\norigin: [0, 0, 0]\n"
                             "startTime: 1\nendTime: 3\n");
  const Vec3 X(0, 0.2, 0);
  expectVec(m.position(X, 0.5), X);
  const double theta = -1.0; // at t = 2: one second of motion
  expectVec(m.position(X, 2.0), Vec3(0.1 - 0.2 * std::sin(theta), 0.2 * std::cos(theta), 0), 1e-15);
  expectVec(m.position(X, 7.0), Vec3(0.2 - 0.2 * std::sin(-2.0), 0.2 * std::cos(-2.0), 0), 1e-15);
  EXPECT_DOUBLE_EQ(m.maxSpeed(0.2), 0.1 + 0.2);
  // Within the motion the speed of the point is |v + omega x r| (here v and omega x r are parallel at t = 1).
  const double dt = 1e-7;
  EXPECT_NEAR(m.meanVelocity(m.pose(1.0), m.pose(1.0 + dt), X, dt).norm(), 0.3, 1e-6);
}

TEST(WallMotion, StepVelocityCarriesEveryWallPointToItsNextPosition) {
  // The chord velocity: x(t) + dt v = x(t + dt) for every point, with large steps, across startTime and across a
  // corner of a table that also translates; omega x r would miss by |omega|^2 r dt^2 / 2.
  const WallMotion spin = parse("angularVelocity: [0, 6.28, 0]\norigin: [0.2, 0, 0.2]\nstartTime: 0.1\n");
  const WallMotion table = parse("axis: [1, 0, 1]\norigin: [0, 1, 0]\ntable:\n"
                                 "  - {time: 0, angle: 0, displacement: [0, 0, 0]}\n"
                                 "  - {time: 0.5, angle: 2, displacement: [0, -0.1, 0]}\n"
                                 "  - {time: 1, angle: 1, displacement: [0.3, 0, 0]}\n");
  for (const WallMotion* m : {&spin, &table})
    for (const double t : {0.05, 0.08, 0.45, 0.9})
      for (const Vec3& X : {Vec3(0.5, 0.1, 0.2), Vec3(0.2, 0.4, -0.3)}) {
        const double dt = 0.04;
        const Vec3 v = m->meanVelocity(m->pose(t), m->pose(t + dt), X, dt);
        expectVec(m->position(X, t) + dt * v, m->position(X, t + dt), 1e-15);
        EXPECT_LE(v.norm(), m->maxSpeed(std::max(m->distanceFromAxis(X), 0.0)) * (1.0 + 1e-12));
      }
  // A translation alone keeps the one velocity of the whole wall.
  const WallMotion slide = parse("velocity: [0, -0.2, 0]\nstartTime: 1\nendTime: 3\n");
  expectVec(slide.meanVelocity(slide.pose(0.999), slide.pose(1.003), Vec3(5, 6, 7), 0.004),
            slide.meanVelocity(0.999, 0.004));
}

TEST(WallMotion, TemplateDictionaryMotionsAreValid) {
  // The two forms as etc/caseDicts/particleDict documents them, translating and turning.
  const Dictionary dict = Dictionary::read(std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/particleDict");
  int motions = 0;
  for (const Dictionary& region : dict.getDictList("regions"))
    if (const auto motion = region.optionalSubDict("motion")) {
      const WallMotion m = WallMotion::read(*motion);
      EXPECT_GT(m.maxSpeed(1.0), 0.0);
      motions += m.rotates() ? 10 : 1;
    }
  EXPECT_EQ(motions, 22);
}

TEST(WallMotion, BadInputNamesFileLineAndWhatWasExpected) {
  EXPECT_NE(errorOf("startTime: 1\n").find("expected velocity"), std::string::npos) << errorOf("startTime: 1\n");
  const std::string both = errorOf("velocity: [0, 1, 0]\ntable:\n  - {time: 0, displacement: [0, 0, 0]}\n");
  EXPECT_NE(both.find("not both"), std::string::npos) << both;
  const std::string order = errorOf("velocity: [0, 1, 0]\nstartTime: 2\nendTime: 1\n");
  EXPECT_NE(order.find("system/particleDict:3"), std::string::npos) << order;
  EXPECT_NE(order.find("endTime > startTime"), std::string::npos) << order;
  const std::string times = errorOf("table:\n  - {time: 1, displacement: [0, 0, 0]}\n"
                                    "  - {time: 1, displacement: [0, 1, 0]}\n");
  EXPECT_NE(times.find("system/particleDict:3"), std::string::npos) << times;
  EXPECT_NE(times.find("times increasing"), std::string::npos) << times;
  EXPECT_NE(errorOf("table: []\n").find("at least one"), std::string::npos) << errorOf("table: []\n");
  const std::string unknown = errorOf("velocity: [0, 1, 0]\nendtime: 3\n");
  EXPECT_NE(unknown.find("endTime"), std::string::npos) << unknown; // the "did you mean" hint
  EXPECT_NE(errorOf("velocity: [0, 1]\n").find("system/particleDict:1"), std::string::npos);
}

TEST(WallMotion, BadRotationNamesFileLineKeyAndWhatWasExpected) {
  const auto expectError = [](const std::string& text, const std::string& where, const std::string& what) {
    const std::string e = errorOf(text);
    EXPECT_NE(e.find(where), std::string::npos) << text << "\n-> " << e;
    EXPECT_NE(e.find(what), std::string::npos) << text << "\n-> " << e;
  };
  const std::string table = "table:\n  - {time: 0, angle: 0}\n  - {time: 1, angle: 1}\n";
  expectError("axis: [0, 0, 0]\norigin: [0, 0, 0]\n" + table, "system/particleDict:1: key 'axis'",
              "non-zero vector to rotate about, got [0, 0, 0]");
  expectError("axis: [0, 0, 1]\norigin: [0, 0, 0]\ntable:\n  - {time: 0, angle: 0}\n  - {time: 1, angle: .nan}\n",
              "system/particleDict:5: key 'table[1].angle'", "finite number");
  expectError("axis: [0, 0, 1]\norigin: [0, 0, 0]\ntable:\n  - {time: 0, angle: 0}\n  - {time: 1}\n",
              "system/particleDict:5", "missing required key 'table[1].angle'");
  expectError("axis: [0, 0, 1]\norigin: [0, 0, 0]\ntable:\n  - {time: 1, angle: 0}\n  - {time: 0.5, angle: 1}\n",
              "system/particleDict:5: key 'table[1].time'", "times increasing");
  expectError("axis: [0, 0, 1]\norigin: [0, 0, 0]\ntable:\n  - {time: 0, angle: 0, displacement: [0, 0, 0]}\n"
              "  - {time: 1, angle: 1}\n",
              "system/particleDict:5: key 'table[1].displacement'", "in every row");
  // Forms mixed wrongly.
  expectError("axis: [0, 0, 1]\n" + table, "system/particleDict:1: key 'axis'", "expected origin");
  expectError("origin: [0, 0, 0]\ntable:\n  - {time: 0, displacement: [0, 0, 0]}\n",
              "system/particleDict:1: key 'origin'", "give axis");
  expectError("table:\n  - {time: 0, displacement: [0, 0, 0], angle: 1}\n",
              "system/particleDict:2: key 'table[0].angle'", "needs axis");
  expectError("angularVelocity: [0, 0, 1]\norigin: [0, 0, 0]\n" + table, "key 'angularVelocity'", "not both");
  expectError("angularVelocity: [0, 0, 1]\n", "system/particleDict:1", "missing required key 'origin'");
  expectError("angularVelocity: [0, 0, 1]\norigin: [0, 0, 0]\naxis: [0, 0, 1]\n", "system/particleDict:3: key 'axis'",
              "direction of angularVelocity");
  expectError("velocity: [0, 0, 1]\norigin: [0, 0, 0]\n", "system/particleDict:2: key 'origin'",
              "give angularVelocity");
  expectError("axis: [0, 0, 1]\norigin: [0, 0, 0]\nstartTime: 1\n" + table, "system/particleDict:3: key 'startTime'",
              "velocity form");
  expectError("angularVelocity: [0, 0, .inf]\norigin: [0, 0, 0]\n", "system/particleDict:1", "finite number");
  // Unknown keys, with the hint.
  expectError("angularVelocity: [0, 0, 1]\norigin: [0, 0, 0]\nendtime: 2\n", "system/particleDict:3",
              "did you mean 'endTime'");
  expectError("velocity: [0, 0, 1]\nangularvelocity: [0, 0, 1]\n", "system/particleDict:2",
              "did you mean 'angularVelocity'");
  expectError("axis: [0, 0, 1]\norigin: [0, 0, 0]\ntable:\n  - {time: 0, angle: 0, spin: 1}\n", "system/particleDict:4",
              "unknown key 'table[0].spin'");
  // A zero angular velocity does not turn (and needs no axis).
  EXPECT_FALSE(parse("angularVelocity: [0, 0, 0]\norigin: [0, 0, 0]\n").rotates());
}

constexpr double kR = 0.01;
constexpr double kGap = 0.001; // 0.1 r between fluid and wall lattices, as etc/caseDicts/particleDict advises

void append(ParticleSet& set, const std::vector<Vec3>& points, std::int64_t object, std::int64_t& id) {
  const std::size_t first = set.size();
  set.resize(first + points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    set.x()[first + i] = points[i];
    set.integer(field::objectId)[first + i] = object;
    set.integer(field::id)[first + i] = id++;
  }
}

/// A channel [0, 0.3] x [0, 0.2] x [0, 0.06] (walls: floor, sides and the far end, object 0) holding water
/// 0.08 m deep from x = 0.02 to 0.3, and a piston (object 1) filling the channel's cross-section at x < 0.02.
ParticleSystem pistonChannel() {
  ParticleSystem ps(kR);
  std::int64_t id = 0;
  append(ps.add("fluid", SetKind::Fluid), sampleBox(Vec3(0.02, 0.0, 0.0), Vec3(0.3, 0.08, 0.06), kR), 0, id);
  ParticleSet& walls = ps.add("boundary", SetKind::Boundary);
  const double g = kGap, t = 4 * kR; // two layers
  append(walls, sampleBox(Vec3(-0.2, -t - g, -t - g), Vec3(0.3 + t + g, -g, 0.06 + t + g), kR), 0, id); // floor
  append(walls, sampleBox(Vec3(-0.2, -g, -t - g), Vec3(0.3 + t + g, 0.2, -g), kR), 0, id);              // side
  append(walls, sampleBox(Vec3(-0.2, -g, 0.06 + g), Vec3(0.3 + t + g, 0.2, 0.06 + t + g), kR), 0, id);  // side
  append(walls, sampleBox(Vec3(0.3 + g, -g, -g), Vec3(0.3 + t + g, 0.2, 0.06 + g), kR), 0, id);         // end
  append(walls, sampleBox(Vec3(0.02 - t - g, 0.0, 0.0), Vec3(0.02 - g, 0.2, 0.06), kR), 1, id);          // piston
  return ps;
}

TimeControl fixedStep(double dt) {
  TimeControl control;
  control.deltaT = dt;
  control.endTime = 10.0;
  control.writeInterval = 10.0;
  return control;
}

/// The piston moves at `speed` along +x from t = `from` to `until`.
std::vector<ObjectMotion> pistonMotion(double speed, double until, double from = 0.0) {
  return {{1, "piston", "system/particleDict:9",
           WallMotion({{from, Vec3::Zero()}, {until, Vec3(speed * (until - from), 0.0, 0.0)}})}};
}

TEST(MovingWalls, SolverMovesThePistonExactlyAndLeavesTheChannel) {
  const double dt = 1e-3, u = 0.1;
  Solver solver(pistonChannel(), FluidProperties{}, {}, SolverSettings{}, fixedStep(dt), RunState{},
                pistonMotion(u, 1.0));
  const ParticleSet& walls = solver.particles()[1];
  const std::vector<Vec3> rest = walls.vec3(field::restPosition);
  for (int n = 1; n <= 20; ++n) {
    solver.step(dt);
    const double t = solver.state().time;
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const bool piston = walls.integer(field::objectId)[k] == 1;
      ASSERT_LE((walls.x()[k] - rest[k] - (piston ? Vec3(u * t, 0, 0) : Vec3::Zero())).norm(), 1e-15) << n;
      ASSERT_LE((walls.v()[k] - (piston ? Vec3(u, 0, 0) : Vec3::Zero())).norm(), 1e-12 * u) << n;
    }
  }
}

TEST(MovingWalls, AStepUndoneForANaNWritesTheWallsWhereTheRestoredStateHasThem) {
  // Step 3 ends in NaN: the run undoes it and writes the state of step 2, the piston included (it was written one
  // step ahead of the water).
  const double u = 0.1;
  SolverSettings settings;
  settings.health.startDensity = 1.1; // the channel's edge water starts at 1.031 (its corners have single layers)
  Solver solver(pistonChannel(), FluidProperties{}, {}, settings, fixedStep(1e-3), RunState{}, pistonMotion(u, 1.0));
  solver.injectNaN(3);
  const std::vector<Vec3> rest = solver.particles()[1].vec3(field::restPosition);
  std::vector<Vec3> written;
  long long writtenStep = -1;
  double writtenTime = 0.0;
  try {
    solver.run([&](const Solver& s) {
      writtenStep = s.state().step;
      writtenTime = s.state().time;
      written = s.particles()[1].x();
    });
    ADD_FAILURE() << "the NaN did not stop the run";
  } catch (const NumericalError&) {
  }
  ASSERT_EQ(writtenStep, 2);
  const auto& object = solver.particles()[1].integer(field::objectId);
  for (std::size_t k = 0; k < written.size(); ++k)
    ASSERT_LE((written[k] - rest[k] - (object[k] == 1 ? Vec3(u * writtenTime, 0, 0) : Vec3::Zero())).norm(), 1e-15)
        << k;
}

TEST(MovingWalls, WallOrderAndVolumesDoNotDependOnWhereTheRunStarts) {
  // A restart reads the piston displaced; the Solver sorts and weighs walls at their rest positions, so the
  // order and the Akinci volumes are those of a run from time 0 (bit-exact restarts, METHOD.md §7).
  const double u = 0.1, t = 0.37;
  Solver fromZero(pistonChannel(), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), RunState{},
                  pistonMotion(u, 1.0));
  ParticleSystem later = pistonChannel();
  ParticleSet& walls = later[1];
  walls.addVec3(field::restPosition, Restart) = walls.x();
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (walls.integer(field::objectId)[k] == 1) walls.x()[k] += Vec3(u * t, 0, 0);
  RunState state;
  state.time = t;
  state.step = 370;
  Solver restarted(std::move(later), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), state,
                   pistonMotion(u, 1.0));
  const ParticleSet& a = fromZero.particles()[1];
  const ParticleSet& b = restarted.particles()[1];
  EXPECT_EQ(a.integer(field::id), b.integer(field::id));
  EXPECT_EQ(a.real(kBoundaryVolumeField), b.real(kBoundaryVolumeField));
  for (std::size_t k = 0; k < b.size(); ++k)
    ASSERT_EQ(b.x()[k], a.x()[k] + (b.integer(field::objectId)[k] == 1 ? Vec3(u * t, 0, 0) : Vec3::Zero()));
}

TEST(MovingWalls, PistonRaisesTheWaterLevelByTheVolumeItDisplaces) {
  // The piston shortens the water-filled part of the channel from 0.28 to 0.23 m at 0.1 m/s, slow against
  // the shallow-water wave speed sqrt(g h) = 0.9 m/s, then rests. Incompressible water has to rise from
  // 0.08 to 0.08 * 0.28 / 0.23 m: its mean particle height by half of that, 8.70 mm (measured: 8.12 mm).
  // The tolerance is a fifth of it, a twelfth of a particle layer of 2r, the free surface's resolution.
  const double dt = 1e-3, u = 0.1, stroke = 0.05, settle = 0.3;
  SolverSettings settings;
  settings.pressure.maxIterations = 200;
  Solver solver(pistonChannel(), FluidProperties{}, {}, settings, fixedStep(dt), RunState{},
                pistonMotion(u, settle + stroke / u, settle));
  const auto meanHeight = [&] {
    double sum = 0.0;
    for (const Vec3& x : solver.particles()[0].x()) sum += x.y();
    return sum / static_cast<double>(solver.particles()[0].size());
  };
  // The water settles first (the sampled lattice sits slightly off its hydrostatic rest), then the piston
  // moves from 0.3 to 0.8 s, then the water settles again.
  while (solver.state().time < settle - 0.5 * dt) solver.step(dt);
  const double before = meanHeight();
  double maxDensity = 0.0;
  while (solver.state().time < 2.0 * settle + stroke / u - 0.5 * dt) {
    solver.step(dt);
    maxDensity = std::max(maxDensity, solver.lastStep().maxFluidDensity);
  }
  const ParticleSet& fluid = solver.particles()[0];
  const double face = 0.02 - kGap + stroke; // the piston's wet face at rest
  for (const Vec3& x : fluid.x()) ASSERT_GT(x.x(), face) << "water left behind the piston";
  const double expectedRise = 0.5 * 0.08 * (0.28 / 0.23 - 1.0);
  EXPECT_NEAR(meanHeight() - before, expectedRise, 0.2 * expectedRise);
  // The pressure solve sees the piston's velocity: the water is pushed, not compressed (0.05 % target).
  EXPECT_LT(maxDensity, 1.01);
}

/// A tank [0, 0.3] x [0, 0.15] x [0, 0.3] (floor and four sides, object 0), a little water in one corner, and a
/// paddle (object 1): a plate 0.14 m long, 0.04 m thick, standing from y = 0.02 to 0.12, centred on the vertical
/// axis through (0.15, 0, 0.15), clear of the water and the sides whichever way it turns.
ParticleSystem paddleTank() {
  ParticleSystem ps(kR);
  std::int64_t id = 0;
  append(ps.add("fluid", SetKind::Fluid), sampleBox(Vec3(0, 0, 0), Vec3(0.06, 0.06, 0.06), kR), 0, id);
  ParticleSet& walls = ps.add("boundary", SetKind::Boundary);
  const double g = kGap, t = 4 * kR;
  append(walls, sampleBox(Vec3(-t - g, -t - g, -t - g), Vec3(0.3 + t + g, -g, 0.3 + t + g), kR), 0, id); // floor
  append(walls, sampleBox(Vec3(-t - g, -g, -t - g), Vec3(-g, 0.15, 0.3 + t + g), kR), 0, id);            // xMin
  append(walls, sampleBox(Vec3(0.3 + g, -g, -t - g), Vec3(0.3 + t + g, 0.15, 0.3 + t + g), kR), 0, id);  // xMax
  append(walls, sampleBox(Vec3(-g, -g, -t - g), Vec3(0.3 + g, 0.15, -g), kR), 0, id);                    // zMin
  append(walls, sampleBox(Vec3(-g, -g, 0.3 + g), Vec3(0.3 + g, 0.15, 0.3 + t + g), kR), 0, id);          // zMax
  append(walls, sampleBox(Vec3(0.08, 0.02, 0.13), Vec3(0.22, 0.12, 0.17), kR), 1, id);                   // paddle
  return ps;
}

const Vec3 kPaddleAxisPoint(0.15, 0.0, 0.15);

std::vector<ObjectMotion> paddleMotion(double omega, double from = 0.0) {
  std::vector<WallMotion::Point> table{{from, Vec3::Zero(), 0.0}};
  return {{1, "paddle", "system/particleDict:9",
           WallMotion(std::move(table), kPaddleAxisPoint, Vec3::UnitY(), Vec3::Zero(), omega)}};
}

TEST(MovingWalls, SolverTurnsThePaddleRigidlyAndCarriesItWithItsStepVelocity) {
  const double dt = 1e-3, omega = 3.0;
  Solver solver(paddleTank(), FluidProperties{}, {}, SolverSettings{}, fixedStep(dt), RunState{}, paddleMotion(omega));
  const ParticleSet& walls = solver.particles()[1];
  const std::vector<Vec3> rest = walls.vec3(field::restPosition);
  const std::vector<double> volumes = walls.real(kBoundaryVolumeField);
  std::vector<Vec3> x = walls.x(), v = walls.v();
  for (int n = 1; n <= 20; ++n) {
    solver.step(dt);
    const double t = solver.state().time;
    const Mat3 R = Eigen::AngleAxisd(omega * t, Vec3::UnitY()).toRotationMatrix();
    for (std::size_t k = 0; k < walls.size(); ++k) {
      const bool paddle = walls.integer(field::objectId)[k] == 1;
      const Vec3 expected = paddle ? Vec3(kPaddleAxisPoint + R * (rest[k] - kPaddleAxisPoint)) : rest[k];
      ASSERT_LE((walls.x()[k] - expected).norm(), 1e-15) << n;
      // The velocity of the step just done carried the wall exactly to where it is now.
      ASSERT_LE((x[k] + dt * v[k] - walls.x()[k]).norm(), 1e-15) << n;
      if (paddle) { // the chord is a hair shorter than the arc: |v| = omega r sinc(omega dt / 2)
        const double r = std::hypot(rest[k].x() - 0.15, rest[k].z() - 0.15);
        ASSERT_NEAR(walls.v()[k].norm(), omega * r * std::sin(0.5 * omega * dt) / (0.5 * omega * dt), 1e-12) << n;
      } else {
        ASSERT_EQ(walls.v()[k], Vec3::Zero());
      }
    }
    x = walls.x();
    v = walls.v();
  }
  EXPECT_EQ(walls.real(kBoundaryVolumeField), volumes); // rigid: the Akinci volumes stay those of the rest state
}

TEST(MovingWalls, TimeStepRespectsTheTurningPaddleBeforeItStarts) {
  // The paddle starts at 0.005 s, within the longest step (10 ms) from the first step's end: the CFL step already
  // sees its tip speed omega R, R the largest distance of a paddle particle from the axis.
  const double omega = 5.0;
  TimeControl control = fixedStep(1e-3);
  control.adjustTimeStep = true;
  control.maxCourant = 0.4;
  control.maxDeltaT = 0.01;
  Solver solver(paddleTank(), FluidProperties{}, {}, SolverSettings{}, control, RunState{}, paddleMotion(omega, 0.005));
  const ParticleSet& walls = solver.particles()[1];
  double reach = 0.0;
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (walls.integer(field::objectId)[k] == 1)
      reach = std::max(reach, std::hypot(walls.x()[k].x() - 0.15, walls.x()[k].z() - 0.15));
  solver.step(1e-3);
  // Not yet turned (its velocity already carries it across the start within the next step).
  for (std::size_t k = 0; k < walls.size(); ++k)
    ASSERT_LE((walls.x()[k] - walls.vec3(field::restPosition)[k]).norm(), 1e-15);
  EXPECT_NEAR(solver.lastStep().maxSpeed, omega * reach, 1e-12);
  EXPECT_LE(solver.state().nextDeltaT, 0.4 * solver.particles().spacing() / (omega * reach) * (1.0 + 1e-12));
}

TEST(MovingWalls, TheFirstStepRespectsATurningPaddleAsEveryLaterOne) {
  // controlDict's deltaT is only the first step's upper bound under adjustTimeStep: a paddle turning from t = 0 at
  // tip speed omega R must shorten that step as it does every later one (it used to take deltaT, 2.4 spacings).
  const double omega = 31.4;
  TimeControl control = fixedStep(0.01);
  control.adjustTimeStep = true;
  control.maxCourant = 0.4;
  control.maxDeltaT = 0.01;
  control.endTime = 0.5;
  Solver solver(paddleTank(), FluidProperties{}, {}, SolverSettings{}, control, RunState{}, paddleMotion(omega));
  const ParticleSet& walls = solver.particles()[1];
  double reach = 0.0;
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (walls.integer(field::objectId)[k] == 1)
      reach = std::max(reach, std::hypot(walls.x()[k].x() - 0.15, walls.x()[k].z() - 0.15));
  double firstStep = 0.0;
  const auto stopAfterTheFirst = [&](Solver& s) {
    firstStep = s.lastStep().deltaT;
    TimeControl c = s.timeControl();
    c.stopAt = TimeControl::StopAt::NoWriteNow;
    s.setTimeControl(c);
  };
  solver.run([](const Solver&) {}, stopAfterTheFirst);
  EXPECT_EQ(solver.state().step, 1);
  EXPECT_GT(firstStep, 0.0);
  EXPECT_LE(firstStep, 0.4 * solver.particles().spacing() / (omega * reach) * (1.0 + 1e-12));
}

TEST(MovingWalls, StepsThatMinDeltaTKeepAboveTheCourantLimitAreWarnedOfOnceAndCounted) {
  // The paddle's tip (omega R about 3 m/s) asks for 0.4 2r / 3 m/s, under 3 ms: minDeltaT = 5 ms overrides it in
  // every step. One warning, then every such step in the run's count.
  TimeControl control = fixedStep(0.005);
  control.adjustTimeStep = true;
  control.maxCourant = 0.4;
  control.minDeltaT = 0.005;
  control.maxDeltaT = 0.01;
  control.endTime = 0.015;
  Solver solver(paddleTank(), FluidProperties{}, {}, SolverSettings{}, control, RunState{}, paddleMotion(31.4));
  testing::internal::CaptureStderr();
  solver.run([](const Solver&) {});
  const std::string log = testing::internal::GetCapturedStderr();
  EXPECT_EQ(solver.state().step, 3);
  EXPECT_EQ(solver.warnings().steps(RunWarnings::Kind::StepAboveCourant), 3);
  const std::string below = "below minDeltaT = 0.005 s; the steps take minDeltaT";
  EXPECT_NE(log.find(below), std::string::npos) << log;
  EXPECT_EQ(log.find(below, log.find(below) + 1), std::string::npos) << log; // once
}

TEST(MovingWalls, TheDefaultDomainHoldsTheCircleOfARotatingWall) {
  // A bar 0.4 m long along x turning about z: the domain is the walls' box grown by its longest side, and the box
  // must be that of the circle the bar sweeps (y up to 0.19 + 0.38), not of the bar at rest (y up to 0.01 +
  // 0.38). Fluid at y = 0.5 is inside the domain only when the turning counts.
  const auto bar = [] {
    ParticleSystem ps(kR);
    std::int64_t id = 0;
    append(ps.add("fluid", SetKind::Fluid), {Vec3(0.0, 0.5, 0.0)}, 0, id);
    append(ps.add("boundary", SetKind::Boundary), sampleBox(Vec3(-0.2, -0.02, -0.02), Vec3(0.2, 0.02, 0.02), kR), 0,
           id);
    return ps;
  };
  const auto turning = [](const Vec3& axis) {
    return std::vector<ObjectMotion>{{0, "bar", "system/particleDict:9",
                                      WallMotion({{0.0, Vec3::Zero(), 0.0}}, Vec3::Zero(), axis, Vec3::Zero(), 1.0)}};
  };
  EXPECT_NO_THROW(
      Solver(bar(), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), RunState{}, turning(Vec3::UnitZ())));
  // Turning about its own length sweeps nothing new: the fluid is outside, which the start check refuses.
  EXPECT_THROW(
      Solver(bar(), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), RunState{}, turning(Vec3::UnitX())),
      InputError);
}

TEST(MovingWalls, TheDefaultDomainGoesWhereATranslatingContainerGoes) {
  // A closed box 0.12 m wide and its water, carried together at 10 m/s without gravity: after 0.04 s they are
  // 0.4 m from where they started, beyond the domain of the walls' box at the start (grown by 0.12 + 4 layers).
  // The domain goes with the walls, so no particle leaves it and the run is not stopped.
  ParticleSystem ps(kR);
  std::int64_t id = 0;
  append(ps.add("fluid", SetKind::Fluid), sampleBox(Vec3::Zero(), Vec3::Constant(0.12), kR), 0, id);
  const double g = kGap, t = 4 * kR, a = -t - g, b = 0.12 + t + g, lo = -g, hi = 0.12 + g; // two layers
  ParticleSet& box = ps.add("boundary", SetKind::Boundary);
  append(box, sampleBox(Vec3(a, a, a), Vec3(b, lo, b), kR), 0, id);   // floor
  append(box, sampleBox(Vec3(a, hi, a), Vec3(b, b, b), kR), 0, id);   // lid
  append(box, sampleBox(Vec3(a, lo, a), Vec3(lo, hi, b), kR), 0, id); // x sides
  append(box, sampleBox(Vec3(hi, lo, a), Vec3(b, hi, b), kR), 0, id);
  append(box, sampleBox(Vec3(lo, lo, a), Vec3(hi, hi, lo), kR), 0, id); // z sides
  append(box, sampleBox(Vec3(lo, lo, hi), Vec3(hi, hi, b), kR), 0, id);
  const Vec3 u(10.0, 0.0, 0.0);
  for (Vec3& v : ps[0].v()) v = u;
  const std::vector<ObjectMotion> carried{{0, "box", "system/particleDict:9", WallMotion({{0.0, Vec3::Zero()}}, u)}};
  FluidProperties weightless;
  weightless.gravity = Vec3::Zero();
  SolverSettings settings;
  settings.health.leavingDomain = HealthAction::Stop;
  TimeControl control = fixedStep(1e-3);
  control.endTime = 0.04;
  Solver solver(std::move(ps), weightless, {}, settings, control, RunState{}, carried);
  try {
    solver.run([](const Solver&) {});
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what();
  }
  EXPECT_EQ(solver.state().step, 40);
  for (const Vec3& x : solver.particles()[0].x()) ASSERT_GT(x.x(), 0.39);
}

TEST(MovingWalls, TurnedWallOrderAndVolumesDoNotDependOnWhereTheRunStarts) {
  // As for the piston: a restart reads the paddle turned by 1.11 rad; order and volumes are those of a run from 0.
  const double omega = 3.0, t = 0.37;
  Solver fromZero(paddleTank(), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), RunState{},
                  paddleMotion(omega));
  ParticleSystem later = paddleTank();
  ParticleSet& walls = later[1];
  walls.addVec3(field::restPosition, Restart) = walls.x();
  const std::vector<ObjectMotion> motion = paddleMotion(omega);
  for (std::size_t k = 0; k < walls.size(); ++k)
    if (walls.integer(field::objectId)[k] == 1) walls.x()[k] = motion[0].motion.position(walls.x()[k], t);
  RunState state;
  state.time = t;
  state.step = 370;
  Solver restarted(std::move(later), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), state, motion);
  const ParticleSet& a = fromZero.particles()[1];
  const ParticleSet& b = restarted.particles()[1];
  EXPECT_EQ(a.integer(field::id), b.integer(field::id));
  EXPECT_EQ(a.real(kBoundaryVolumeField), b.real(kBoundaryVolumeField));
  for (std::size_t k = 0; k < b.size(); ++k)
    ASSERT_EQ(b.x()[k], b.integer(field::objectId)[k] == 1
                            ? motion[0].motion.position(a.vec3(field::restPosition)[k], t)
                            : a.x()[k]);
}

TEST(MovingWalls, MotionOfAnObjectWithoutWallsIsAnInputError) {
  std::vector<ObjectMotion> motion = pistonMotion(0.1, 1.0);
  motion[0].objectId = 7;
  try {
    Solver solver(pistonChannel(), FluidProperties{}, {}, SolverSettings{}, fixedStep(1e-3), RunState{}, motion);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("system/particleDict:9: region 'piston'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("run sampleParticles again"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace poro
