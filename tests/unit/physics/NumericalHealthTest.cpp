// The health checks of solverDict (NaN, leaving the domain, iteration limits) and the stop controls of the
// time loop (stopAt, runTimeModifiable), driven through Solver::run as the application drives it.

#include "PorousTestSystems.hpp"
#include "core/Error.hpp"
#include "geometry/LatticeSampling.hpp"
#include "physics/FieldNames.hpp"
#include "physics/Solver.hpp"
#include "physics/StateSnapshot.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace poro {
namespace {

constexpr double kR = 0.01;
constexpr double kDt = 1e-3;

/// A resting block of water, 8 x 8 x 8 particles, without walls (no default domain).
ParticleSystem waterBlock() {
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  const auto points = sampleBox(Vec3::Zero(), Vec3::Constant(0.16), kR);
  fluid.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    fluid.x()[i] = points[i];
    fluid.integer(field::id)[i] = static_cast<std::int64_t>(i);
  }
  return ps;
}

/// The block with velocities towards its centre: pressures and viscous forces are not zero.
ParticleSystem squeezedBlock() {
  ParticleSystem ps = waterBlock();
  for (std::size_t i = 0; i < ps[0].size(); ++i) ps[0].v()[i] = -20.0 * (ps[0].x()[i] - Vec3::Constant(0.08));
  return ps;
}

TimeControl steps(int n, int writeEvery = 1000) {
  TimeControl control;
  control.deltaT = kDt;
  control.endTime = n * kDt;
  control.writeControl = TimeControl::WriteControl::TimeStep;
  control.writeInterval = writeEvery;
  return control;
}

/// What a writer saw: the step, ids, positions, velocities and pressures of every write.
struct Writes {
  std::vector<long long> steps;
  std::vector<std::vector<std::int64_t>> ids;
  std::vector<std::vector<Vec3>> positions;
  std::vector<std::vector<Vec3>> velocities;
  std::vector<std::vector<double>> pressures;
  std::vector<std::vector<Vec3>> warmStarts; ///< deltaV
  Solver::Writer writer() {
    return [this](const Solver& s) {
      if (s.state().step == 0) return; // the start's rewrite of 0/ (Solver::run), not a write these tests check
      steps.push_back(s.state().step);
      ids.push_back(s.particles()[0].integer(field::id));
      positions.push_back(s.particles()[0].x());
      velocities.push_back(s.particles()[0].v());
      pressures.push_back(s.particles()[0].real(field::pressure));
      warmStarts.push_back(s.particles()[0].vec3(field::deltaV));
    };
  }
};

std::string runExpectingStop(Solver& solver, Writes& writes) {
  try {
    solver.run(writes.writer());
  } catch (const NumericalError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the run did not stop";
  return "";
}

TEST(StateSnapshot, RestoreGivesBackFieldsAndParticleCount) {
  ParticleSystem ps = waterBlock();
  ParticleSet& set = ps[0];
  auto& pressure = set.addReal("pressure", Output);
  set.addReal("scratch");
  for (std::size_t i = 0; i < set.size(); ++i) pressure[i] = static_cast<double>(i);
  const std::vector<Vec3> x = set.x();
  const std::vector<double> p = pressure;
  StateSnapshot snapshot;
  snapshot.take(ps, {0}, RunState{0.5, 7, 1e-3});
  for (auto& xi : set.x()) xi.x() += 1.0;
  set.remove({0, 1, 2});
  RunState state;
  snapshot.restore(ps, state);
  EXPECT_EQ(set.x(), x);
  EXPECT_EQ(pressure, p);
  EXPECT_EQ(state.step, 7);
  EXPECT_EQ(state.time, 0.5);
  EXPECT_EQ(*snapshot.positionOf(0, 7, 5), x[5]) << "found by its id";
  EXPECT_FALSE(snapshot.positionOf(0, 0, 100000).has_value());
}

TEST(StateSnapshot, FieldsKeptInPlaceAreNeitherCopiedNorRestored) {
  // A step that keeps the order leaves ids (and other fields set once) as they are: the snapshot leaves them out,
  // and finds a particle's last position at its index.
  ParticleSystem ps = waterBlock();
  ParticleSet& set = ps[0];
  const std::vector<Vec3> x = set.x();
  const std::vector<std::int64_t> ids = set.integer(field::id);
  StateSnapshot snapshot;
  snapshot.take(ps, {0}, RunState{}, {field::id});
  for (auto& xi : set.x()) xi.x() += 1.0;
  set.integer(field::id)[3] = -1; // a step never does this: only shows that restore leaves the field alone
  RunState state;
  snapshot.restore(ps, state);
  EXPECT_EQ(set.x(), x);
  EXPECT_EQ(set.integer(field::id)[3], -1);
  EXPECT_EQ(*snapshot.positionOf(0, 5, ids[5]), x[5]);
  EXPECT_FALSE(snapshot.positionOf(0, x.size(), 0).has_value());
}

TEST(Health, NaNUndoesTheStepAndWritesTheLastFiniteState) {
  // NaN in step 3: the run writes the state after step 2 -- bit for bit what an undisturbed run has there --
  // and stops with a message naming the particle, its last position and what to change.
  Solver reference(waterBlock(), FluidProperties{}, {}, SolverSettings{}, steps(2), RunState{});
  reference.run([](const Solver&) {});
  Solver solver(waterBlock(), FluidProperties{}, {}, SolverSettings{}, steps(10), RunState{});
  solver.injectNaN(3);
  Writes writes;
  const std::string message = runExpectingStop(solver, writes);
  ASSERT_EQ(writes.steps, std::vector<long long>{2});
  EXPECT_EQ(writes.positions[0], reference.particles()[0].x());
  EXPECT_EQ(solver.state().step, 2);
  EXPECT_NE(message.find("step 3 "), std::string::npos) << message;
  // The injected NaN velocity reaches only its own particle's position; its neighbours' step was done.
  EXPECT_NE(message.find("NaN or infinite position or velocity in 1 fluid particle: id 0 at (0.01, 0.00997"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("reduce deltaT (now 0.001 s) in system/controlDict"), std::string::npos) << message;
  EXPECT_NE(message.find("is written"), std::string::npos) << message;
}

TEST(Health, NaNUndoesTheStepAndWritesTheWarmStartAsZero) {
  // The snapshot does not copy the implicit solve's warm start (deltaV): an undone step writes it as zero, so a
  // restart from the written state starts the solve cold. Everything else is the last finite state. Viscosity
  // and a squeezed block give the solve something to do.
  FluidProperties viscous;
  viscous.viscosity = 1.0;
  Solver reference(squeezedBlock(), viscous, {}, SolverSettings{}, steps(2), RunState{});
  reference.run([](const Solver&) {});
  const auto& warmStart = reference.particles()[0].vec3(field::deltaV);
  ASSERT_TRUE(std::any_of(warmStart.begin(), warmStart.end(), [](const Vec3& d) { return d != Vec3::Zero(); }))
      << "the run had no warm start to drop";
  Solver solver(squeezedBlock(), viscous, {}, SolverSettings{}, steps(10), RunState{});
  solver.injectNaN(3);
  Writes writes;
  runExpectingStop(solver, writes);
  ASSERT_EQ(writes.steps, std::vector<long long>{2});
  EXPECT_EQ(writes.positions[0], reference.particles()[0].x());
  EXPECT_EQ(writes.velocities[0], reference.particles()[0].v());
  EXPECT_EQ(writes.warmStarts[0], std::vector<Vec3>(warmStart.size(), Vec3::Zero()));
}

/// An elastic porous block spinning about its vertical axis, with water resting 0.1 r above it: its rotations,
/// saturations and the water's phi^loc change from step to step.
ParticleSystem spinningSoakedBlock() {
  ParticleSystem ps(kR);
  const Vec3 centre(0.04, 0.04, 0.04);
  std::vector<Vec3> spin;
  for (const Vec3& x : sampleBox(Vec3::Zero(), Vec3::Constant(0.08), kR))
    spin.push_back(Vec3(0.0, 20.0, 0.0).cross(x - centre)); // [m/s], 0.02 rad per step
  test::addSet(ps, "water", SetKind::Fluid, sampleBox(Vec3(0.0, 0.081, 0.0), Vec3(0.08, 0.161, 0.08), kR));
  ParticleSet& soil = test::addSet(ps, "soil", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3::Constant(0.08), kR));
  soil.v() = spin;
  return ps;
}

TEST(Health, NaNUndoesTheStepAndWritesWhatItFormedFromTheRestoredPositions) {
  // Rotations, saturations and phi^loc are formed from the positions at a step's start only. A serial run's snapshot
  // does not copy them: an undone step writes those it formed, which fit the restored positions (those of a third
  // step undisturbed), where a write after step 2 holds step 2's, formed from the positions before it.
  PorousMaterial soil = test::material("soil", 0.4, 2650.0, false);
  soil.youngsModulus = 2.5e5;
  soil.poissonsRatio = 0.33;
  struct Formed {
    std::vector<Vec3> waterPositions;
    std::vector<Mat3> rotations;
    std::vector<double> saturations, localPorosities;
  };
  const auto formed = [](const Solver& s) {
    return Formed{s.particles()[0].x(), s.particles()[1].mat3(field::rotation),
                  s.particles()[1].real(field::saturation), s.particles()[0].real(field::localPorosity)};
  };
  const auto run = [&](int n) {
    Solver solver(spinningSoakedBlock(), FluidProperties{}, {soil}, SolverSettings{}, steps(n), RunState{});
    solver.run([](const Solver&) {});
    return formed(solver);
  };
  const Formed two = run(2), three = run(3);
  ASSERT_NE(two.rotations, three.rotations) << "the rotations did not change: the test shows nothing";
  ASSERT_NE(two.saturations, three.saturations) << "the saturations did not change: the test shows nothing";
  ASSERT_NE(two.localPorosities, three.localPorosities) << "phi^loc did not change: the test shows nothing";
  Solver solver(spinningSoakedBlock(), FluidProperties{}, {soil}, SolverSettings{}, steps(10), RunState{});
  solver.injectNaN(3);
  std::vector<Formed> written;
  try {
    solver.run([&](const Solver& s) {
      if (s.state().step > 0) written.push_back(formed(s));
    });
    ADD_FAILURE() << "the run did not stop";
  } catch (const NumericalError&) {
  }
  ASSERT_EQ(written.size(), 1u);
  EXPECT_EQ(written[0].waterPositions, two.waterPositions);
  EXPECT_EQ(written[0].rotations, three.rotations);
  EXPECT_EQ(written[0].saturations, three.saturations);
  EXPECT_EQ(written[0].localPorosities, three.localPorosities);
}

TEST(Health, NaNUndoesTheStepAndWritesThePressuresBefore) {
  // The snapshot does not copy p: it is formed again from the restored pi and densities, and must be the p of the
  // last finite state to the bit. The block is squeezed (velocities towards its centre), so that p is not zero.
  Solver reference(squeezedBlock(), FluidProperties{}, {}, SolverSettings{}, steps(2), RunState{});
  reference.run([](const Solver&) {});
  const auto& p = reference.particles()[0].real(field::pressure);
  ASSERT_GT(*std::max_element(p.begin(), p.end()), 0.0) << "no pressure to check";
  Solver solver(squeezedBlock(), FluidProperties{}, {}, SolverSettings{}, steps(10), RunState{});
  solver.injectNaN(3);
  Writes writes;
  runExpectingStop(solver, writes);
  ASSERT_EQ(writes.steps, std::vector<long long>{2});
  EXPECT_EQ(writes.pressures[0], p);
}

TEST(Health, NaNInASortStepWritesTheSortedStateBefore) {
  // A serial run puts its particles into Morton order before the snapshot of a sort step, so that the snapshot
  // need not copy the fields set once (ids, rest positions): a step undone there writes the state before it,
  // sorted, with every particle's fields still its own. Starting at step 1 (no sort at the start), the block is
  // in lattice order until step 2 sorts it.
  SolverSettings settings;
  settings.sortInterval = 2;
  const RunState atStep1{kDt, 1, kDt};
  Solver reference(waterBlock(), FluidProperties{}, {}, settings, steps(2), atStep1);
  reference.run([](const Solver&) {});
  Solver solver(waterBlock(), FluidProperties{}, {}, settings, steps(10), atStep1);
  solver.injectNaN(3);
  Writes writes;
  runExpectingStop(solver, writes);
  ASSERT_EQ(solver.state().step, 2);
  ASSERT_EQ(writes.steps, std::vector<long long>{2});
  const auto& ids = writes.ids[0];
  const auto& x = writes.positions[0];
  const auto& v = writes.velocities[0];
  const ParticleSet& before = reference.particles()[0];
  ASSERT_EQ(ids.size(), before.size());
  ASSERT_NE(ids, before.integer(field::id)) << "step 2 did not reorder the block: the test shows nothing";
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const auto k = static_cast<std::size_t>(ids[i]); // waterBlock's ids are its lattice indices
    ASSERT_EQ(before.integer(field::id)[k], ids[i]);
    EXPECT_EQ(x[i], before.x()[k]) << "id " << ids[i];
    EXPECT_EQ(v[i], before.v()[k]) << "id " << ids[i];
  }
}

TEST(Health, NaNRightAfterAWriteIsNotWrittenTwice) {
  Solver solver(waterBlock(), FluidProperties{}, {}, SolverSettings{}, steps(10, 2), RunState{});
  solver.injectNaN(3);
  Writes writes;
  const std::string message = runExpectingStop(solver, writes);
  EXPECT_EQ(writes.steps, std::vector<long long>{2});
  EXPECT_NE(message.find("already on disk"), std::string::npos) << message;
}

TEST(Health, NaNParticlesCanBeRemovedInstead) {
  SolverSettings settings;
  settings.health.nonFinite = HealthAction::Remove;
  Solver solver(waterBlock(), FluidProperties{}, {}, settings, steps(5), RunState{});
  const std::size_t before = solver.particles()[0].size();
  solver.injectNaN(3);
  Writes writes;
  EXPECT_EQ(solver.run(writes.writer()).end, RunOutcome::End::EndTime);
  const ParticleSet& fluid = solver.particles()[0];
  EXPECT_LT(fluid.size(), before);
  for (std::size_t i = 0; i < fluid.size(); ++i) ASSERT_TRUE(fluid.x()[i].allFinite() && fluid.v()[i].allFinite());
  EXPECT_EQ(writes.steps, std::vector<long long>{5});
  EXPECT_EQ(solver.warnings().steps(RunWarnings::Kind::NonFiniteRemoved), 1);
  EXPECT_EQ(solver.warnings().particles(RunWarnings::Kind::NonFiniteRemoved), before - fluid.size());
}

/// A block falling freely out of a domain whose floor is 1 mm below it.
Solver fallingBlock(HealthAction action) {
  SolverSettings settings;
  settings.health.leavingDomain = action;
  settings.health.domain = Domain{Vec3::Constant(-1.0), Vec3::Constant(1.0)};
  settings.health.domain->min.y() = 0.01 - 0.001 - 1e-12; // the lowest row starts at y = r
  return Solver(waterBlock(), FluidProperties{}, {}, settings, steps(20), RunState{});
}

TEST(Health, ParticlesLeavingTheDomainAreRemovedByDefault) {
  // Free fall: y = r - g dt^2 n(n+1)/2 passes 1 mm below the start in step 14; the bottom row (64
  // particles) goes then, the rows above keep their distance 2r and stay.
  Solver solver = fallingBlock(HealthAction::Remove);
  Writes writes;
  EXPECT_EQ(solver.run(writes.writer()).end, RunOutcome::End::EndTime);
  EXPECT_EQ(solver.particles()[0].size(), 512u - 64u);
  for (const Vec3& x : solver.particles()[0].x()) EXPECT_GT(x.y(), 0.009);
  EXPECT_EQ(solver.warnings().steps(RunWarnings::Kind::LeftDomainRemoved), 1);
  EXPECT_EQ(solver.warnings().particles(RunWarnings::Kind::LeftDomainRemoved), 64u);
  EXPECT_FALSE(solver.warnings().steps(RunWarnings::Kind::OutsideDomainKept));
}

TEST(Health, ParticlesLeavingTheDomainCanStopTheRun) {
  Solver solver = fallingBlock(HealthAction::Stop);
  Writes writes;
  const std::string message = runExpectingStop(solver, writes);
  ASSERT_EQ(writes.steps, std::vector<long long>{14});
  EXPECT_EQ(writes.positions[0].size(), 512u);
  EXPECT_NE(message.find("64 fluid particles: id 0 at (0.01, 0.0"), std::string::npos) << message;
  EXPECT_NE(message.find("left the domain (-1, 0.009, -1) - (1, 1, 1)"), std::string::npos) << message;
  EXPECT_NE(message.find("health.leavingDomain stop"), std::string::npos) << message;
}

TEST(Health, ParticlesLeavingTheDomainCanBeKept) {
  Solver solver = fallingBlock(HealthAction::Warn);
  Writes writes;
  EXPECT_EQ(solver.run(writes.writer()).end, RunOutcome::End::EndTime);
  EXPECT_EQ(solver.particles()[0].size(), 512u);
  // The bottom row is outside from step 14 to the last, 20, and the rows above stay in (see above).
  EXPECT_EQ(solver.warnings().steps(RunWarnings::Kind::OutsideDomainKept), 7);
  EXPECT_EQ(solver.warnings().particles(RunWarnings::Kind::OutsideDomainKept), 64u);
  EXPECT_FALSE(solver.warnings().steps(RunWarnings::Kind::LeftDomainRemoved));
}

TEST(Health, DefaultDomainIsTheWallBoxGrownByItsLongestSide) {
  // Walls spanning (1, 1, 1) - (1.2, 1.3, 1.1): longest side 0.3, domain (0.7, 0.7, 0.7) - (1.5, 1.6, 1.4),
  // which the block (0 - 0.16) is outside of from the start: an input error (StartCheckTest.cpp).
  ParticleSystem ps = waterBlock();
  ParticleSet& wall = ps.add("boundary", SetKind::Boundary);
  wall.resize(2);
  wall.x()[0] = Vec3(1.0, 1.0, 1.0);
  wall.x()[1] = Vec3(1.2, 1.3, 1.1);
  SolverSettings settings;
  settings.health.leavingDomain = HealthAction::Stop;
  try {
    Solver solver(std::move(ps), FluidProperties{}, {}, settings, steps(10), RunState{});
    ADD_FAILURE() << "a block outside the domain was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("512 fluid particles"), std::string::npos) << message;
    EXPECT_NE(message.find("outside the domain (0.7, 0.7, 0.7) - (1.5, 1.6, 1.4), the walls' bounding box grown"),
              std::string::npos)
        << message;
  }
}

TEST(Health, PressureIterationLimitCanStopTheRun) {
  // A compressed blob with one sweep allowed cannot converge; policy stop writes this step and names the
  // most compressed particle.
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  const auto points = sampleBox(Vec3::Zero(), Vec3::Constant(0.16), kR);
  fluid.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    fluid.x()[i] = 0.9 * points[i];
    fluid.integer(field::id)[i] = static_cast<std::int64_t>(i);
  }
  SolverSettings settings;
  settings.health.startDensity = 2.0; // the blob starts at rho~ 1.37 on purpose
  settings.pressure.minIterations = settings.pressure.maxIterations = 1;
  settings.health.pressureIterations = HealthAction::Stop;
  Solver solver(std::move(ps), FluidProperties{}, {}, settings, steps(5), RunState{});
  Writes writes;
  const std::string message = runExpectingStop(solver, writes);
  EXPECT_EQ(writes.steps, std::vector<long long>{1});
  EXPECT_NE(message.find("pressure.maxIterations = 1 with mean density error"), std::string::npos) << message;
  EXPECT_NE(message.find("most compressed: fluid particle id"), std::string::npos) << message;
}

TEST(Health, EveryStepThatReachedAnIterationLimitIsCounted) {
  // One sweep and one CG iteration on the squeezed, viscous block: each step that warns is counted, and no other.
  SolverSettings settings;
  settings.pressure.minIterations = settings.pressure.maxIterations = 1;
  settings.implicit.maxIterations = 1;
  settings.implicit.tolerance = 1e-9;
  FluidProperties viscous;
  viscous.viscosity = 1.0;
  Solver solver(squeezedBlock(), viscous, {}, settings, steps(6), RunState{});
  Writes writes;
  testing::internal::CaptureStderr();
  solver.run(writes.writer());
  const std::string log = testing::internal::GetCapturedStderr();
  const auto occurrences = [&](const std::string& text) {
    long long n = 0;
    for (std::size_t at = log.find(text); at != std::string::npos; at = log.find(text, at + 1)) ++n;
    return n;
  };
  const long long pressure = occurrences("pressure.maxIterations = 1 with");
  const long long implicit = occurrences("implicit.maxIterations = 1 with");
  EXPECT_GT(pressure, 0) << log;
  EXPECT_GT(implicit, 0) << log;
  EXPECT_EQ(solver.warnings().steps(RunWarnings::Kind::PressureIterations), pressure);
  EXPECT_EQ(solver.warnings().steps(RunWarnings::Kind::ImplicitIterations), implicit);
}

TEST(Health, AnUnmetParticleBoundIsNamedInTheIterationMessage) {
  // The mean is met at once (50 %), so only the single-particle bound can keep the sweeps going: the message must
  // name the bound that was not met, and with the skeletons' bound a skeleton particle as the most compressed.
  const auto message = [](double particleBound, double skeletonBound) {
    SolverSettings settings;
    settings.pressure.maxDensityError = 50.0;
    settings.health.startDensity = 2.0; // fluid is sampled into the sand on purpose (mixedSystem)
    settings.pressure.maxParticleDensityError = particleBound;
    settings.pressure.maxSkeletonParticleDensityError = skeletonBound;
    settings.pressure.minIterations = settings.pressure.maxIterations = 2;
    settings.health.pressureIterations = HealthAction::Stop;
    Solver solver(test::mixedSystem(), FluidProperties{}, test::mixedMaterials(), settings, steps(20), RunState{});
    Writes writes;
    return runExpectingStop(solver, writes);
  };
  const std::string particle = message(1e-9, 0.0);
  EXPECT_NE(particle.find("(bound pressure.maxParticleDensityError 1e-09 %)"), std::string::npos) << particle;
  EXPECT_EQ(particle.find("maxSkeletonParticleDensityError"), std::string::npos) << particle;
  EXPECT_NE(particle.find("or raise pressure.maxIterations or the bound"), std::string::npos) << particle;
  const std::string skeleton = message(0.0, 1e-9);
  EXPECT_NE(skeleton.find("(bound pressure.maxSkeletonParticleDensityError 1e-09 %)"), std::string::npos) << skeleton;
  EXPECT_EQ(skeleton.find("(bound pressure.maxParticleDensityError"), std::string::npos) << skeleton;
  EXPECT_TRUE(skeleton.find("most compressed: sand particle") != std::string::npos ||
              skeleton.find("most compressed: foam particle") != std::string::npos)
      << skeleton;
}

TEST(TimeLoop, StopAtWriteNowSetWhileRunningWritesAndStops) {
  Solver solver(waterBlock(), FluidProperties{}, {}, SolverSettings{}, steps(10), RunState{});
  Writes writes;
  const auto monitor = [](Solver& s) {
    if (s.state().step != 3) return;
    TimeControl control = s.timeControl();
    control.stopAt = TimeControl::StopAt::WriteNow;
    s.setTimeControl(control);
  };
  EXPECT_EQ(solver.run(writes.writer(), monitor).end, RunOutcome::End::StopAt);
  EXPECT_EQ(writes.steps, std::vector<long long>{3});
}

TEST(TimeLoop, StopAtNextWriteAndNoWriteNow) {
  Solver next(waterBlock(), FluidProperties{}, {}, SolverSettings{}, steps(10, 4), RunState{});
  Writes nextWrites;
  auto set = [](TimeControl::StopAt stopAt) {
    return [stopAt](Solver& s) {
      if (s.state().step != 1) return;
      TimeControl control = s.timeControl();
      control.stopAt = stopAt;
      s.setTimeControl(control);
    };
  };
  EXPECT_EQ(next.run(nextWrites.writer(), set(TimeControl::StopAt::NextWrite)).end, RunOutcome::End::StopAt);
  EXPECT_EQ(nextWrites.steps, std::vector<long long>{4});
  Solver now(waterBlock(), FluidProperties{}, {}, SolverSettings{}, steps(10, 4), RunState{});
  Writes nowWrites;
  EXPECT_EQ(now.run(nowWrites.writer(), set(TimeControl::StopAt::NoWriteNow)).end, RunOutcome::End::StopAt);
  EXPECT_TRUE(nowWrites.steps.empty());
  EXPECT_EQ(now.state().step, 1);
}

TEST(TimeLoop, EndTimeAndWriteIntervalChangedWhileRunning) {
  // At step 2: endTime 10 -> 6 steps, writeInterval 1000 -> 2 steps; and deltaT takes effect at once.
  Solver solver(waterBlock(), FluidProperties{}, {}, SolverSettings{}, steps(10), RunState{});
  Writes writes;
  const auto monitor = [](Solver& s) {
    if (s.state().step != 2) return;
    TimeControl control = s.timeControl();
    control.endTime = 6 * kDt;
    control.writeInterval = 2;
    s.setTimeControl(control);
  };
  EXPECT_EQ(solver.run(writes.writer(), monitor).end, RunOutcome::End::EndTime);
  EXPECT_EQ(writes.steps, (std::vector<long long>{2, 4, 6}));
}

} // namespace
} // namespace poro
