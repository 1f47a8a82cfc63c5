#pragma once
/// Everything saturationAnalysis writes for a set of times: the CSV files (analysis/SaturationTables.hpp)
/// and the SVG plots (analysis/SaturationPlots.hpp).

#include "analysis/SaturationAnalysis.hpp"

#include <filesystem>
#include <vector>

namespace poro {

/// Creates `dir` and writes timeSeries.csv, saturationProfiles.csv and the plots into it, each file
/// atomically; returns the files written. Throws OutputError naming what could not be written.
std::vector<std::filesystem::path> writeSaturationReport(const std::vector<TimeRecord>& records,
                                                         const AnalysisSettings& settings,
                                                         const std::filesystem::path& dir);

} // namespace poro
