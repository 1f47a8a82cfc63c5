#include "io/CaseReader.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "io/ControlDictWatcher.hpp"
#include "io/TimeDirectory.hpp"

#include <cmath>

namespace poro {

namespace fs = std::filesystem;

double readParticleRadius(const fs::path& caseDir) {
  const Dictionary dict = Dictionary::read((caseDir / "system" / "particleDict").string());
  return dict.getReal("particleRadius", Range::positive());
}

std::vector<PorousMaterial> readPorousMaterials(const fs::path& caseDir) {
  const fs::path path = caseDir / "constant" / "porosityProperties";
  if (!fs::exists(path)) return {};
  return PorousMaterial::readAll(Dictionary::read(path.string()));
}

SimulationCase readCase(const fs::path& caseDir, int threads) {
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const auto [control, output] = readControlDict(caseDir);

  const fs::path solverDictPath = caseDir / "system" / "solverDict";
  SolverSettings solver =
      fs::exists(solverDictPath) ? SolverSettings::read(Dictionary::read(solverDictPath.string())) : SolverSettings{};
  if (threads > 0) solver.threads = threads;
  const FluidProperties fluid =
      FluidProperties::read(Dictionary::read((caseDir / "constant" / "fluidProperties").string()));
  std::vector<PorousMaterial> materials = readPorousMaterials(caseDir);
  const double radius = readParticleRadius(caseDir);

  std::string startName;
  const auto times = listTimeDirectories(caseDir);
  if (control.startFrom == TimeControl::StartFrom::LatestTime) {
    if (times.empty()) throw InputError((caseDir / "0").string() + ": no time directory; run sampleParticles first");
    startName = times.back().name;
  } else {
    for (const auto& t : times)
      if (std::abs(t.time - control.startTime) <= 1e-10 * std::max(1.0, control.startTime)) startName = t.name;
    if (startName.empty())
      throw InputError((caseDir / "system" / "controlDict").string() + ": no time directory for startTime " +
                       timeName(control.startTime) + (times.empty() ? "; run sampleParticles first" : ""));
  }
  RunState start = readRunState(caseDir / startName);
  ParticleSystem particles = readParticles(caseDir, startName, radius, materials);
  if (start.time >= control.endTime)
    throw InputError((caseDir / "system" / "controlDict").string() + ": endTime " + timeName(control.endTime) +
                     " is not after the start time " + startName);
  return SimulationCase{control, output, solver, fluid, std::move(materials), startName, start, std::move(particles)};
}

} // namespace poro
