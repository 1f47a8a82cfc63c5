#pragma once
/// postProcessing/solverPerformance/<startTime>/solverPerformance.csv: one row per step with the step size,
/// pressure and CG convergence and the wall time of each phase, so that convergence and cost can be plotted
/// (OpenFOAM keeps function-object output under postProcessing/<name>/<startTime>/ the same way). Each rank of a
/// parallel run writes its own, in its processor directory, with its load: own particles, ghosts, the run's
/// imbalance, the wall time of its halo exchanges and reductions in the step, and the part of it spent migrating.

#include "physics/Solver.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace poro {

class SolverPerformanceLog {
public:
  /// Creates the file (replacing one of an earlier run from the same start time) and writes the header.
  /// `ranks`: the rank of a parallel run whose load the rows also give.
  SolverPerformanceLog(const std::filesystem::path& caseDir, const std::string& startName,
                       const GhostExchange* ranks = nullptr);

  /// Appends the row of the step just done. A failed write is reported once and ends the log, not the run:
  /// the time directories are what must not be lost.
  void record(const Solver& solver);

  const std::filesystem::path& file() const { return file_; }
  /// Phases with a column of their own, in column order.
  static const std::vector<std::string>& phaseColumns();

private:
  double phaseSeconds(const Solver& solver, const std::string& phase) const;
  /// Reports `why` once; no row is written after it.
  void fail(const std::string& why);

  std::filesystem::path file_;
  std::ofstream out_;
  const GhostExchange* ranks_ = nullptr;
  std::vector<double> previous_; ///< accumulated phase seconds at the previous row, by column
  double previousExchange_ = 0.0, previousMigration_ = 0.0;
  bool failed_ = false;
};

} // namespace poro
