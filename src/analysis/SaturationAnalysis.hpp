#pragma once
/// One time of saturationAnalysis: every porous object's statistics and saturation profile, and the fluid's.

#include "analysis/AnalysisSettings.hpp"
#include "analysis/FluidStatistics.hpp"
#include "analysis/SaturationProfiles.hpp"
#include "analysis/SaturationStatistics.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace poro {

struct TimeRecord {
  std::string name; ///< the time directory
  double time = 0.0;
  long long step = 0;
  std::vector<ObjectStatistics> objects;         ///< by increasing objectId
  std::vector<std::vector<ProfileBin>> profiles; ///< profiles[k] belongs to objects[k]
  FluidStatistics fluid;
};

/// The objects seen at any of `records` as (objectId, name), by increasing objectId: the columns and series
/// of the report.
std::vector<std::pair<std::int64_t, std::string>> objectsOf(const std::vector<TimeRecord>& records);
/// The index of objectId in record.objects, or record.objects.size() when the object is absent at that time.
std::size_t indexOf(const TimeRecord& record, std::int64_t objectId);

/// Analyses a particle system (a set named "fluid" is the fluid; without one, nothing is absorbed). Leaves
/// name, time and step at their defaults.
TimeRecord analyse(const ParticleSystem& particles, const AnalysisSettings& settings);

/// Reads `<caseDir>/<name>` (uniform/time and the particle files, io/TimeDirectory.hpp) and analyses it.
/// Whatever makes the directory unreadable (a truncated .vtp, a missing uniform/time) is an InputError
/// naming the file.
TimeRecord analyseTimeDirectory(const std::filesystem::path& caseDir, const std::string& name,
                                const AnalysisSettings& settings);

} // namespace poro
