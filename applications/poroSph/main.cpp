/// poroSph: the porous-flow SPH solver. Reads a case, runs it to endTime, writes time directories.

#include "ControlDictChange.hpp"
#include "ParallelRun.hpp"
#include "core/Arguments.hpp"
#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Memory.hpp"
#include "core/Parallel.hpp"
#include "core/StopSignals.hpp"
#include "io/CaseLock.hpp"
#include "io/CaseReader.hpp"
#include "io/ControlDictWatcher.hpp"
#include "io/SolverPerformanceLog.hpp"
#include "io/TimeDirectory.hpp"

#include <cstdlib>
#include <iostream>
#include <sstream>

using namespace poro;

int main(int argc, char* argv[]) try {
  memory::returnLargeBlocksToSystem();
  const Arguments args(argc, argv, "poroSph",
                       "Implicit incompressible porous flow with SPH (Boettcher et al. 2025). Runs the case\n"
                       "from its start time directory to endTime and writes time directories and case.pvd.",
                       {{"parallel", "",
                         "run a decomposed case (decomposePar) on MPI ranks: mpirun -np N poroSph -parallel; each rank "
                         "reads and writes processor<rank>/ (fluid and walls so far)"}});
  if (args.help()) {
    std::cout << args.usage();
    return 0;
  }
  if (args.has("parallel")) return runParallel(args, argc, argv);
  const CaseLock lock(args.caseDir(), "poroSph"); // before readCase: its recovery deletes unfinished output
  SimulationCase simulation = readCase(args.caseDir(), args.threads());
  if (simulation.endTimeReached) {
    log::info("Case: " + args.caseDir() + "\nThe start time directory " + simulation.startName +
              " has reached endTime " + timeName(simulation.control.endTime) +
              " (system/controlDict): nothing to run. To run further, raise endTime.\nEnd");
    return 0;
  }
  std::ostringstream banner;
  banner << "Case: " << args.caseDir() << "\nStarting from time " << simulation.startName << " with "
         << simulation.particles.particleCount() << " particles";
  log::info(banner.str());
  const bool movingWalls = !simulation.wallMotions.empty(); // rigid bodies have rigid.vtp of their own
  Solver solver(std::move(simulation.particles), simulation.fluid, std::move(simulation.materials), simulation.solver,
                simulation.control, simulation.start, std::move(simulation.wallMotions),
                std::move(simulation.rigidBodies));
  log::info("Threads: " + std::to_string(parallel::threads()) + "\nBuild: " + buildDescription());
  solver.checkStart(); // a refused start leaves case.pvd and postProcessing as they were
  TimeWriter writer(args.caseDir(), simulation.output, simulation.startName);
  writer.setMovingWalls(movingWalls);
  if (const char* step = std::getenv("POROSPH_INJECT_NAN_STEP")) { // tests the health checks end to end
    solver.injectNaN(std::atoll(step));
    log::warning(std::string("POROSPH_INJECT_NAN_STEP: one particle's velocity becomes NaN in step ") + step);
  }
  ControlDictWatcher watcher(args.caseDir());
  ControlSettings current{simulation.control, simulation.output};
  const auto rereadControlDict = [&](Solver& s) {
    if (!current.control.runTimeModifiable) return;
    if (const auto changed = watcher.poll()) applyControlDictChange(current, *changed, s, writer);
  };
  signals::installStopHandlers();
  SolverPerformanceLog performance(args.caseDir(), simulation.startName);
  const RunOutcome outcome = solver.run([&](const Solver& s) { writer.write(s.particles(), s.state()); },
                                        rereadControlDict, [&](const Solver& s) { performance.record(s); });
  return outcome.end == RunOutcome::End::Signal ? 1 : 0;
} catch (const OutputError& e) {
  log::fatal(OutputError(std::string(e.what()) +
                         "\nEarlier time directories are intact. Free disk space (or fix the permissions), then "
                         "continue with startFrom latestTime in system/controlDict."));
  return 1;
} catch (const Error& e) {
  log::fatal(e);
  return 1;
} catch (const std::exception& e) {
  log::fatal(e.what());
  return 1;
}
