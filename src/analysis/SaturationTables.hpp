#pragma once
/// The CSV files of saturationAnalysis.
///  timeSeries.csv: one row per time: time_s (as its directory is named), step, then for every porous object
///    <name>.<quantity> (columns in saturationAnalysis -help), then fluid.<quantity>. Empty cell: no value.
///  saturationProfiles.csv (long format): time_s, object, position_m, meanSaturation, particles.

#include "analysis/CsvTable.hpp"
#include "analysis/SaturationAnalysis.hpp"

namespace poro {

CsvTable timeSeriesTable(const std::vector<TimeRecord>& records);
CsvTable profileTable(const std::vector<TimeRecord>& records);

} // namespace poro
