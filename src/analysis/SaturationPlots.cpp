#include "analysis/SaturationPlots.hpp"

#include <cctype>
#include <functional>
#include <optional>
#include <sstream>

namespace poro {

namespace {

using Points = std::vector<std::pair<double, double>>;

/// (time, value) of one object's quantity over the records; times without a value are left out.
Points overTime(const std::vector<TimeRecord>& records, std::int64_t objectId,
                const std::function<std::optional<double>(const ObjectStatistics&)>& value) {
  Points points;
  for (const TimeRecord& record : records) {
    const std::size_t k = indexOf(record, objectId);
    if (k == record.objects.size()) continue;
    if (const auto v = value(record.objects[k])) points.emplace_back(record.time, *v);
  }
  return points;
}

Points fluidOverTime(const std::vector<TimeRecord>& records,
                     const std::function<std::optional<double>(const FluidStatistics&)>& value) {
  Points points;
  for (const TimeRecord& record : records)
    if (const auto v = value(record.fluid)) points.emplace_back(record.time, *v);
  return points;
}

/// A file-name-safe form of an object name.
std::string fileStem(const std::string& name) {
  std::string stem = name;
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return stem;
}

/// Kinetic energy, potential energy relative to the first time with fluid, and their sum: the mechanical
/// energy the flow has gained (> 0 would be spurious) or dissipated (< 0).
SvgLinePlot energyPlot(const std::vector<TimeRecord>& records) {
  std::optional<double> reference;
  for (const TimeRecord& record : records)
    if (!reference && record.fluid.particles > 0) reference = record.fluid.potentialEnergy;
  const double base = reference.value_or(0.0);
  SvgLinePlot energy("Fluid energy (potential relative to the first time)", "time [s]", "energy [J]");
  energy.includeZeroY();
  energy.add({"kinetic", fluidOverTime(records, [](auto& f) { return std::optional<double>(f.kineticEnergy); }),
              false, 0});
  energy.add({"potential change", fluidOverTime(records, [&](auto& f) {
                return std::optional<double>(f.potentialEnergy - base);
              }),
              false, 1});
  energy.add({"kinetic + potential change", fluidOverTime(records, [&](auto& f) {
                return std::optional<double>(f.kineticEnergy + f.potentialEnergy - base);
              }),
              true, 2});
  return energy;
}

SvgLinePlot extentPlot(const std::vector<TimeRecord>& records, const std::string& along) {
  SvgLinePlot extent("Fluid extent (particle centres)", "time [s]", along);
  extent.add({"highest", fluidOverTime(records, [](auto& f) { return f.maxPosition; }), false, 0});
  extent.add({"lowest", fluidOverTime(records, [](auto& f) { return f.minPosition; }), true, 0});
  return extent;
}

} // namespace

std::vector<std::size_t> profileTimes(const std::vector<TimeRecord>& records, std::int64_t objectId) {
  std::vector<std::size_t> withProfile;
  for (std::size_t r = 0; r < records.size(); ++r) {
    const std::size_t k = indexOf(records[r], objectId);
    if (k < records[r].objects.size() && !records[r].profiles[k].empty()) withProfile.push_back(r);
  }
  constexpr std::size_t kMost = 6;
  if (withProfile.size() <= kMost) return withProfile;
  std::vector<std::size_t> chosen;
  for (std::size_t j = 0; j < kMost; ++j)
    chosen.push_back(withProfile[(j * (withProfile.size() - 1) + (kMost - 1) / 2) / (kMost - 1)]);
  return chosen;
}

std::vector<std::pair<std::string, SvgLinePlot>> saturationPlots(const std::vector<TimeRecord>& records,
                                                                 const AnalysisSettings& settings) {
  const auto objects = objectsOf(records);
  const Axis& axis = settings.axis;
  const std::string along = "position along " + std::string(axis.sign > 0 ? "+" : "") + axis.name() + " [m]";
  std::ostringstream wet;
  wet << "Wet region (saturation ≥ " << settings.wetThreshold << ")";
  SvgLinePlot absorbed("Absorbed fluid volume", "time [s]", "volume [m³]");
  SvgLinePlot filling("Pore filling and saturation", "time [s]", "fraction of pore volume, saturation [-]");
  SvgLinePlot front(wet.str(), "time [s]", along);
  absorbed.includeZeroY();
  filling.includeZeroY();
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const auto& [id, name] = objects[k];
    const int colour = static_cast<int>(k);
    absorbed.add({name + " absorbed", overTime(records, id, [](auto& o) { return o.absorbedVolume; }), false, colour});
    absorbed.add({name + " pore volume φV", overTime(records, id, [](auto& o) { return o.poreVolume; }), true, colour});
    filling.add(
        {name + " fraction filled", overTime(records, id, [](auto& o) { return o.fractionFilled; }), false, colour});
    filling.add(
        {name + " mean saturation", overTime(records, id, [](auto& o) { return o.meanSaturation; }), true, colour});
    front.add({name + " wetMin", overTime(records, id, [](auto& o) { return o.wetMin; }), false, colour});
    front.add({name + " wetMax", overTime(records, id, [](auto& o) { return o.wetMax; }), true, colour});
  }

  SvgLinePlot density("Fluid density error (compression only)", "time [s]", "density error [%]");
  density.includeZeroY();
  density.add({"mean", fluidOverTime(records, [](auto& f) { return f.meanDensityError; }), false, 0});
  density.add({"max", fluidOverTime(records, [](auto& f) { return f.maxDensityError; }), true, 0});
  std::vector<std::pair<std::string, SvgLinePlot>> plots;
  if (!objects.empty()) // a fluid-only case (a dam break) gets the fluid's plots only
    plots = {{"absorbedVolume.svg", absorbed}, {"fillFraction.svg", filling}, {"wetFront.svg", front}};
  plots.emplace_back("densityError.svg", density);
  plots.emplace_back("energy.svg", energyPlot(records));
  plots.emplace_back("fluidExtent.svg", extentPlot(records, along));
  for (const auto& [id, name] : objects) {
    const std::vector<std::size_t> times = profileTimes(records, id);
    if (times.empty()) continue;
    SvgLinePlot profile("Saturation profile of " + name, "mean saturation [-]", along);
    profile.includeZeroX();
    for (std::size_t j = 0; j < times.size(); ++j) {
      const TimeRecord& record = records[times[j]];
      Points points;
      for (const ProfileBin& bin : record.profiles[indexOf(record, id)])
        points.emplace_back(bin.meanSaturation, bin.position);
      profile.add({"t = " + record.name + " s", points, false, static_cast<int>(j)});
    }
    plots.emplace_back("saturationProfiles_" + fileStem(name) + ".svg", profile);
  }
  return plots;
}

} // namespace poro
