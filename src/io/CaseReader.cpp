#include "io/CaseReader.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "io/ControlDictWatcher.hpp"
#include "io/SamplingRecord.hpp"
#include "io/TimeDirectory.hpp"

#include <cmath>
#include <cstdlib>

namespace poro {

namespace fs = std::filesystem;

double readParticleRadius(const fs::path& caseDir) {
  const Dictionary dict = Dictionary::read((caseDir / "system" / "particleDict").string());
  return dict.getReal("particleRadius", Range::positive());
}

std::vector<ObjectMotion> readWallMotions(const fs::path& caseDir) {
  const Dictionary dict = Dictionary::read((caseDir / "system" / "particleDict").string());
  std::vector<ObjectMotion> motions;
  if (!dict.has("regions")) return motions; // sampleParticles reports it
  const std::vector<Dictionary> regions = dict.getDictList("regions");
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const auto motion = regions[r].optionalSubDict("motion");
    if (!motion) continue;
    if (regions[r].getString("phase") != "boundary")
      regions[r].fail("motion", "only walls (phase: boundary) have a prescribed motion; fluid and porous "
                                "particles move by the physics (give them an initial velocity instead)");
    motions.push_back({static_cast<long long>(r), regions[r].getString("name"), regions[r].where("motion"),
                       WallMotion::read(*motion)});
  }
  return motions;
}

std::vector<RigidBody::Spec> readRigidBodies(const fs::path& caseDir) {
  const Dictionary dict = Dictionary::read((caseDir / "system" / "particleDict").string());
  std::vector<RigidBody::Spec> bodies;
  if (!dict.has("regions")) return bodies; // sampleParticles reports it
  const std::vector<Dictionary> regions = dict.getDictList("regions");
  for (std::size_t r = 0; r < regions.size(); ++r)
    if (regions[r].getString("phase") == "rigid")
      bodies.push_back(RigidBody::read(regions[r], static_cast<long long>(r)));
  return bodies;
}

std::vector<PorousMaterial> readPorousMaterials(const fs::path& caseDir) {
  // Only needed for porous regions: missing, empty or comments only, the case has no materials.
  const Dictionary dict = Dictionary::readOptional((caseDir / "constant" / "porosityProperties").string());
  if (dict.keys().empty()) return {};
  return PorousMaterial::readAll(dict);
}

namespace {

/// A numeric directory without uniform/time, whose time `relevant` accepts: a time directory that lost its run
/// state, which the run would otherwise silently pass over.
template <class Relevant> void throwIfIncomplete(const fs::path& caseDir, const Relevant& relevant) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
    const std::string name = entry.path().filename().string();
    char* end = nullptr;
    const double time = std::strtod(name.c_str(), &end);
    if (!entry.is_directory() || name.empty() || *end != '\0' || !relevant(time) ||
        fs::exists(entry.path() / "uniform" / "time"))
      continue;
    throw InputError((entry.path() / "uniform" / "time").string() + ": missing; time directory " + name +
                     " is incomplete (restore it, or run sampleParticles again for 0/)");
  }
}

} // namespace

SimulationCase readCase(const fs::path& caseDir, int threads, const fs::path& timesDirOrEmpty) {
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const fs::path timesDir = timesDirOrEmpty.empty() ? caseDir : timesDirOrEmpty;
  const auto [control, output] = readControlDict(caseDir);

  SolverSettings solver = SolverSettings::read(Dictionary::readOptional((caseDir / "system" / "solverDict").string()));
  if (threads > 0) solver.threads = threads;
  const FluidProperties fluid =
      FluidProperties::read(Dictionary::read((caseDir / "constant" / "fluidProperties").string()));
  std::vector<PorousMaterial> materials = readPorousMaterials(caseDir);
  const double radius = readParticleRadius(caseDir);
  std::vector<ObjectMotion> wallMotions = readWallMotions(caseDir);
  std::vector<RigidBody::Spec> rigidBodies = readRigidBodies(caseDir);

  const auto controlDictError = [&](const std::string& key, const std::string& message) {
    Dictionary::read((caseDir / "system" / "controlDict").string()).fail(key, message); // for the line
  };
  std::string startName;
  recoverInterruptedWrites(timesDir);
  const auto times = listTimeDirectories(timesDir);
  std::string names;
  for (const auto& t : times) names += (names.empty() ? "" : ", ") + t.name;
  const auto sameTime = [](double a, double b) { return std::abs(a - b) <= 1e-10 * std::max(1.0, std::abs(b)); };
  if (control.startFrom == TimeControl::StartFrom::LatestTime) {
    throwIfIncomplete(timesDir, [&](double t) { return times.empty() || t > times.back().time; });
    if (times.empty()) throw InputError((timesDir / "0").string() + ": no time directory; run sampleParticles first");
    startName = times.back().name;
  } else {
    for (const auto& t : times)
      if (sameTime(t.time, control.startTime)) startName = t.name;
    throwIfIncomplete(timesDir, [&](double t) { return startName.empty() && sameTime(t, control.startTime); });
    if (startName.empty())
      controlDictError("startTime", "no time directory " + timeName(control.startTime) +
                                        (times.empty() ? "; run sampleParticles first"
                                                       : "; the case has " + names + " (or use startFrom: latestTime)"));
  }
  RunState start = readRunState(timesDir / startName);
  checkSampledRegions(caseDir, timesDir / startName); // before reading what may be gigabytes of particles
  // As OpenFOAM: a finished case run again (startFrom latestTime) reports that it is done; the caller exits 0
  // without the particles.
  const bool endTimeReached = control.endTimeReached(start.time);
  ParticleSystem particles =
      endTimeReached ? ParticleSystem(radius)
                     : readParticles(timesDir, startName, radius, materials, timesDir != caseDir); // a rank's share
  return SimulationCase{control,   output, solver, fluid, std::move(materials), startName, start, std::move(particles),
                        std::move(wallMotions), std::move(rigidBodies), endTimeReached};
}

} // namespace poro
