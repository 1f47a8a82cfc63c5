// A long run can be steered and survives what goes wrong: system/controlDict edited while it runs
// (runTimeModifiable), a NaN (the health checks of solverDict), and a write that fails (a full disk).

#include "CaseRunner.hpp"
#include "io/ParticleVtk.hpp"
#include "physics/FieldNames.hpp"

#include <algorithm>

#include <sys/resource.h>

#include <csignal>
#include <cstdlib>

namespace poro::test {
namespace {

constexpr double kDt = 0.001; // the hydrostatic tank's fixed step

/// The hydrostatic tank at r = 2 cm: 1,250 fluid particles, about a millisecond per step.
void makeCoarseTank(CaseRunner& runner, const std::string& endTime, const std::string& writeInterval) {
  runner.setKey("system/particleDict", "particleRadius", "0.02");
  runner.replace("system/particleDict", "min: [-0.001, -0.001, -0.001]", "min: [-0.002, -0.002, -0.002]"); // 0.1 r
  runner.replace("system/particleDict", "max: [0.401, 0.7, 0.401]", "max: [0.402, 0.7, 0.402]");
  runner.setKey("system/controlDict", "endTime", endTime);
  runner.setKey("system/controlDict", "writeInterval", writeInterval);
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");
}

/// The last step the log reports as done ("Time = ...  (step N)").
long long lastLoggedStep(const std::string& log) {
  const std::string tag = "  (step ";
  const auto at = log.rfind(tag);
  return at == std::string::npos ? -1 : std::atoll(log.c_str() + at + tag.size());
}

/// Stops a running solver and waits until it has stopped (a signal is delivered asynchronously).
void pause(pid_t pid) {
  ::kill(pid, SIGSTOP);
  int status = 0;
  ::waitpid(pid, &status, WUNTRACED);
}

/// Starts the solver (one thread), lets it pass step `step` and pauses it with SIGSTOP; returns its pid.
pid_t startAndPause(const CaseRunner& runner, long long step) {
  const pid_t pid = runner.startSolver("1");
  for (int wait = 0; wait < 6000 && lastLoggedStep(runner.read("log.poroSph")) < step; ++wait) ::usleep(10000);
  pause(pid);
  return pid;
}

/// Resumes a paused solver and waits for it; returns its exit code (-1 if it did not exit normally).
int resumeAndWait(pid_t pid) {
  ::kill(pid, SIGCONT);
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool hasTime(const std::vector<TimeDirectoryEntry>& times, double t) {
  for (const auto& entry : times)
    if (std::abs(entry.time - t) < 1e-9) return true;
  return false;
}

TEST(RunTimeModifiable, EndTimeAndWriteIntervalTakeEffectWhileRunning) {
  CaseRunner runner("fluid/hydrostaticTank");
  makeCoarseTank(runner, "100", "50");
  const pid_t pid = startAndPause(runner, 5);
  const long long n = lastLoggedStep(runner.read("log.poroSph"));
  ASSERT_GE(n, 5);
  const double end = static_cast<double>(n + 10) * kDt;
  runner.setKey("system/controlDict", "endTime", std::to_string(end));
  runner.setKey("system/controlDict", "writeInterval", "0.002");
  const int code = resumeAndWait(pid);
  const std::string log = runner.read("log.poroSph");
  ASSERT_EQ(code, 0) << log;
  EXPECT_NE(log.find("system/controlDict changed (runTimeModifiable):\n  endTime 100 -> "), std::string::npos) << log;
  EXPECT_NE(log.find("writeInterval 50 -> 0.002"), std::string::npos) << log;
  const auto times = listTimeDirectories(runner.dir());
  EXPECT_NEAR(times.back().time, end, 1e-9);
  std::string names;
  for (const auto& t : times) names += t.name + " ";
  for (long long k = n + 2; k <= n + 10; ++k) {
    if (k % 2) continue;
    EXPECT_TRUE(hasTime(times, static_cast<double>(k) * kDt)) << "step " << k << " (n = " << n << "): " << names;
  }
}

TEST(CaseLock, SamplingACaseWhilePoroSphRunsOnItIsRefusedAndTheRunGoesOn) {
  // sampleParticles would rewrite 0/ and case.pvd under a running solver (io/CaseLock.hpp).
  CaseRunner runner("fluid/hydrostaticTank");
  makeCoarseTank(runner, "0.02", "0.01");
  const pid_t pid = startAndPause(runner, 5);
  EXPECT_EQ(runner.sample(), 1);
  const std::string refused = runner.read("log.sampleParticles");
  EXPECT_NE(refused.find("another program is writing this case (poroSph, pid " + std::to_string(pid) + ")"),
            std::string::npos)
      << refused;
  ASSERT_EQ(resumeAndWait(pid), 0) << runner.read("log.poroSph");
  EXPECT_TRUE(hasTime(listTimeDirectories(runner.dir()), 0.02));
  EXPECT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles"); // the lock went with the solver
}

TEST(RunTimeModifiable, StopAtWriteNowEndsTheRunWritten) {
  CaseRunner runner("fluid/hydrostaticTank");
  makeCoarseTank(runner, "100", "50");
  const pid_t pid = startAndPause(runner, 5);
  const long long n = lastLoggedStep(runner.read("log.poroSph"));
  runner.write("system/controlDict", runner.read("system/controlDict") + "stopAt: writeNow\n");
  const int code = resumeAndWait(pid);
  const std::string log = runner.read("log.poroSph");
  ASSERT_EQ(code, 0) << log;
  EXPECT_NE(log.find("stopAt in system/controlDict: stopped after step"), std::string::npos) << log;
  EXPECT_NE(log.find("which is written"), std::string::npos) << log;
  const double last = listTimeDirectories(runner.dir()).back().time;
  EXPECT_TRUE(std::abs(last - n * kDt) < 1e-9 || std::abs(last - (n + 1) * kDt) < 1e-9) << last;
}

TEST(RunTimeModifiable, AnInvalidEditIsReportedAndTheRunGoesOn) {
  CaseRunner runner("fluid/hydrostaticTank");
  makeCoarseTank(runner, "100", "50");
  const pid_t pid = startAndPause(runner, 5);
  runner.setKey("system/controlDict", "endTime", "-3");
  ::kill(pid, SIGCONT);
  for (int wait = 0; wait < 6000 && runner.read("log.poroSph").find("is not valid") == std::string::npos; ++wait)
    ::usleep(10000);
  pause(pid);
  const std::string log = runner.read("log.poroSph");
  EXPECT_NE(log.find("system/controlDict changed but is not valid; the run goes on"), std::string::npos) << log;
  EXPECT_NE(log.find("system/controlDict:4: key 'endTime'"), std::string::npos) << log;
  runner.setKey("system/controlDict", "endTime", "100");
  runner.write("system/controlDict", runner.read("system/controlDict") + "stopAt: noWriteNow\n");
  EXPECT_EQ(resumeAndWait(pid), 0) << runner.read("log.poroSph");
  EXPECT_NE(runner.read("log.poroSph").find("which is not written"), std::string::npos);
}

TEST(Health, InjectedNaNStopsWithTheLastFiniteStateWrittenAndTheRunResumes) {
  // NaN in step 25: exit 1, the state of step 24 is written, and continuing from it (startFrom latestTime,
  // as the tutorial has) reaches bit for bit the state of a run that never failed.
  CaseRunner straight("fluid/hydrostaticTank");
  makeCoarseTank(straight, "0.05", "0.01");
  ASSERT_EQ(straight.solve("-threads 1"), 0) << straight.read("log.poroSph");

  CaseRunner runner("fluid/hydrostaticTank");
  makeCoarseTank(runner, "0.05", "0.01");
  ::setenv("POROSPH_INJECT_NAN_STEP", "25", 1);
  const int code = runner.solve("-threads 1");
  ::unsetenv("POROSPH_INJECT_NAN_STEP");
  const std::string log = runner.read("log.poroSph");
  EXPECT_EQ(code, 1) << log;
  EXPECT_NE(log.find("--> PoroSPH FATAL numerical error:\nstep 25 (time 0.025 s, deltaT 0.001 s): NaN or infinite "
                     "position or velocity in 1 fluid particle: id "),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("reduce deltaT (now 0.001 s) in system/controlDict"), std::string::npos) << log;
  EXPECT_NE(log.find("The state at time 0.024 (step 24) is written as a time directory."), std::string::npos) << log;
  const ParticleSystem lastGood = runner.particles("0.024", 0.02);
  for (const Vec3& x : lastGood.find("fluid")->x()) ASSERT_TRUE(x.allFinite());
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0.024");

  std::filesystem::remove(runner.dir() / "log.poroSph");
  ASSERT_EQ(runner.solve("-threads 1"), 0) << runner.read("log.poroSph");
  const ParticleSystem a = straight.particles("0.05", 0.02);
  const ParticleSystem b = runner.particles("0.05", 0.02);
  EXPECT_TRUE(a.find("fluid")->x() == b.find("fluid")->x());
  EXPECT_TRUE(a.find("fluid")->v() == b.find("fluid")->v());
}

TEST(Health, WaterSampledTooCloseToTheWallsIsRefusedBeforeStep1) {
  // The tank's 1 mm wall offset is 0.05 r at r = 2 cm (0.056 r between particles: the walls split the tank's
  // 0.402 m into 11 equal steps, off the water's lattice): the water starts at rho/rho^max 1.02, which the first
  // pressure solve would blow apart (2.2 m/s at deltaT = 1 ms, 314 m/s at 1e-5 s) without a word.
  CaseRunner runner("fluid/hydrostaticTank");
  runner.setKey("system/particleDict", "particleRadius", "0.02");
  runner.setKey("system/controlDict", "endTime", "0.01");
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");
  const std::string sampling = runner.read("log.sampleParticles");
  EXPECT_NE(sampling.find("region water: smallest gap to the walls 0.056 r (0.00112 m), to region tank"),
            std::string::npos)
      << sampling;
  EXPECT_NE(sampling.find("Warning: " + runner.dir().string() + "/system/particleDict:"), std::string::npos)
      << sampling;
  EXPECT_EQ(runner.solve("-threads 1"), 1);
  const std::string log = runner.read("log.poroSph");
  EXPECT_NE(log.find("Densest particles at the start (rho / rho^max; health.startDensity 1.005): fluid 1.0"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("--> PoroSPH FATAL input error:\n" + runner.dir().string() + "/0/fluid.vtp: "), std::string::npos)
      << log;
  EXPECT_NE(log.find(" fluid particles start denser than health.startDensity = 1.005 allows"), std::string::npos)
      << log;
  EXPECT_NE(log.find("Leave a gap of 0.1 r or more"), std::string::npos) << log;
  EXPECT_EQ(log.find("Time = "), std::string::npos) << "a step was done:\n" << log;
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0");

  // The cure the message gives: 0.1 r.
  makeCoarseTank(runner, "0.002", "0.001");
  std::filesystem::remove(runner.dir() / "log.poroSph");
  EXPECT_EQ(runner.solve("-threads 1"), 0) << runner.read("log.poroSph");
}

/// Runs the solver with files limited to `bytes` (RLIMIT_FSIZE, SIGXFSZ ignored): writes beyond it fail with
/// EFBIG as on a full disk, for root too. Returns the exit code.
int solveWithFileSizeLimit(const CaseRunner& runner, rlim_t bytes) {
  const std::string log = (runner.dir() / "log.poroSph").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const rlimit limit{bytes, bytes};
    std::signal(SIGXFSZ, SIG_IGN);
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) std::_Exit(126);
    std::FILE* out = std::freopen(log.c_str(), "w", stdout);
    if (!out || ::dup2(::fileno(stdout), 2) < 0) std::_Exit(127);
    ::execl(POROSPH_SOLVER, POROSPH_SOLVER, "-case", runner.dir().c_str(), "-threads", "1", nullptr);
    std::_Exit(127);
  }
  int status = 0;
  if (::waitpid(pid, &status, 0) != pid) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(OutputErrors, AFullDiskStopsTheRunAndKeepsEarlierTimes) {
  CaseRunner runner("fluid/hydrostaticTank");
  makeCoarseTank(runner, "0.02", "0.01");
  ASSERT_EQ(runner.solve("-threads 1"), 0) << runner.read("log.poroSph");
  runner.setKey("system/controlDict", "endTime", "0.04");
  // Room for the log, not for a fluid.vtp.
  const auto vtpBytes = std::filesystem::file_size(runner.dir() / "0.02" / "fluid.vtp");
  ASSERT_GT(vtpBytes, 40000u);
  const int code = solveWithFileSizeLimit(runner, 20000);
  const std::string log = runner.read("log.poroSph");
  EXPECT_EQ(code, 1) << log;
  EXPECT_NE(log.find("--> PoroSPH FATAL output error:"), std::string::npos) << log;
  EXPECT_NE(log.find("fluid.vtp"), std::string::npos) << log;
  EXPECT_NE(log.find("Earlier time directories are intact"), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(runner.dir() / ".0.03.tmp")) << "the partial directory is left behind";
  EXPECT_FALSE(std::filesystem::exists(runner.dir() / "0.03"));
  const std::string pvd = runner.read("case.pvd");
  EXPECT_NE(pvd.find("0.02/fluid.vtp"), std::string::npos) << pvd;
  EXPECT_EQ(pvd.find("0.03"), std::string::npos) << pvd;
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0.02");

  ASSERT_EQ(runner.solve("-threads 1"), 0) << runner.read("log.poroSph"); // space again: it continues
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0.04");
}

TEST(OutputErrors, AnUnfinishedDirectoryOfAKilledRunIsRemovedAtTheNextStart) {
  // SIGKILL (or SIGXFSZ, the default action at a file-size limit) cannot be caught: the run leaves its
  // `.<time>.tmp`, which never counts as a time directory, and the next start removes it.
  CaseRunner runner("fluid/hydrostaticTank");
  makeCoarseTank(runner, "0.01", "0.01");
  std::filesystem::create_directories(runner.dir() / ".0.03.tmp" / "uniform");
  runner.write(".0.03.tmp/fluid.vtp", "<VTKFile");
  EXPECT_EQ(listTimeDirectories(runner.dir()).back().name, "0");
  ASSERT_EQ(runner.solve("-threads 1"), 0) << runner.read("log.poroSph");
  EXPECT_FALSE(std::filesystem::exists(runner.dir() / ".0.03.tmp"));
  EXPECT_NE(runner.read("log.poroSph").find(".0.03.tmp: removed an unfinished time directory"), std::string::npos);
}

TEST(OutputAtTimeZero, HoldsEveryArrayOfALaterTime) {
  // ParaView builds its array list from the first time it opens: 0/ as sampled held positions and velocities
  // only, so density, pressure and saturation could not be chosen at t = 0 and colouring set up there broke.
  CaseRunner runner(CaseSource{POROSPH_BAD_INPUTS "/base"});
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");
  ASSERT_EQ(runner.solve(), 0) << runner.read("log.poroSph");
  const auto times = listTimeDirectories(runner.dir());
  ASSERT_GE(times.size(), 2u);
  for (const auto& [file, kind] : {std::pair{"fluid.vtp", SetKind::Fluid}, std::pair{"porous.vtp", SetKind::Porous}}) {
    ParticleSet atStart("start", kind), atEnd("end", kind);
    auto first = readParticleSet(atStart, runner.dir() / "0" / file);
    auto last = readParticleSet(atEnd, runner.dir() / times.back().name / file);
    std::sort(first.begin(), first.end());
    std::sort(last.begin(), last.end());
    EXPECT_EQ(first, last) << file;
    // The start's densities are computed, not placeholders: rho / rho^max of a sampled lattice is about 1.
    const auto& rho = atStart.real(field::density);
    ASSERT_FALSE(rho.empty());
    EXPECT_GT(*std::min_element(rho.begin(), rho.end()), 100.0) << file;
  }
  // The static walls and the record of what was sampled stay in 0/, and a restart from 0/ still runs.
  EXPECT_TRUE(std::filesystem::exists(runner.dir() / "0" / "boundary.vtp"));
  EXPECT_TRUE(std::filesystem::exists(runner.dir() / "0" / "uniform" / "sampling"));
  // A run from the rewritten 0/ takes controlDict's deltaT, not the step 0/uniform/time recorded.
  runner.setKey("system/controlDict", "startFrom", "startTime");
  runner.setKey("system/controlDict", "deltaT", "0.0005");
  std::filesystem::remove(runner.dir() / "log.poroSph");
  EXPECT_EQ(runner.solve(), 0) << runner.read("log.poroSph");
  EXPECT_NE(runner.read("log.poroSph").find("deltaT = 0.0005 "), std::string::npos) << runner.read("log.poroSph");
}

TEST(OutputAtTimeZero, AnEditedFixedBoxAppliesAtTheNextRunFromZero) {
  // The rewritten 0/ stores the Fixed flags a material's fixedBox added; they must not stick to the particles
  // once the fixedBox is removed (sampledFixed keeps the flags as sampled).
  CaseRunner runner(CaseSource{POROSPH_BAD_INPUTS "/base"});
  runner.replace("system/particleDict", "    fixed: true", "    fixed: false");
  const std::string materials = runner.read("constant/porosityProperties");
  runner.write("constant/porosityProperties", materials + "  fixedBox: {min: [-1, -1, -1], max: [2, 2, 2]}\n");
  // The block rests on the floor in lattice contact; held, it is not judged, free it would be refused.
  runner.write("system/solverDict", runner.read("system/solverDict") + "health:\n  startDensity: 2\n");
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");
  ASSERT_EQ(runner.solve(), 0) << runner.read("log.poroSph");
  const auto fixedCount = [&](const std::string& time) {
    ParticleSet set("soil", SetKind::Porous);
    readParticleSet(set, runner.dir() / time / "porous.vtp");
    const auto& fixed = set.integer(field::fixed);
    return std::count(fixed.begin(), fixed.end(), 1);
  };
  EXPECT_EQ(fixedCount("0"), 75);
  runner.write("constant/porosityProperties", materials);
  runner.setKey("system/controlDict", "startFrom", "startTime");
  ASSERT_EQ(runner.solve(), 0) << runner.read("log.poroSph");
  EXPECT_EQ(fixedCount("0"), 0);
  EXPECT_EQ(fixedCount("0.003"), 0);
}

} // namespace
} // namespace poro::test
