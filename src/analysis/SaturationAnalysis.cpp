#include "analysis/SaturationAnalysis.hpp"

#include "analysis/AbsorbedFluid.hpp"
#include "io/ProcessorDirectories.hpp"
#include "io/TimeDirectory.hpp"

#include <map>

namespace poro {

std::vector<std::pair<std::int64_t, std::string>> objectsOf(const std::vector<TimeRecord>& records) {
  std::map<std::int64_t, std::string> names;
  for (const TimeRecord& record : records)
    for (const ObjectStatistics& object : record.objects) names.emplace(object.objectId, object.name);
  return {names.begin(), names.end()};
}

std::size_t indexOf(const TimeRecord& record, std::int64_t objectId) {
  for (std::size_t k = 0; k < record.objects.size(); ++k)
    if (record.objects[k].objectId == objectId) return k;
  return record.objects.size();
}

TimeRecord analyse(const ParticleSystem& particles, const AnalysisSettings& settings) {
  TimeRecord record;
  const std::vector<PorousObject> objects = findPorousObjects(particles, settings.regionNames);
  const ParticleSet* fluid = particles.find("fluid");
  const std::vector<std::size_t> absorbed =
      fluid ? countAbsorbedFluid(fluid->x(), particles, objects, settings.particleRadius)
            : std::vector<std::size_t>(objects.size(), 0);
  for (std::size_t k = 0; k < objects.size(); ++k) {
    record.objects.push_back(objectStatistics(particles, objects[k], absorbed[k], settings));
    record.profiles.push_back(saturationProfile(particles, objects[k], settings.axis, settings.particleRadius));
  }
  if (fluid) record.fluid = fluidStatistics(*fluid, settings);
  return record;
}

TimeRecord analyseTimeDirectory(const std::filesystem::path& caseDir, const std::string& name,
                                const AnalysisSettings& settings) {
  // A time a decomposed run wrote only into processor<N>/ is read from its subdomains, merged.
  const std::vector<std::filesystem::path> processors =
      std::filesystem::exists(caseDir / name / "uniform" / "time") ? std::vector<std::filesystem::path>()
                                                                   : listProcessorDirectories(caseDir);
  const RunState state =
      processors.empty() ? readRunState(caseDir / name) : readDecomposedRunState(processors, name);
  AnalysisSettings sampled = settings; // the objects are named as their regions were when they were sampled
  sampled.regionNames =
      sampledRegionNames((processors.empty() ? caseDir : processors.front()) / name, settings.regionNames);
  TimeRecord record = analyse(
      processors.empty() ? readParticles(caseDir, name, settings.particleRadius, settings.materials)
                         : readDecomposedParticles(processors, name, settings.particleRadius, settings.materials),
      sampled);
  record.name = name;
  record.time = state.time;
  record.step = state.step;
  return record;
}

} // namespace poro
