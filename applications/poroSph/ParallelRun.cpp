#include "ParallelRun.hpp"

#include "ControlDictChange.hpp"
#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "core/StopSignals.hpp"
#include "io/CaseLock.hpp"
#include "io/CaseReader.hpp"
#include "io/ControlDictWatcher.hpp"
#include "io/ProcessorDirectories.hpp"
#include "io/SolverPerformanceLog.hpp"
#include "io/TimeDirectory.hpp"
#include "parallel/DecomposeSettings.hpp"
#include "parallel/mpi/Migration.hpp"
#include "parallel/mpi/RankGhosts.hpp"
#include "physics/FieldNames.hpp"

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

namespace poro {

namespace {

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Elastic sets lend by rest position too, two support radii deep: the rest neighbours of every own particle and
/// theirs (RestHalo), so a rank never lacks one, however far a body has deformed or moved.
RestHalo restHaloOf(const SimulationCase& simulation) {
  RestHalo rest{field::restPosition, std::vector<double>(simulation.particles.size(), 0.0)};
  for (std::size_t s = 0; s < simulation.particles.size(); ++s) {
    const ParticleSet& set = simulation.particles[s];
    if (set.kind() != SetKind::Porous) continue;
    for (const PorousMaterial& m : simulation.materials)
      if (m.name == set.name() && m.youngsModulus > 0.0) rest.reach[s] = 2.0 * simulation.particles.supportRadius();
  }
  return rest;
}

/// The partition of the particles of every rank, by decomposeParDict's method and weights: decomposePar's cut of the
/// same particles, so nothing moves at the start.
Partition partitionOf(const ParticleSystem& particles, const DecomposeSettings& settings, const Communicator& comm) {
  return WeightedParticles(particles, settings).cut(comm.size(), settings.method, reductionsOver(comm));
}

int runRank(const Arguments& args, const Communicator& comm) {
  const fs::path caseDir = args.caseDir();
  const std::vector<fs::path> processors = listProcessorDirectories(caseDir);
  if (processors.size() != static_cast<std::size_t>(comm.size()))
    throw InputError(caseDir.string() + ": " + std::to_string(processors.size()) + " processor directories for " +
                     std::to_string(comm.size()) + " ranks; run mpirun -np " + std::to_string(processors.size()) +
                     " (or decomposePar -force for " + std::to_string(comm.size()) + " subdomains)");
  const fs::path mine = processors[static_cast<std::size_t>(comm.rank())];
  const CaseLock lock(mine.string(), "poroSph");
  SimulationCase simulation = readCase(caseDir, args.threads(), mine);
  if (simulation.endTimeReached) {
    log::info("Case: " + caseDir.string() + "\nThe start time directory " + simulation.startName +
              " has reached endTime: nothing to run.\nEnd");
    return 0;
  }
  const DecomposeSettings settings = readDecomposeSettings(caseDir);
  std::ostringstream banner;
  banner << "Case: " << caseDir.string() << " (parallel, " << comm.size() << " ranks)\nStarting from time "
         << simulation.startName << " with " << comm.sum(static_cast<long long>(simulation.particles.particleCount()))
         << " particles";
  log::info(banner.str());
  // A restart cuts as the run it continues (the partition is written with every time), so it continues bit for bit.
  const fs::path saved = mine / simulation.startName / "uniform" / "partition";
  Partition partition = fs::exists(saved) ? Partition::parse(readText(saved), saved.string())
                                          : partitionOf(simulation.particles, settings, comm);
  if (partition.parts() != comm.size())
    throw InputError(saved.string() + ": a partition into " + std::to_string(partition.parts()) + " parts for " +
                     std::to_string(comm.size()) + " ranks");
  // Ghosts within the support radius plus the Verlet skin: the lists are searched afresh only when a particle has moved
  // half the skin since the last migration, and every pair within H until then was within H + skin at it.
  const double reach = simulation.particles.supportRadius() * (1.0 + simulation.solver.searchSkin);
  RankGhosts ghosts(comm, std::move(partition), settings, reach, restHaloOf(simulation));
  const bool movingWalls = !simulation.wallMotions.empty();
  Solver solver(std::move(simulation.particles), simulation.fluid, std::move(simulation.materials), simulation.solver,
                simulation.control, simulation.start, std::move(simulation.wallMotions),
                std::move(simulation.rigidBodies), &ghosts);
  log::info("Threads per rank: " + std::to_string(parallel::threads()) + "\nBuild: " + buildDescription());
  solver.checkStart();
  if (const char* step = std::getenv("POROSPH_INJECT_NAN_STEP"); step && comm.rank() == 0) // tests the health checks
    solver.injectNaN(std::atoll(step));
  TimeWriter writer(mine, simulation.output, simulation.startName);
  writer.setMovingWalls(movingWalls);

  SolverPerformanceLog performance(mine, simulation.startName, &ghosts);
  signals::installStopHandlers(); // kill -TERM on the ranks: every rank stops after the same step and writes it
  const auto write = [&](const Solver& s) {
    writer.setUniformFile("partition", ghosts.partition().text()); // the cut of this time (it may have changed)
    writer.write(s.particles(), s.state());
    comm.barrier(); // every piece of this time is on disk: rank 0 lists them all for ParaView
    if (comm.rank() == 0) {
      seriesOfSubdomains(processors).write(caseDir / "case.pvd");
      appendRigidBodyRows(caseDir, s.state()); // the bodies are every rank's: the case's trajectory, as a serial run's
    }
  };
  // runTimeModifiable: rank 0 looks at system/controlDict after every step and, when it changed, every rank applies
  // the text rank 0 read, so all of them change their settings after the same step.
  ControlDictWatcher watcher(caseDir);
  ControlSettings current{simulation.control, simulation.output};
  const auto rereadControlDict = [&](Solver& s) {
    if (!current.control.runTimeModifiable) return;
    const std::optional<std::string> text = comm.rank() == 0 ? watcher.changedText() : std::nullopt;
    if (comm.max(text ? 1.0 : 0.0) == 0.0) return;
    const std::optional<ControlSettings> changed = watcher.settingsOf(comm.broadcast(text.value_or("")));
    if (changed) applyControlDictChange(current, *changed, s, writer);
  };
  const RunOutcome outcome = solver.run(write, rereadControlDict, [&](const Solver& s) { performance.record(s); });
  return outcome.end == RunOutcome::End::Signal ? 1 : 0;
}

} // namespace

int runParallel(const Arguments& args, int& argc, char**& argv) {
  Communicator comm(argc, argv);
  log::setQuiet(comm.rank() != 0); // one log, rank 0's; errors are printed by the rank that meets them
  try {
    return runRank(args, comm);
  } catch (const Error& e) {
    log::fatal(e);
  } catch (const std::exception& e) {
    log::fatal(e.what());
  }
  // The other ranks wait in a collective this rank will not reach: stop them all.
  comm.abort(1);
}

} // namespace poro
