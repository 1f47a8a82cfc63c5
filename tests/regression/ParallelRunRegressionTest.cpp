// poroSph -parallel on MPI ranks (ARCHITECTURE.md "Decomposed runs"): a decomposed dam break, a porous wall, an
// elastic sponge and a floating rigid box equal the serial run to round-off on 2 and 3 ranks, a run continues bit for
// bit from a time it wrote, and a wrong number of ranks is refused by name.

#include "CaseRunner.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <sys/wait.h>
#include <unistd.h>

namespace poro::test {
namespace {

namespace fs = std::filesystem;
constexpr double kRadius = 0.005;

/// The dam break in a 4-particle slab (8,620 particles with the walls) to `endTime`, viscous so that the implicit
/// solve's CG runs on the ranks too.
void makeSmallViscousDamBreak(CaseRunner& runner, const std::string& endTime) {
  runner.replace("system/particleDict", "max: [0.2, 0.4, 0.64]", "max: [0.1, 0.2, 0.04]");
  runner.replace("system/particleDict", "max: [1.2005, 0.6005, 0.6405]", "max: [0.4005, 0.3005, 0.0405]");
  runner.setKey("system/controlDict", "endTime", endTime);
  runner.setKey("system/controlDict", "writeInterval", "0.05");
  runner.setKey("constant/fluidProperties", "viscosity", "0.5");
}

/// mpirun -np `ranks` poroSph -parallel on the case (log in log.poroSph); its exit code.
int runOnRanks(const CaseRunner& runner, int ranks) {
  const std::string root = ::geteuid() == 0 ? "--allow-run-as-root " : "";
  const std::string command = std::string(POROSPH_MPIEXEC) + " " + root + "--oversubscribe -np " +
                              std::to_string(ranks) + " '" + POROSPH_SOLVER + "' -parallel -threads 1 -case '" +
                              runner.dir().string() + "' > '" + (runner.dir() / "log.poroSph").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// How far, in spacings, a run on ranks may drift from the serial run in 0.1 s. Sums run in another order on the ranks
/// (1e-16 relative), and such a difference in a distance can flip the single-precision rounding of one of the pair
/// numbers (PairFactor, 2^-24 relative) of a step. A flip changes one pair force by 6e-8 of itself: 0.1 s of it at
/// accelerations of g moves a particle 0.5 (0.1 s)^2 6e-8 g = 3e-9 m, 1.5e-7 of a 2 cm spacing. 1e-6 allows several g
/// and is still five orders below what a missing ghost or rest halo does (0.12 to 1.4 spacings).
constexpr double kRoundOffDrift = 1e-6;

/// Largest position difference of the particles of set `name` of two systems, matched by id, over the spacing 2r.
double largestShift(const ParticleSystem& a, const ParticleSystem& b, const std::string& name = "fluid",
                    double radius = kRadius) {
  if (!a.find(name) || !b.find(name)) {
    ADD_FAILURE() << "no particle set '" << name << "'";
    return INFINITY;
  }
  const ParticleSet& fa = *a.find(name);
  const ParticleSet& fb = *b.find(name);
  EXPECT_EQ(fa.size(), fb.size());
  std::map<std::int64_t, std::size_t> slot;
  for (std::size_t i = 0; i < fb.size(); ++i) slot[fb.integer(field::id)[i]] = i;
  double worst = 0.0;
  for (std::size_t i = 0; i < fa.size(); ++i) {
    const auto at = slot.find(fa.integer(field::id)[i]);
    if (at == slot.end()) return INFINITY;
    worst = std::max(worst, (fa.x()[i] - fb.x()[at->second]).norm());
  }
  return worst / (2.0 * radius);
}

/// Runs `runner` serially and `ranks`-parallel copies of it (decomposePar, mpirun, reconstructPar) to `endTime`; the
/// largest shift of set `name` between them, per rank count, over the spacing.
std::vector<double> shiftsAgainstSerial(const std::function<void(CaseRunner&)>& makeCase, const std::string& tutorial,
                                        const std::string& endTime, const std::vector<std::string>& names) {
  CaseRunner serial(tutorial);
  makeCase(serial);
  EXPECT_EQ(serial.sample(), 0);
  EXPECT_EQ(serial.solve("-threads 1"), 0) << serial.read("log.poroSph");
  const double radius = readParticleRadius(serial.dir());
  const ParticleSystem reference = serial.particles(endTime, radius);
  std::vector<double> shifts;
  for (const auto& [ranks, method] : {std::pair<int, std::string>{2, "recursiveBisection"}, {3, "hilbertCurve"}}) {
    CaseRunner parallel(tutorial);
    makeCase(parallel);
    parallel.write("system/decomposeParDict",
                   "numberOfSubdomains: " + std::to_string(ranks) + "\nmethod: " + method + "\n");
    EXPECT_EQ(parallel.sample(), 0);
    EXPECT_EQ(parallel.run(POROSPH_DECOMPOSE), 0) << parallel.read("log.decomposePar");
    EXPECT_EQ(runOnRanks(parallel, ranks), 0) << parallel.read("log.poroSph");
    EXPECT_EQ(parallel.run(POROSPH_RECONSTRUCT, "-time " + endTime), 0) << parallel.read("log.reconstructPar");
    const ParticleSystem merged = parallel.particles(endTime, radius);
    double worst = 0.0;
    for (const std::string& name : names) worst = std::max(worst, largestShift(reference, merged, name, radius));
    std::cout << tutorial << " on " << ranks << " ranks: largest shift " << worst << " of the spacing\n";
    shifts.push_back(worst);
  }
  return shifts;
}

TEST(ParallelRun, TwoAndThreeRanksEqualTheSerialRunToRoundOff) {
  CaseRunner serial("fluid/damBreak");
  makeSmallViscousDamBreak(serial, "0.1");
  ASSERT_EQ(serial.sample(), 0);
  ASSERT_EQ(serial.solve("-threads 1"), 0) << serial.read("log.poroSph");
  const ParticleSystem reference = serial.particles("0.1", kRadius);
  for (const auto& [ranks, method] : {std::pair<int, std::string>{2, "recursiveBisection"}, {3, "hilbertCurve"}}) {
    CaseRunner parallel("fluid/damBreak");
    makeSmallViscousDamBreak(parallel, "0.1");
    parallel.write("system/decomposeParDict",
                   "numberOfSubdomains: " + std::to_string(ranks) + "\nmethod: " + method +
                       "\nrebalanceThreshold: 0.02\n"); // cut anew as the water runs from one part into another
    ASSERT_EQ(parallel.sample(), 0);
    ASSERT_EQ(parallel.run(POROSPH_DECOMPOSE), 0) << parallel.read("log.decomposePar");
    ASSERT_EQ(runOnRanks(parallel, ranks), 0) << parallel.read("log.poroSph");
    EXPECT_NE(parallel.read("log.poroSph").find("CG iterations"), std::string::npos);
    EXPECT_NE(parallel.read("log.poroSph").find("Re-partitioned"), std::string::npos);
    // ParaView opens the decomposed case: every piece of every time, the subdomains' static walls at every time.
    const std::string pvd = parallel.read("case.pvd");
    EXPECT_NE(pvd.find("processor" + std::to_string(ranks - 1) + "/0.1/fluid.vtp"), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("timestep=\"0.10000000000000001\" group=\"\" part=\"1\" name=\"boundary.processor0\" "
                       "file=\"processor0/0/boundary.vtp\""),
              std::string::npos)
        << pvd;
    ASSERT_EQ(parallel.run(POROSPH_RECONSTRUCT, "-time 0.1"), 0) << parallel.read("log.reconstructPar");
    // Round-off of sums in another order, in single-precision pair numbers now and then (kRoundOffDrift).
    EXPECT_LT(largestShift(reference, parallel.particles("0.1", kRadius)), kRoundOffDrift)
        << ranks << " ranks, " << method;
  }
}

TEST(ParallelRun, ARestartOnTheSameRanksContinuesBitForBit) {
  CaseRunner straight("fluid/damBreak");
  CaseRunner split("fluid/damBreak");
  makeSmallViscousDamBreak(straight, "0.1");
  makeSmallViscousDamBreak(split, "0.05");
  for (CaseRunner* runner : {&straight, &split}) {
    runner->write("system/decomposeParDict", "numberOfSubdomains: 2\nrebalanceThreshold: 0.02\n");
    ASSERT_EQ(runner->sample(), 0);
    ASSERT_EQ(runner->run(POROSPH_DECOMPOSE), 0) << runner->read("log.decomposePar");
    ASSERT_EQ(runOnRanks(*runner, 2), 0) << runner->read("log.poroSph");
  }
  EXPECT_TRUE(fs::exists(split.dir() / "processor1" / "0.05" / "uniform" / "partition"));
  split.setKey("system/controlDict", "endTime", "0.1");
  split.setKey("system/controlDict", "startFrom", "latestTime");
  ASSERT_EQ(runOnRanks(split, 2), 0) << split.read("log.poroSph");
  EXPECT_NE(split.read("log.poroSph").find("Starting from time 0.05"), std::string::npos);
  for (const char* piece : {"processor0/0.1/fluid.vtp", "processor1/0.1/fluid.vtp"})
    EXPECT_TRUE(straight.read(piece) == split.read(piece)) << piece << " differs";
}

TEST(ParallelRun, ACaseDecomposedFromALaterTimeKeepsItsWallsThroughRestarts) {
  // Decomposed from 0.05 s of a serial run, the subdomains have no 0/ with the static walls: each time directory the
  // ranks write must hold them, or the restart from 0.075 s ran without walls (no message, the water fell through
  // the floor).
  CaseRunner serial("fluid/damBreak");
  CaseRunner split("fluid/damBreak");
  for (CaseRunner* runner : {&serial, &split}) {
    makeSmallViscousDamBreak(*runner, "0.1");
    runner->setKey("system/controlDict", "writeInterval", "0.025");
    ASSERT_EQ(runner->sample(), 0);
  }
  ASSERT_EQ(serial.solve("-threads 1"), 0) << serial.read("log.poroSph");
  split.setKey("system/controlDict", "endTime", "0.05");
  ASSERT_EQ(split.solve("-threads 1"), 0) << split.read("log.poroSph");
  split.write("system/decomposeParDict", "numberOfSubdomains: 2\n");
  ASSERT_EQ(split.run(POROSPH_DECOMPOSE), 0) << split.read("log.decomposePar");
  EXPECT_FALSE(fs::exists(split.dir() / "processor0" / "0"));
  for (const char* endTime : {"0.075", "0.1"}) {
    split.setKey("system/controlDict", "endTime", endTime);
    ASSERT_EQ(runOnRanks(split, 2), 0) << split.read("log.poroSph");
    EXPECT_TRUE(fs::exists(split.dir() / "processor1" / endTime / "boundary.vtp")) << endTime;
  }
  EXPECT_NE(split.read("log.poroSph").find("Starting from time 0.075"), std::string::npos);
  ASSERT_EQ(split.run(POROSPH_RECONSTRUCT, "-time 0.1"), 0) << split.read("log.reconstructPar");
  EXPECT_LT(largestShift(serial.particles("0.1", kRadius), split.particles("0.1", kRadius)), kRoundOffDrift);
}

TEST(ParallelRun, ControlDictEditsTakeEffectOnEveryRankAfterTheSameStep) {
  CaseRunner runner("fluid/damBreak");
  makeSmallViscousDamBreak(runner, "5");
  runner.write("system/decomposeParDict", "numberOfSubdomains: 2\n");
  ASSERT_EQ(runner.sample(), 0);
  ASSERT_EQ(runner.run(POROSPH_DECOMPOSE), 0) << runner.read("log.decomposePar");
  const std::string root = ::geteuid() == 0 ? "--allow-run-as-root " : "";
  const std::string command = std::string(POROSPH_MPIEXEC) + " " + root + "--oversubscribe -np 2 '" + POROSPH_SOLVER +
                              "' -parallel -threads 1 -case '" + runner.dir().string() + "' > '" +
                              (runner.dir() / "log.poroSph").string() + "' 2>&1";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), nullptr);
    std::_Exit(127);
  }
  // Once the ranks are stepping, the run is told to stop and write (stopAt) and to write the time directories of the
  // steps before that no more often than every 10 s: what the ranks then write is the one time they stopped at.
  for (int wait = 0; wait < 6000 && runner.read("log.poroSph").find("  (step 5)") == std::string::npos; ++wait)
    ::usleep(10000);
  runner.setKey("system/controlDict", "writeInterval", "10");
  runner.write("system/controlDict", runner.read("system/controlDict") + "stopAt: writeNow\n");
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const std::string log = runner.read("log.poroSph");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << log;
  EXPECT_NE(log.find("system/controlDict changed (runTimeModifiable):"), std::string::npos) << log;
  EXPECT_NE(log.find("stopAt in system/controlDict: stopped after step"), std::string::npos) << log;
  const auto last = [&](const char* processor) { return listTimeDirectories(runner.dir() / processor).back().name; };
  EXPECT_EQ(last("processor0"), last("processor1"));
  EXPECT_LT(std::stod(last("processor0")), 5.0);
}

TEST(ParallelRun, RefusesTheWrongNumberOfRanksByName) {
  CaseRunner wrongRanks("fluid/damBreak");
  makeSmallViscousDamBreak(wrongRanks, "0.01");
  wrongRanks.write("system/decomposeParDict", "numberOfSubdomains: 3\n");
  ASSERT_EQ(wrongRanks.sample(), 0);
  ASSERT_EQ(wrongRanks.run(POROSPH_DECOMPOSE), 0);
  EXPECT_NE(runOnRanks(wrongRanks, 2), 0);
  EXPECT_NE(wrongRanks.read("log.poroSph").find("3 processor directories for 2 ranks"), std::string::npos)
      << wrongRanks.read("log.poroSph");
}

// The floating box of rigid/floatingBox (2,400 water and 144 box particles at r = 1 cm) drops the millimetre onto the
// water and bobs: its wrench is summed over the ranks, its mass and inertia over all of its particles.
TEST(ParallelRun, ARigidBodyOnTwoAndThreeRanksEqualsTheSerialRun) {
  const auto short100 = [](CaseRunner& runner) {
    runner.setKey("system/controlDict", "endTime", "0.1");
    runner.setKey("system/controlDict", "writeInterval", "0.05");
  };
  // Round-off grown over 100 steps, as for the sponge.
  for (const double shift : shiftsAgainstSerial(short100, "rigid/floatingBox", "0.1", {"fluid", "rigid"}))
    EXPECT_LT(shift, kRoundOffDrift);
}

/// The elastic sponge of porous/sponge at r = 2 cm (1,512 water and 162 sponge particles) to `endTime`: it falls 4 cm
/// into its bath, so elasticity, drag, capillary adhesion, the porous pressure solve and wall contact run on the
/// ranks, with the sponge's rest neighbours spread over them.
void makeCoarseSponge(CaseRunner& runner, const std::string& endTime) {
  runner.setKey("system/particleDict", "particleRadius", "0.02");
  runner.replace("system/particleDict", "min: [-0.0015, -0.0015, -0.0015]", "min: [-0.002, -0.002, -0.002]");
  runner.replace("system/particleDict", "max: [0.8415, 0.9, 0.4815]", "max: [0.842, 0.9, 0.482]"); // 0.1 r off
  runner.setKey("system/controlDict", "endTime", endTime);
  runner.setKey("system/controlDict", "writeInterval", "0.05");
}

// 100 steps at 1 ms, the last 10 after first contact.
TEST(ParallelRun, AnElasticSpongeOnTwoAndThreeRanksEqualsTheSerialRun) {
  // Sums run in another order on the ranks (round-off grown by 100 steps of a stiff body, kRoundOffDrift); 0.12 of
  // the spacing on 3 ranks without the rest halo.
  const auto coarse = [](CaseRunner& runner) { makeCoarseSponge(runner, "0.1"); };
  for (const double shift : shiftsAgainstSerial(coarse, "porous/sponge", "0.1", {"fluid", "sponge"}))
    EXPECT_LT(shift, kRoundOffDrift);
}

/// `tutorial` made by `makeCase(runner, endTime)` on 2 ranks (decomposeParDict `decompose`), once to 0.1 s and once to
/// 0.05 s and continued to 0.1 s: the pieces of 0.1 s, compared byte for byte. Returns the uninterrupted run's case.
void expectRestartBitForBit(const std::string& tutorial,
                            const std::function<void(CaseRunner&, const std::string&)>& makeCase,
                            const std::string& decompose, const std::vector<std::string>& pieces,
                            CaseRunner& straight) {
  CaseRunner split(tutorial);
  makeCase(straight, "0.1");
  makeCase(split, "0.05");
  for (CaseRunner* runner : {&straight, &split}) {
    runner->write("system/decomposeParDict", decompose);
    ASSERT_EQ(runner->sample(), 0);
    ASSERT_EQ(runner->run(POROSPH_DECOMPOSE), 0) << runner->read("log.decomposePar");
    ASSERT_EQ(runOnRanks(*runner, 2), 0) << runner->read("log.poroSph");
  }
  split.setKey("system/controlDict", "endTime", "0.1");
  split.setKey("system/controlDict", "startFrom", "latestTime");
  ASSERT_EQ(runOnRanks(split, 2), 0) << split.read("log.poroSph");
  EXPECT_NE(split.read("log.poroSph").find("Starting from time 0.05"), std::string::npos);
  for (const std::string& piece : pieces)
    for (const char* processor : {"processor0/0.1/", "processor1/0.1/"})
      EXPECT_TRUE(straight.read(processor + piece) == split.read(processor + piece))
          << processor << piece << " differs";
}

// A sponge run stopped at 0.05 s continues on its ranks bit for bit, and serially after reconstructPar to round-off.
TEST(ParallelRun, AnElasticSpongeRestartsOnItsRanksBitForBitAndSeriallyAfterReconstructPar) {
  CaseRunner straight("porous/sponge");
  expectRestartBitForBit("porous/sponge", makeCoarseSponge, "numberOfSubdomains: 2\nmethod: hilbertCurve\n",
                         {"fluid.vtp", "porous.vtp"}, straight); // a Hilbert curve cuts the sponge
  // decomposePar -> parallel run -> reconstructPar -> serial run: the serial continuation of 0.05 s against the
  // parallel run's 0.1 s.
  ASSERT_EQ(straight.run(POROSPH_RECONSTRUCT, "-time 0.1"), 0) << straight.read("log.reconstructPar");
  const double radius = readParticleRadius(straight.dir());
  const ParticleSystem parallel = straight.particles("0.1", radius);
  fs::remove_all(straight.dir() / "0.1");
  ASSERT_EQ(straight.run(POROSPH_RECONSTRUCT, "-time 0.05"), 0) << straight.read("log.reconstructPar");
  ASSERT_EQ(straight.solve("-threads 1"), 0) << straight.read("log.poroSph");
  EXPECT_NE(straight.read("log.poroSph").find("Starting from time 0.05"), std::string::npos);
  for (const char* set : {"fluid", "sponge"}) // 50 steps: round-off, as above
    EXPECT_LT(largestShift(straight.particles("0.1", radius), parallel, set, radius), kRoundOffDrift);
}

// The floating box stopped at 0.05 s continues on its ranks bit for bit: its body state and the particles.
TEST(ParallelRun, ARigidBodyRestartsOnItsRanksBitForBit) {
  CaseRunner straight("rigid/floatingBox");
  const auto makeCase = [](CaseRunner& runner, const std::string& endTime) {
    runner.setKey("system/controlDict", "endTime", endTime);
    runner.setKey("system/controlDict", "writeInterval", "0.05");
  };
  expectRestartBitForBit("rigid/floatingBox", makeCase, "numberOfSubdomains: 2\n",
                         {"fluid.vtp", "rigid.vtp", "uniform/rigidBodies"}, straight);
  // The case's own trajectory, as a serial run writes it: 0, 0.05 and 0.1 s.
  const std::string trajectory = straight.read("postProcessing/rigidBodies/box.csv");
  EXPECT_EQ(std::count(trajectory.begin(), trajectory.end(), '\n'), 4) << trajectory;
}

// The fixed porous wall of porous/porousWall at r = 2 cm, the water column moved against it so that it seeps in from
// the first step: drag and the porous pressure solve across the ranks.
TEST(ParallelRun, APorousWallOnTwoAndThreeRanksEqualsTheSerialRun) {
  const auto adjacent = [](CaseRunner& runner) {
    runner.setKey("system/particleDict", "particleRadius", "0.02");
    runner.replace("system/particleDict", "min: [0.02, 0.02, 0.02]", "min: [0.4, 0.02, 0.02]");
    runner.replace("system/particleDict", "max: [0.4, 0.82, 0.38]", "max: [0.8, 0.58, 0.38]");
    runner.setKey("system/controlDict", "endTime", "0.1");
    runner.setKey("system/controlDict", "writeInterval", "0.05");
  };
  for (const double shift : shiftsAgainstSerial(adjacent, "porous/porousWall", "0.1", {"fluid", "porousWall"}))
    EXPECT_LT(shift, kRoundOffDrift);
}

} // namespace
} // namespace poro::test
