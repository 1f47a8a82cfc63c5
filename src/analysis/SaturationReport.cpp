#include "analysis/SaturationReport.hpp"

#include "analysis/SaturationPlots.hpp"
#include "analysis/SaturationTables.hpp"
#include "core/Error.hpp"
#include "io/OutputDirectory.hpp"

namespace poro {

namespace fs = std::filesystem;

std::vector<fs::path> writeSaturationReport(const std::vector<TimeRecord>& records, const AnalysisSettings& settings,
                                            const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(whyDirectoryFails(dir, ec));
  std::vector<fs::path> written = {dir / "timeSeries.csv", dir / "saturationProfiles.csv"};
  timeSeriesTable(records).write(written[0]);
  profileTable(records).write(written[1]);
  for (const auto& [name, plot] : saturationPlots(records, settings)) {
    plot.write(dir / name);
    written.push_back(dir / name);
  }
  return written;
}

} // namespace poro
