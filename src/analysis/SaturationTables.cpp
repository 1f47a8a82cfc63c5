#include "analysis/SaturationTables.hpp"

namespace poro {

namespace {

const char* const kObjectColumns[] = {"solidParticles", "absorbedParticles", "absorbedVolume_m3", "absorbedMass_kg",
                                      "poreVolume_m3",  "fractionFilled",    "meanSaturation",    "maxSaturation",
                                      "wetParticles",   "wetMin_m",          "wetMax_m",          "wetHeight_m",
                                      "centre_m",       "minPosition_m",     "maxPosition_m",     "maxDensity_kg_per_m3"};
const char* const kFluidColumns[] = {
    "particles",            "meanDensityError_percent", "maxDensityError_percent", "kineticEnergy_J",
    "momentumX_kg_m_per_s", "momentumY_kg_m_per_s",     "momentumZ_kg_m_per_s",    "potentialEnergy_J",
    "maxSpeed_m_per_s",     "minPosition_m",            "maxPosition_m",           "meanSpeed_m_per_s",
    "pressureGradient_rho0g"};

void addObject(CsvTable& table, const ObjectStatistics& o) {
  table.add(o.solidParticles).add(o.absorbedParticles).add(o.absorbedVolume).add(o.absorbedMass);
  table.add(o.poreVolume).add(o.fractionFilled).add(o.meanSaturation).add(o.maxSaturation);
  if (o.meanSaturation) // without saturation data nothing is known to be wet
    table.add(o.wetParticles);
  else
    table.add(std::string());
  table.add(o.wetMin).add(o.wetMax).add(o.wetHeight);
  table.add(o.centre).add(o.minPosition).add(o.maxPosition).add(o.maxDensity);
}

/// The time as its directory is named ("0.3", where uniform/time may say 0.30000000000000004).
std::string timeCell(const TimeRecord& record) {
  return record.name.empty() ? CsvTable::formatNumber(record.time) : record.name;
}

} // namespace

CsvTable timeSeriesTable(const std::vector<TimeRecord>& records) {
  const auto objects = objectsOf(records);
  std::vector<std::string> columns = {"time_s", "step"};
  for (const auto& [id, name] : objects)
    for (const char* column : kObjectColumns) columns.push_back(name + "." + column);
  for (const char* column : kFluidColumns) columns.push_back(std::string("fluid.") + column);

  CsvTable table(std::move(columns));
  for (const TimeRecord& record : records) {
    table.row().add(timeCell(record)).add(record.step);
    for (const auto& [id, name] : objects) {
      const std::size_t k = indexOf(record, id);
      if (k < record.objects.size())
        addObject(table, record.objects[k]);
      else
        for (std::size_t c = 0; c < std::size(kObjectColumns); ++c) table.add(std::string());
    }
    const FluidStatistics& f = record.fluid;
    table.add(f.particles).add(f.meanDensityError).add(f.maxDensityError).add(f.kineticEnergy);
    table.add(f.momentum.x()).add(f.momentum.y()).add(f.momentum.z());
    table.add(f.potentialEnergy).add(f.maxSpeed).add(f.minPosition).add(f.maxPosition);
    table.add(f.meanSpeed).add(f.pressureGradient);
  }
  return table;
}

CsvTable profileTable(const std::vector<TimeRecord>& records) {
  CsvTable table({"time_s", "object", "position_m", "meanSaturation", "particles"});
  for (const TimeRecord& record : records)
    for (std::size_t k = 0; k < record.objects.size(); ++k)
      for (const ProfileBin& bin : record.profiles[k])
        table.row()
            .add(timeCell(record))
            .add(record.objects[k].name)
            .add(bin.position)
            .add(bin.meanSaturation)
            .add(bin.particles);
  return table;
}

} // namespace poro
