#include "io/SolverPerformanceLog.hpp"

#include "core/Log.hpp"
#include "io/OutputDirectory.hpp"

#include <cerrno>
#include <cstring>

namespace poro {

namespace fs = std::filesystem;

const std::vector<std::string>& SolverPerformanceLog::phaseColumns() {
  static const std::vector<std::string> phases{"search",    "densities", "implicit", "pressure",
                                               "integrate", "health",    "output"};
  return phases;
}

SolverPerformanceLog::SolverPerformanceLog(const fs::path& caseDir, const std::string& startName,
                                           const GhostExchange* ranks)
    : file_(caseDir / "postProcessing" / "solverPerformance" / startName / "solverPerformance.csv"), ranks_(ranks),
      previous_(phaseColumns().size(), 0.0) {
  std::error_code ec;
  fs::create_directories(file_.parent_path(), ec);
  if (ec) {
    fail(whyDirectoryFails(file_.parent_path(), ec));
    return;
  }
  out_.open(file_, std::ios::trunc);
  if (!out_) {
    fail(file_.string() + ": cannot write (" + std::strerror(errno) + ")");
    return;
  }
  out_ << "step,time_s,deltaT_s,maxSpeed_m_per_s,maxFluidDensity_rho0,pressureIterations,pressureConverged,"
          "densityErrorMean_pct,densityErrorMax_pct,cgIterations,cgConverged,cgResidual";
  for (const auto& phase : phaseColumns()) out_ << ',' << phase << "_s";
  if (ranks_) out_ << ",particles,ghosts,imbalance,haloExchange_s,migration_s";
  out_ << '\n';
}

double SolverPerformanceLog::phaseSeconds(const Solver& solver, const std::string& phase) const {
  for (const auto& [name, seconds] : solver.phaseTimes().phases())
    if (name == phase) return seconds;
  return 0.0;
}

void SolverPerformanceLog::record(const Solver& solver) {
  if (failed_) return;
  const StepReport& r = solver.lastStep();
  out_.precision(10);
  out_ << solver.state().step << ',' << solver.state().time << ',' << r.deltaT << ',' << r.maxSpeed << ','
       << r.maxFluidDensity << ',' << r.pressure.iterations << ',' << r.pressure.converged << ','
       << r.pressure.meanError << ',' << r.pressure.maxError << ',' << r.implicit.iterations << ','
       << r.implicit.converged << ',' << r.implicit.relativeResidual;
  out_.precision(6);
  const auto& phases = phaseColumns();
  for (std::size_t k = 0; k < phases.size(); ++k) {
    const double total = phaseSeconds(solver, phases[k]);
    out_ << ',' << total - previous_[k];
    previous_[k] = total;
  }
  if (ranks_) {
    const GhostExchange::Load load = ranks_->load();
    out_ << ',' << load.particles << ',' << load.ghosts << ',' << load.imbalance << ','
         << load.seconds - previousExchange_ << ',' << load.migrationSeconds - previousMigration_;
    previousExchange_ = load.seconds;
    previousMigration_ = load.migrationSeconds;
  }
  out_ << '\n';
  out_.flush(); // a killed run keeps its rows
  if (!out_) fail(file_.string() + ": cannot write (" + std::strerror(errno) + ")");
}

void SolverPerformanceLog::fail(const std::string& why) {
  failed_ = true;
  log::warning(why + "; the run goes on without its solverPerformance record");
}

} // namespace poro
