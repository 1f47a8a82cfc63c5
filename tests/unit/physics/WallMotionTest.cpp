// Prescribed wall motion (physics/WallMotion.hpp, METHOD.md §6.2): the displacement law, its input checks, and
// walls moved by the Solver exactly as prescribed, pushing the fluid in front of them.

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "geometry/LatticeSampling.hpp"
#include "physics/FieldNames.hpp"
#include "physics/Solver.hpp"
#include "physics/WallMotion.hpp"
#include "sph/BoundaryVolume.hpp"

#include <gtest/gtest.h>

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

TEST(WallMotion, TemplateDictionaryMotionsAreValid) {
  // The two forms as etc/caseDicts/particleDict documents them.
  const Dictionary dict = Dictionary::read(std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/particleDict");
  int motions = 0;
  for (const Dictionary& region : dict.getDictList("regions"))
    if (const auto motion = region.optionalSubDict("motion")) {
      const WallMotion m = WallMotion::read(*motion);
      EXPECT_GT(m.maxSpeed(), 0.0);
      ++motions;
    }
  EXPECT_EQ(motions, 2);
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
