// A run stopped and restarted with startFrom latestTime continues the same trajectory bit for bit
// (METHOD.md §7), whatever the thread count (METHOD.md §1).

#include "CaseRunner.hpp"
#include "core/BuildInfo.hpp"
#include "physics/FieldNames.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>

namespace poro::test {
namespace {

void makeSmallDamBreak(CaseRunner& runner, const std::string& endTime) {
  runner.replace("system/particleDict", "max: [0.2, 0.4, 0.64]", "max: [0.1, 0.2, 0.04]");
  runner.replace("system/particleDict", "max: [1.2005, 0.6005, 0.6405]", "max: [0.4005, 0.3005, 0.0405]");
  runner.setKey("system/controlDict", "endTime", endTime);
  runner.setKey("system/controlDict", "writeInterval", "0.05");
  // Sort often, so the restart crosses Morton reorderings.
  runner.replace("system/solverDict", "sortInterval: 500", "sortInterval: 7");
}

void expectIdentical(const ParticleSet& a, const ParticleSet& b) {
  ASSERT_EQ(a.size(), b.size());
  for (const char* name : {field::x, field::v}) {
    const auto& va = a.vec3(name);
    const auto& vb = b.vec3(name);
    for (std::size_t i = 0; i < va.size(); ++i)
      ASSERT_TRUE(va[i] == vb[i]) << name << "[" << i << "]: " << va[i].transpose() << " vs " << vb[i].transpose();
  }
  EXPECT_EQ(a.integer(field::id), b.integer(field::id));
}

TEST(Restart, StoppedAndRestartedRunMatchesUninterruptedRun) {
  CaseRunner straight("fluid/damBreak");
  makeSmallDamBreak(straight, "0.1");
  ASSERT_EQ(straight.sample(), 0);
  ASSERT_EQ(straight.solve("-threads 2"), 0) << straight.read("log.poroSph");

  CaseRunner split("fluid/damBreak");
  makeSmallDamBreak(split, "0.05");
  ASSERT_EQ(split.sample(), 0);
  ASSERT_EQ(split.solve("-threads 2"), 0) << split.read("log.poroSph");
  split.setKey("system/controlDict", "endTime", "0.1");
  std::filesystem::remove(split.dir() / "log.poroSph");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph"); // also: thread count does not matter
  EXPECT_NE(split.read("log.poroSph").find("Starting from time 0.05"), std::string::npos);
  // Bit for bit holds for one binary: the log names the build it ran (compiler, instruction set, fused multiply-adds).
  EXPECT_NE(split.read("log.poroSph").find("\nBuild: " + buildDescription() + "\n"), std::string::npos);

  const ParticleSystem a = straight.particles("0.1", 0.005);
  const ParticleSystem b = split.particles("0.1", 0.005);
  expectIdentical(*a.find("fluid"), *b.find("fluid"));
  EXPECT_NE(split.read("case.pvd").find("0.1/fluid.vtp"), std::string::npos);
  EXPECT_NE(split.read("case.pvd").find("0.05/fluid.vtp"), std::string::npos);
}

TEST(Restart, RigidBodyContinuesBitForBit) {
  // The floating box (tutorials/rigid/floatingBox) splashing into the pool: its pose and momenta go through
  // uniform/rigidBodies and its particles through rigid.vtp; the restarted run matches the straight one.
  CaseRunner straight("rigid/floatingBox");
  straight.setKey("system/controlDict", "endTime", "0.16");
  ASSERT_EQ(straight.sample(), 0);
  ASSERT_EQ(straight.solve("-threads 2"), 0) << straight.read("log.poroSph");

  CaseRunner split("rigid/floatingBox");
  split.setKey("system/controlDict", "endTime", "0.08");
  ASSERT_EQ(split.sample(), 0);
  ASSERT_EQ(split.solve("-threads 2"), 0) << split.read("log.poroSph");
  split.setKey("system/controlDict", "endTime", "0.16");
  std::filesystem::remove(split.dir() / "log.poroSph");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph");
  EXPECT_NE(split.read("log.poroSph").find("Starting from time 0.08"), std::string::npos);

  const std::string bodies = straight.read("0.16/uniform/rigidBodies");
  EXPECT_EQ(bodies, split.read("0.16/uniform/rigidBodies"));
  EXPECT_EQ(straight.read("postProcessing/rigidBodies/box.csv"), split.read("postProcessing/rigidBodies/box.csv"));
  const ParticleSystem a = straight.particles("0.16", 0.01);
  const ParticleSystem b = split.particles("0.16", 0.01);
  expectIdentical(*a.find("fluid"), *b.find("fluid"));
  expectIdentical(*a.find("boundary"), *b.find("boundary"));
  expectIdentical(*a.find("rigid"), *b.find("rigid"));
  // The tank stands still: it stays in 0/boundary.vtp, and only the box's particles are written at every time.
  EXPECT_TRUE(std::filesystem::exists(straight.dir() / "0.16" / "rigid.vtp"));
  EXPECT_FALSE(std::filesystem::exists(straight.dir() / "0.16" / "boundary.vtp"));
  // By 0.16 s the box has fallen into the water: the test compares a moving body.
  const std::string first = straight.read("0.02/uniform/rigidBodies");
  EXPECT_NE(first, bodies);

  // Run again from an earlier time: the rows after it leave the body's CSV before the run writes them anew.
  split.setKey("system/controlDict", "startFrom", "startTime");
  split.setKey("system/controlDict", "startTime", "0.08");
  std::filesystem::remove(split.dir() / "log.poroSph");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph");
  EXPECT_NE(split.read("log.poroSph").find("Starting from time 0.08"), std::string::npos);
  EXPECT_EQ(straight.read("postProcessing/rigidBodies/box.csv"), split.read("postProcessing/rigidBodies/box.csv"));
  EXPECT_EQ(bodies, split.read("0.16/uniform/rigidBodies"));
}

TEST(Restart, SigtermWritesTheCurrentStepAndTheRunResumesBitForBit) {
  // SIGTERM ends the run after the current step with a written time directory, a resume hint and exit code
  // 1; startFrom latestTime then reaches the same final state as an uninterrupted run (one thread).
  CaseRunner straight("fluid/damBreak");
  makeSmallDamBreak(straight, "0.1");
  ASSERT_EQ(straight.sample(), 0);
  ASSERT_EQ(straight.solve("-threads 1"), 0) << straight.read("log.poroSph");

  CaseRunner killed("fluid/damBreak");
  makeSmallDamBreak(killed, "0.1");
  ASSERT_EQ(killed.sample(), 0);
  const pid_t pid = killed.startSolver("1");
  ASSERT_GT(pid, 0);
  // Signal once the run is under way (step 20 of about 100), long before it ends.
  for (int wait = 0; wait < 6000 && killed.read("log.poroSph").find("(step 20)") == std::string::npos; ++wait)
    ::usleep(10000);
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const std::string log = killed.read("log.poroSph");
  ASSERT_TRUE(WIFEXITED(status)) << log;
  EXPECT_EQ(WEXITSTATUS(status), 1) << log;
  EXPECT_NE(log.find("SIGTERM received: stopped after step"), std::string::npos) << log;
  EXPECT_NE(log.find("startFrom latestTime"), std::string::npos);
  const auto times = listTimeDirectories(killed.dir());
  ASSERT_GE(times.size(), 2u);
  ASSERT_LT(times.back().time, 0.1 - 1e-9) << "the run ended before the signal arrived";

  std::filesystem::remove(killed.dir() / "log.poroSph");
  ASSERT_EQ(killed.solve("-threads 1"), 0) << killed.read("log.poroSph");
  expectIdentical(*straight.particles("0.1", 0.005).find("fluid"), *killed.particles("0.1", 0.005).find("fluid"));
}

/// Starts the small dam break in the background and waits until step 20 of about 100 is logged.
pid_t startAndWaitForStep20(const CaseRunner& runner) {
  const pid_t pid = runner.startSolver("1");
  for (int wait = 0; wait < 6000 && runner.read("log.poroSph").find("(step 20)") == std::string::npos; ++wait)
    ::usleep(10000);
  return pid;
}

TEST(Restart, SighupStopsTheRunLikeSigterm) {
  // A closed terminal sends SIGHUP: the run writes its current step and says how to resume, as for SIGTERM.
  CaseRunner runner("fluid/damBreak");
  makeSmallDamBreak(runner, "0.1");
  ASSERT_EQ(runner.sample(), 0);
  const pid_t pid = startAndWaitForStep20(runner);
  ASSERT_GT(pid, 0);
  ASSERT_EQ(::kill(pid, SIGHUP), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const std::string log = runner.read("log.poroSph");
  ASSERT_TRUE(WIFEXITED(status)) << log;
  EXPECT_EQ(WEXITSTATUS(status), 1) << log;
  EXPECT_NE(log.find("SIGHUP received: stopped after step"), std::string::npos) << log;
  const auto times = listTimeDirectories(runner.dir());
  ASSERT_GE(times.size(), 2u);
  EXPECT_LT(times.back().time, 0.1 - 1e-9);
}

TEST(Restart, ASecondSignalStopsAtOnceAndEarlierTimesStayIntact) {
  // Ctrl-C, then Ctrl-C again (or kill): the second does not wait for the step; what is on disk stays usable.
  CaseRunner runner("fluid/damBreak");
  makeSmallDamBreak(runner, "0.1");
  ASSERT_EQ(runner.sample(), 0);
  const pid_t pid = startAndWaitForStep20(runner);
  ASSERT_GT(pid, 0);
  // Two different signals: two of one kind sent before the first is handled would merge into one.
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const std::string log = runner.read("log.poroSph");
  ASSERT_TRUE(WIFEXITED(status)) << log;
  EXPECT_GT(WEXITSTATUS(status), 128) << log;
  EXPECT_NE(log.find("Second stop signal: stopping at once"), std::string::npos) << log;
  EXPECT_EQ(log.find("received: stopped after step"), std::string::npos) << "the step was not waited for";
  std::filesystem::remove(runner.dir() / "log.poroSph");
  ASSERT_EQ(runner.solve("-threads 1"), 0) << runner.read("log.poroSph");
  EXPECT_TRUE(std::filesystem::exists(runner.dir() / "0.1" / "fluid.vtp"));
}

TEST(Restart, AFinishedCaseRunAgainSaysSoAndExitsZero) {
  // As OpenFOAM: a second ./Allrun of a finished case is not an error; nothing is rewritten.
  CaseRunner runner("fluid/damBreak");
  makeSmallDamBreak(runner, "0.05");
  ASSERT_EQ(runner.sample(), 0);
  ASSERT_EQ(runner.solve(), 0) << runner.read("log.poroSph");
  const auto before = std::filesystem::last_write_time(runner.dir() / "0.05" / "fluid.vtp");
  std::filesystem::remove(runner.dir() / "log.poroSph");
  ASSERT_EQ(runner.solve(), 0) << runner.read("log.poroSph");
  EXPECT_NE(runner.read("log.poroSph").find("has reached endTime 0.05"), std::string::npos)
      << runner.read("log.poroSph");
  EXPECT_EQ(std::filesystem::last_write_time(runner.dir() / "0.05" / "fluid.vtp"), before);
}

void makeCoarsePorousWall(CaseRunner& runner, const std::string& endTime) {
  runner.setKey("system/particleDict", "particleRadius", "0.02");
  runner.replace("system/particleDict", "fixed: true", "fixed: false"); // the solid moves too
  // Free, it may not touch the walls: in lattice contact it would start at rho/rho^max 1.041 (health.startDensity).
  runner.replace("system/particleDict", "min: [0, 0, 0]", "min: [-0.002, -0.002, -0.002]"); // 0.1 r
  runner.replace("system/particleDict", "max: [1.6, 1.2, 0.4]", "max: [1.602, 1.2, 0.402]");
  runner.setKey("system/controlDict", "endTime", endTime);
  runner.setKey("system/controlDict", "writeInterval", "0.05");
  runner.replace("system/solverDict", "sortInterval: 500", "sortInterval: 7");
}

TEST(Restart, PorousRunRestartsBitForBit) {
  // Fluid and a free porous solid (pressure, drag and buoyancy with its lagged pressures), restarted across
  // Morton reorderings and on another thread count.
  CaseRunner straight("porous/porousWall");
  makeCoarsePorousWall(straight, "0.1");
  ASSERT_EQ(straight.sample(), 0) << straight.read("log.sampleParticles");
  ASSERT_EQ(straight.solve("-threads 2"), 0) << straight.read("log.poroSph");

  CaseRunner split("porous/porousWall");
  makeCoarsePorousWall(split, "0.05");
  ASSERT_EQ(split.sample(), 0);
  ASSERT_EQ(split.solve("-threads 2"), 0) << split.read("log.poroSph");
  split.setKey("system/controlDict", "endTime", "0.1");
  std::filesystem::remove(split.dir() / "log.poroSph");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph");

  const ParticleSystem a = straight.particles("0.1", 0.02);
  const ParticleSystem b = split.particles("0.1", 0.02);
  expectIdentical(*a.find("fluid"), *b.find("fluid"));
  expectIdentical(*a.find("porousWall"), *b.find("porousWall"));
  EXPECT_NE(split.read("case.pvd").find("0.1/porous.vtp"), std::string::npos);
}

/// The sinking sphere at r = 3 cm with a second, stiff and inelastic material (a stone above the water): the two
/// materials' sets have different fields (only the elastic one has rotations).
void addStone(CaseRunner& runner) {
  runner.setKey("system/particleDict", "particleRadius", "0.03");
  runner.replace("system/particleDict", "min: [-0.001, -0.001, -0.001]", "min: [-0.003, -0.003, -0.003]");
  runner.replace("system/particleDict", "max: [0.601, 0.8, 0.601]", "max: [0.603, 0.8, 0.603]"); // 0.1 r off
  runner.replace("system/particleDict", "  - name: tank\n",
                 "  - name: stone\n"
                 "    phase: porous\n"
                 "    material: stone\n"
                 "    shape: box\n"
                 "    min: [0.03, 0.45, 0.03]\n"
                 "    max: [0.15, 0.57, 0.15]\n"
                 "  - name: tank\n");
  runner.write("constant/porosityProperties", runner.read("constant/porosityProperties") +
                                                  "stone:\n  porosity: 0.3\n  bulkDensity: 1800\n"
                                                  "  compressible: false\n");
  runner.setKey("system/controlDict", "writeInterval", "0.01");
}

/// Continues `runner` to `endTime`, with or without `preset: paper`, and reads that time's particles.
ParticleSystem continueTo(CaseRunner& runner, const std::string& endTime, bool preset) {
  const std::string solverDict = runner.read("system/solverDict");
  const std::string block = "compatibility:\n  preset: paper\n";
  const auto at = solverDict.find(block);
  if (preset && at == std::string::npos) runner.write("system/solverDict", solverDict + block);
  if (!preset && at != std::string::npos) runner.write("system/solverDict", solverDict.substr(0, at));
  runner.setKey("system/controlDict", "endTime", endTime);
  std::filesystem::remove(runner.dir() / "log.poroSph");
  EXPECT_EQ(runner.solve("-threads 2"), 0) << runner.read("log.poroSph");
  return runner.particles(endTime, 0.03);
}

// Two porous materials with different models share porous.vtp (it failed to write before), and a run switched
// between the wall contact of every skeleton (PoroSPH's default) and the preset's, which has none for these
// incompressible ones, continues either way (it stopped on a field the preset's sets lacked before).
TEST(Restart, PorousMaterialsOfDifferentModelsRestartUnderAnotherPreset) {
  CaseRunner runner("porous/sinkingSphere");
  addStone(runner);
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");

  const ParticleSystem paper = continueTo(runner, "0.02", true);
  ASSERT_TRUE(paper.find("pumice") && paper.find("stone"));
  EXPECT_FALSE(paper.find("pumice")->has(field::contactPressure)) << "the preset: no contact";
  for (const Mat3& r : paper.find("stone")->mat3(field::rotation)) EXPECT_TRUE(r.isZero()) << "written as zeros";
  for (const Mat3& r : paper.find("pumice")->mat3(field::rotation)) EXPECT_NEAR(r.determinant(), 1.0, 1e-9);

  const ParticleSystem defaults = continueTo(runner, "0.04", false);
  for (const char* name : {"pumice", "stone"}) {
    const auto& limits = defaults.find(name)->real(field::wallContactLimit);
    ASSERT_FALSE(limits.empty()) << name;
    EXPECT_TRUE(std::all_of(limits.begin(), limits.end(), [](double d) { return d > 0.0; }))
        << name << ": every limit set at the first step with the contact";
  }

  const ParticleSystem again = continueTo(runner, "0.06", true);
  EXPECT_FALSE(again.find("pumice")->has(field::contactPressure)) << "dropped with the preset";
  EXPECT_EQ(again.find("stone")->size(), paper.find("stone")->size());
}

void addPaddle(CaseRunner& runner) {
  // A wall moving into the water from the far side, stopping inside the restart interval.
  runner.replace("system/particleDict", "    layers: 2\n",
                 "    layers: 2\n"
                 "  - name: paddle\n"
                 "    phase: boundary\n"
                 "    shape: box\n"
                 "    min: [0.3, -0.0005, -0.0005]\n"
                 "    max: [0.34, 0.2, 0.0405]\n"
                 "    motion:\n"
                 "      table:\n"
                 "        - {time: 0.02, displacement: [0, 0, 0]}\n"
                 "        - {time: 0.07, displacement: [-0.05, 0, 0]}\n");
}

TEST(Restart, MovingWallRunRestartsBitForBit) {
  // A paddle pushes into the dam break; the restart reads it displaced from 0.05/boundary.vtp.
  CaseRunner straight("fluid/damBreak");
  makeSmallDamBreak(straight, "0.1");
  addPaddle(straight);
  ASSERT_EQ(straight.sample(), 0) << straight.read("log.sampleParticles");
  ASSERT_EQ(straight.solve("-threads 2"), 0) << straight.read("log.poroSph");

  CaseRunner split("fluid/damBreak");
  makeSmallDamBreak(split, "0.05");
  addPaddle(split);
  ASSERT_EQ(split.sample(), 0);
  ASSERT_EQ(split.solve("-threads 2"), 0) << split.read("log.poroSph");
  split.setKey("system/controlDict", "endTime", "0.1");
  std::filesystem::remove(split.dir() / "log.poroSph");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph");

  const ParticleSystem a = straight.particles("0.1", 0.005);
  const ParticleSystem b = split.particles("0.1", 0.005);
  expectIdentical(*a.find("fluid"), *b.find("fluid"));
  expectIdentical(*a.find("boundary"), *b.find("boundary"));
  // Every time directory holds the walls where they were, and case.pvd lists them for ParaView.
  EXPECT_TRUE(std::filesystem::exists(split.dir() / "0.05" / "boundary.vtp"));
  EXPECT_NE(split.read("case.pvd").find("0.1/boundary.vtp"), std::string::npos);
}

void addTurningPaddle(CaseRunner& runner) {
  // A blade turning about the tank's depth axis (z) while its axis slides along x, from 0.02 s to 0.09 s: the
  // restart reads it turned and displaced from 0.05/boundary.vtp and places it again from its rest positions.
  runner.replace("system/particleDict", "    layers: 2\n",
                 "    layers: 2\n"
                 "  - name: blade\n"
                 "    phase: boundary\n"
                 "    shape: box\n"
                 "    min: [0.22, 0.06, -0.0005]\n"
                 "    max: [0.34, 0.1, 0.0405]\n"
                 "    motion:\n"
                 "      angularVelocity: [0, 0, -20]\n"
                 "      origin: [0.28, 0.08, 0]\n"
                 "      velocity: [0.2, 0, 0]\n"
                 "      startTime: 0.02\n"
                 "      endTime: 0.09\n");
}

TEST(Restart, TurningWallRunRestartsBitForBit) {
  // As MovingWallRunRestartsBitForBit, with a wall that turns and translates.
  CaseRunner straight("fluid/damBreak");
  makeSmallDamBreak(straight, "0.1");
  addTurningPaddle(straight);
  ASSERT_EQ(straight.sample(), 0) << straight.read("log.sampleParticles");
  EXPECT_NE(straight.read("log.sampleParticles").find("turning"), std::string::npos);
  ASSERT_EQ(straight.solve("-threads 2"), 0) << straight.read("log.poroSph");

  CaseRunner split("fluid/damBreak");
  makeSmallDamBreak(split, "0.05");
  addTurningPaddle(split);
  ASSERT_EQ(split.sample(), 0);
  ASSERT_EQ(split.solve("-threads 2"), 0) << split.read("log.poroSph");
  split.setKey("system/controlDict", "endTime", "0.1");
  std::filesystem::remove(split.dir() / "log.poroSph");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph");

  const ParticleSystem a = straight.particles("0.1", 0.005);
  const ParticleSystem b = split.particles("0.1", 0.005);
  expectIdentical(*a.find("fluid"), *b.find("fluid"));
  expectIdentical(*a.find("boundary"), *b.find("boundary"));
  // The blade did turn: 20 rad/s for 0.07 s, 1.4 rad clockwise about z. Its particle farthest along +x at rest
  // (x = 0.335, y = 0.065 .. 0.095) is now below and left of the axis.
  const ParticleSet& walls = *b.find("boundary");
  const auto& rest = walls.vec3(field::restPosition);
  std::size_t turned = 0;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    if (walls.integer(field::objectId)[k] != 2) continue; // regions: column, tank, blade
    const Vec3 r0 = rest[k] - Vec3(0.28, 0.08, 0), r = walls.x()[k] - Vec3(0.28 + 0.014, 0.08, 0);
    const double angle = std::atan2(r0.x() * r.y() - r0.y() * r.x(), r0.x() * r.x() + r0.y() * r.y());
    ASSERT_NEAR(angle, -1.4, 1e-9) << k;
    ++turned;
  }
  EXPECT_GT(turned, 0u);
}

void makeSmallSeep(CaseRunner& runner, const std::string& endTime) {
  // A water column landing on an elastic soil block that settles on the floor; CFL steps that change every step.
  runner.setKey("system/particleDict", "particleRadius", "0.025");
  runner.replace("system/particleDict", "min: [-0.48, 1.07, -0.48]", "min: [-0.2, 0.53, -0.2]");
  runner.replace("system/particleDict", "max: [0.48, 2.05, 0.48]", "max: [0.2, 0.93, 0.2]");
  runner.replace("system/particleDict", "min: [-0.48, 0.035, -0.48]", "min: [-0.2, 0.035, -0.2]");
  runner.replace("system/particleDict", "max: [0.48, 1.015, 0.48]", "max: [0.2, 0.5, 0.2]");
  runner.replace("system/controlDict", "adjustTimeStep: false",
                 "adjustTimeStep: true\nmaxCourant: 0.05\nmaxDeltaT: 0.002");
  runner.setKey("system/controlDict", "endTime", endTime);
  runner.setKey("system/controlDict", "writeInterval", "0.1");
  // Every switch at its alternative: a^p of the step before and its step size join the state.
  runner.replace("system/solverDict", "  preset: paper", "  preset: reference\n  pressureWarmStartCap: reference");
  runner.write("system/solverDict", runner.read("system/solverDict") + "neighbourSearch:\n  sortInterval: 7\n");
}

TEST(Restart, ElasticBodyInReferenceModeRestartsBitForBit) {
  // The elastic block's rest state is rebuilt from X and its rotations warm-start from R; setSequential needs
  // the lagged a^p of the compressed block, the capped warm start the step size before.
  CaseRunner straight("published/seep");
  makeSmallSeep(straight, "0.3");
  ASSERT_EQ(straight.sample(), 0) << straight.read("log.sampleParticles");
  ASSERT_EQ(straight.solve("-threads 2"), 0) << straight.read("log.poroSph");

  CaseRunner split("published/seep");
  makeSmallSeep(split, "0.2");
  ASSERT_EQ(split.sample(), 0);
  ASSERT_EQ(split.solve("-threads 2"), 0) << split.read("log.poroSph");
  split.setKey("system/controlDict", "endTime", "0.3");
  std::filesystem::remove(split.dir() / "log.poroSph");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph");

  const ParticleSystem a = straight.particles("0.3", 0.025);
  const ParticleSystem b = split.particles("0.3", 0.025);
  expectIdentical(*a.find("fluid"), *b.find("fluid"));
  expectIdentical(*a.find("soil"), *b.find("soil"));
  // What the restart has to carry is in play at the restart: the step size changes there, the block is
  // compressed, its a^p is saved, and it has deformed.
  const RunState state = readRunState(split.dir() / "0.2");
  EXPECT_GT(state.lastDeltaT, 0.0);
  EXPECT_NE(state.lastDeltaT, state.nextDeltaT);
  const ParticleSystem atRestart = split.particles("0.2", 0.025);
  const ParticleSet& block = *atRestart.find("soil");
  const auto& pi = block.real(field::pi);
  EXPECT_GT(*std::max_element(pi.begin(), pi.end()), 0.0);
  ASSERT_TRUE(block.has(field::accelP));
  const auto& accel = block.vec3(field::accelP);
  EXPECT_GT(
      std::max_element(accel.begin(), accel.end(), [](const Vec3& a, const Vec3& b) { return a.norm() < b.norm(); })
          ->norm(),
      0.0);
  const auto& x = block.x();
  const auto& rest = block.vec3(field::restPosition);
  double spread = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) spread = std::max(spread, ((x[i] - rest[i]) - (x[0] - rest[0])).norm());
  EXPECT_GT(spread, 1e-5);
}

/// The small valid case of the bad-input corpus (ascii particle files).
const CaseSource kBaseCase{std::filesystem::path(POROSPH_BAD_INPUTS) / "base"};

/// Samples and runs the base case for its three steps, then sets a later endTime for the restart.
void runThreeSteps(CaseRunner& runner) {
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");
  ASSERT_EQ(runner.solve("-threads 1"), 0) << runner.read("log.poroSph");
  runner.setKey("system/controlDict", "endTime", "0.005");
}

TEST(Restart, WithoutZeroTheMissingStaticWallsAreNamed) {
  // The tank stands still, so its walls live in 0/boundary.vtp only; with 0/ deleted the restart from 0.003
  // used to blame 0.003/boundary.vtp ("the time directory is incomplete").
  CaseRunner runner(kBaseCase);
  ASSERT_NO_FATAL_FAILURE(runThreeSteps(runner));
  std::filesystem::remove_all(runner.dir() / "0");
  EXPECT_EQ(runner.solve("-threads 1"), 1);
  const std::string log = runner.read("log.poroSph");
  const std::string dir = runner.dir().string();
  EXPECT_NE(log.find("--> PoroSPH FATAL input error:\n" + dir + "/0: no such directory, but " + dir +
                     "/system/particleDict:18 samples boundary region 'tank'. Walls that do not move are written "
                     "once, to 0/boundary.vtp, not to later time directories such as 0.003/, so without it the run "
                     "would have no walls. Restore 0/, or run sampleParticles again"),
            std::string::npos)
      << log;
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0.003");
}

TEST(Restart, SamplingAgainOverARunSaysWhatItLeaves) {
  // A new 0/ under the times of a run before it: they are kept (never lose data), but a run with startFrom
  // latestTime would continue them and saturationAnalysis read them, so sampleParticles says so.
  CaseRunner runner(kBaseCase);
  ASSERT_NO_FATAL_FAILURE(runThreeSteps(runner));
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");
  const std::string log = runner.read("log.sampleParticles");
  EXPECT_NE(log.find("holds 3 time directories after 0/ (0.001 ... 0.003) from before this sampling"),
            std::string::npos)
      << log;
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0.003");
}

/// Replaces the first x coordinate of an ascii particle file's Points.
void moveFirstParticle(CaseRunner& runner, const std::string& file, const std::string& x) {
  std::string text = runner.read(file);
  const auto points = text.find("Name=\"Points\"");
  ASSERT_NE(points, std::string::npos) << file;
  const auto first = text.find_first_not_of(" \n", text.find('>', points) + 1);
  text.replace(first, text.find(' ', first) - first, x);
  runner.write(file, text);
}

TEST(Restart, AParticleOutsideTheDomainInARestartFileIsNamedAsInputDamage) {
  // A particle 1000 km away in 0.003/fluid.vtp used to stop the first step's neighbour search with "particles
  // are leaving the domain (reduce deltaT ...)" instead of being removed by health.leavingDomain remove.
  CaseRunner runner(kBaseCase);
  ASSERT_NO_FATAL_FAILURE(runThreeSteps(runner));
  ASSERT_NO_FATAL_FAILURE(moveFirstParticle(runner, "0.003/fluid.vtp", "1e6"));
  EXPECT_EQ(runner.solve("-threads 1"), 1);
  const std::string log = runner.read("log.poroSph");
  EXPECT_NE(
      log.find("--> PoroSPH FATAL input error:\n" + runner.dir().string() + "/0.003/fluid.vtp: 1 fluid particle: id "),
      std::string::npos)
      << log;
  EXPECT_NE(log.find(" at (1e+06, "), std::string::npos) << log;
  EXPECT_NE(log.find("outside the domain (-0.5, -0.5, -0.5) - (0.7, 0.82, 0.7), the walls' bounding box grown by "
                     "its longest side, at the start (time 0.003 s, step 3)"),
            std::string::npos)
      << log;
  EXPECT_EQ(log.find("reduce deltaT"), std::string::npos) << log;
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0.003");
}

} // namespace
} // namespace poro::test
