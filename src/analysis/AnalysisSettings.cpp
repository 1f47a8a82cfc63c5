#include "analysis/AnalysisSettings.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "io/CaseReader.hpp"
#include "io/SamplingRecord.hpp"
#include "physics/FluidProperties.hpp"

namespace poro {

namespace fs = std::filesystem;

namespace {

/// Region names by index (= objectId). Post-processing must not refuse a case for a region list that only
/// sampleParticles cares about, so anything unreadable leaves that name empty.
std::vector<std::string> readRegionNames(const Dictionary& particleDict) {
  std::vector<std::string> names;
  if (!particleDict.has("regions")) return names;
  try {
    for (const Dictionary& region : particleDict.getDictList("regions")) {
      std::string name;
      try {
        if (region.has("name")) name = region.getString("name");
      } catch (const InputError&) {
      }
      names.push_back(name);
    }
  } catch (const InputError&) {
    names.clear();
  }
  return names;
}

} // namespace

std::vector<std::string> sampledRegionNames(const fs::path& timeDir, const std::vector<std::string>& current) {
  const fs::path record = timeDir / "uniform" / kSamplingRecordName;
  if (!fs::exists(record)) return current;
  try {
    std::vector<std::string> names = readRegionNames(Dictionary::read(record.string()));
    return names.empty() ? current : names;
  } catch (const InputError&) { // unreadable: the objects keep particleDict's names
    return current;
  }
}

AnalysisSettings readAnalysisSettings(const fs::path& caseDir) {
  AnalysisSettings settings;
  settings.particleRadius = readParticleRadius(caseDir);
  settings.regionNames = readRegionNames(Dictionary::read((caseDir / "system" / "particleDict").string()));
  const FluidProperties fluid =
      FluidProperties::read(Dictionary::read((caseDir / "constant" / "fluidProperties").string()));
  settings.fluidDensity = fluid.density;
  settings.gravity = fluid.gravity;
  settings.axis = Axis::up(fluid.gravity);
  settings.materials = readPorousMaterials(caseDir);
  return settings;
}

} // namespace poro
