/// saturationAnalysis: time directories -> postProcessing/saturationAnalysis/ (CSV and SVG plots).

#include "analysis/SaturationReport.hpp"
#include "analysis/TimeSelection.hpp"
#include "core/Arguments.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace poro;

namespace {

const char* const kDefinitions = R"(
Definitions (r = particle radius, V = (2r)^3, rho0 = fluid density of constant/fluidProperties):
  object          the porous particles of one region of system/particleDict (same objectId), named by the
                  region; "object<k>" when the name cannot be recovered
  absorbed        fluid particles inside the object: within the lattice cell of one of its particles,
                  |x_f - x_s|_inf <= r (for an undeformed box: inside the box); volume = count V,
                  mass = count rho0 V
  pore volume     sum of phi V over the object's particles (phi of their material); fractionFilled =
                  absorbed volume / pore volume
  saturation      the particles' `saturation` field (Eq. 12): mean and max over the object; wet particles
                  have saturation >= wetThreshold; wetMin, wetMax = their lowest and highest position along
                  the axis (empty when none is wet), wetHeight = wetMax - wetMin (0 when none is wet)
  profiles        mean saturation in bins of width 2r along the axis (one lattice layer each)
  density error   of the fluid's `density` field: max(rho/rho0 - 1, 0) in %, mean over all fluid particles
                  and max; compression only, as the pressure solver measures it (a free surface's density
                  deficit is no error)
  kinetic energy  sum 1/2 rho0 V |v|^2 [J]; momentum sum rho0 V v [kg m/s]
  potential       sum -rho0 V g.x [J] (g of constant/fluidProperties), zero at the origin: only its change
                  over time means something; energy.svg plots it relative to the first time
  fluid extent    minPosition, maxPosition: the lowest and highest fluid particle centre along the axis
                  (a surge front with -axis x, a pool's free surface with the default axis); maxSpeed = max |v|,
                  meanSpeed = mean |v|
  pressure gradient  -(slope of the `pressure` field against the height, along -g) / (rho0 |g|), least squares
                  over the particles between 15 and 85 % of the way from the lowest to the highest one and three
                  spacings 2r inside the fluid's horizontal extent (the layer at a side wall stands steeper);
                  1 for a pool at rest, empty without pressure
Time 0 of sampleParticles has no saturation or density yet: those cells stay empty.

Output in <case>/postProcessing/saturationAnalysis/ (rewritten on every run, for the selected times):
  timeSeries.csv          time_s, step; per object <name>.solidParticles, .absorbedParticles,
                          .absorbedVolume_m3, .absorbedMass_kg, .poreVolume_m3, .fractionFilled,
                          .meanSaturation, .maxSaturation, .wetParticles, .wetMin_m, .wetMax_m, .wetHeight_m,
                          .centre_m, .minPosition_m, .maxPosition_m (where the solid is along the axis),
                          .maxDensity_kg_per_m3 (its densest particle);
                          fluid.particles, .meanDensityError_percent, .maxDensityError_percent,
                          .kineticEnergy_J, .momentumX_kg_m_per_s, .momentumY_kg_m_per_s, .momentumZ_kg_m_per_s,
                          .potentialEnergy_J, .maxSpeed_m_per_s, .minPosition_m, .maxPosition_m,
                          .meanSpeed_m_per_s, .pressureGradient_rho0g
  saturationProfiles.csv  time_s, object, position_m, meanSaturation, particles
  *.svg                   with porous objects: absorbedVolume, fillFraction, wetFront and per object
                          saturationProfiles_<object> (up to six times, including the latest); always
                          densityError, energy and fluidExtent
Time directories that cannot be read (truncated .vtp, no uniform/time) are named in a warning and skipped;
when none can be read, saturationAnalysis exits with status 1. -threads has no effect (the analysis is serial).
)";

double wetThreshold(const Arguments& args) {
  if (!args.has("wetThreshold")) return 0.5;
  const std::string text = args.value("wetThreshold");
  std::size_t used = 0;
  double value = -1.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value >= 0.0 && value <= 1.0))
    throw InputError("option -wetThreshold expects a saturation in [0, 1], got '" + text + "'");
  return value;
}

std::string summary(const TimeRecord& record) {
  std::ostringstream line;
  line << "Time " << record.name << ":";
  for (const ObjectStatistics& o : record.objects) {
    line << " " << o.name << " absorbed " << o.absorbedVolume << " m^3 (" << 100.0 * o.fractionFilled
         << " % of its pores)";
    if (o.meanSaturation) line << ", mean saturation " << *o.meanSaturation << ";";
  }
  if (record.fluid.maxDensityError)
    line << " fluid density error " << *record.fluid.meanDensityError << " % (max " << *record.fluid.maxDensityError
         << " %)";
  return line.str();
}

} // namespace

int main(int argc, char* argv[]) try {
  const Arguments args(
      argc, argv, "saturationAnalysis",
      "Post-processing: reads the time directories of a case and writes, per porous object, the absorbed fluid\n"
      "volume and mass, pore filling, saturation statistics, the wet region and saturation profiles along an\n"
      "axis, and the fluid's density error, kinetic energy and momentum, as CSV and SVG plots to\n"
      "postProcessing/saturationAnalysis/.",
      [] {
        auto options = timeOptions("analyse");
        options.push_back(
            {"axis", "AXIS", "x, y, z, -x, -y or -z: direction of fronts and profiles (default: against gravity)"});
        options.push_back({"wetThreshold", "S", "a porous particle with saturation >= S is wet (default 0.5)"});
        return options;
      }());
  if (args.help()) {
    std::cout << args.usage() << kDefinitions;
    return 0;
  }
  const fs::path caseDir = args.caseDir();
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");

  AnalysisSettings settings = readAnalysisSettings(caseDir);
  if (args.has("axis")) settings.axis = Axis::parse(args.value("axis"));
  settings.wetThreshold = wetThreshold(args);
  const TimeSelection selection = selectTimesWithSubdomains(args, caseDir);
  std::ostringstream banner;
  banner << "Case: " << caseDir.string() << "\nAxis: " << settings.axis.name() << ", wet threshold "
         << settings.wetThreshold << "\nTimes: " << selection.complete.size();
  log::info(banner.str());

  std::vector<TimeRecord> records;
  for (const TimeCandidate& time : selection.complete) {
    try {
      records.push_back(analyseTimeDirectory(caseDir, time.name, settings));
      log::info(summary(records.back()));
    } catch (const std::exception& e) { // a bad directory is reported and skipped, never the end of the run
      log::warning((caseDir / time.name).string() + ": cannot be read; skipped:\n    " + e.what());
    }
  }
  if (records.empty()) throw noneReadable(caseDir, selection.complete.size());

  const auto files = writeSaturationReport(records, settings, caseDir / "postProcessing" / "saturationAnalysis");
  std::ostringstream done;
  done << "Analysed " << records.size() << " of " << selection.complete.size() << " time directories; wrote";
  for (const fs::path& file : files) done << "\n  " << file.string();
  log::info(done.str() + "\nEnd");
  return 0;
} catch (const Error& e) {
  log::fatal(e);
  return 1;
} catch (const std::exception& e) {
  log::fatal(e.what());
  return 1;
}
