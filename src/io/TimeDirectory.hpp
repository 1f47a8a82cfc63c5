#pragma once
/// Time directories of a case (ARCHITECTURE.md "A case directory"): `<t>/<set>.vtp` per particle set and
/// `<t>/uniform/time` (time, step index, the coming step's deltaT), written under a temporary name and
/// renamed when complete; `case.pvd` rewritten atomically after each write; boundary sets are static and
/// live in `0/` only.

#include "io/OutputSettings.hpp"
#include "io/PvdSeries.hpp"
#include "physics/Solver.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// The directory name of a time value: shortest decimal that reads back within 1e-10 relative ("0.1", "2.5").
std::string timeName(double time);

struct TimeDirectoryEntry {
  std::string name;
  double time;
};

/// Complete time directories (those with uniform/time) of a case, by increasing time.
std::vector<TimeDirectoryEntry> listTimeDirectories(const std::filesystem::path& caseDir);

/// Reads `<dir>/uniform/time`.
RunState readRunState(const std::filesystem::path& timeDir);

/// Loads every particle set of a time directory: each `<set>.vtp` in it, plus `0/boundary.vtp` when the
/// directory has no boundary of its own. `fluid` and `boundary` name the fluid and wall sets.
ParticleSystem readParticles(const std::filesystem::path& caseDir, const std::string& timeName, double particleRadius);

/// Writes the solver's state as a time directory and keeps case.pvd in step.
class TimeWriter {
public:
  /// Starts the series at the time directory `startName` (entries after it are dropped from case.pvd).
  TimeWriter(std::filesystem::path caseDir, const OutputSettings& settings, const std::string& startName);

  /// Writes `<t>/` for the dynamic sets and uniform/time, atomically, then case.pvd and purgeWrite.
  void write(const ParticleSystem& particles, const RunState& state);

  /// Writes a complete time directory including boundary sets (sampleParticles writes 0/ with this).
  static void writeAll(const std::filesystem::path& caseDir, const ParticleSystem& particles, const RunState& state,
                       bool binary);

private:
  void purge();
  std::filesystem::path caseDir_;
  OutputSettings settings_;
  PvdSeries series_;
};

} // namespace poro
