/// sampleParticles: system/particleDict -> 0/ (fluid.vtp, porous.vtp, boundary.vtp, uniform/time, uniform/sampling)
/// and case.pvd.

#include "ParticleRegions.hpp"
#include "RegionPlacement.hpp"
#include "WallGaps.hpp"
#include "core/Arguments.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "io/CaseLock.hpp"
#include "io/CaseReader.hpp"
#include "io/ProcessorDirectories.hpp"
#include "io/SamplingRecord.hpp"
#include "io/TimeDirectory.hpp"
#include "physics/FieldNames.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace poro;

namespace {

/// Appends the lattice points of one region to its set with fresh persistent ids; returns the first new slot.
std::size_t appendRegion(ParticleSet& set, const std::vector<Vec3>& points, const Vec3& velocity, long long objectId,
                         long long& nextId) {
  const std::size_t first = set.size();
  set.resize(first + points.size());
  auto& ids = set.integer(field::id);
  auto& objects = set.integer(field::objectId);
  for (std::size_t k = 0; k < points.size(); ++k) {
    set.x()[first + k] = points[k];
    set.v()[first + k] = velocity;
    ids[first + k] = nextId++;
    objects[first + k] = objectId;
  }
  return first;
}

bool hasRegion(const ParticleDict& dict, ParticleRegion::Phase phase, std::size_t materialId = 0) {
  for (const ParticleRegion& region : dict.regions)
    if (region.phase == phase && (phase != ParticleRegion::Phase::Porous || region.materialId == materialId))
      return true;
  return false;
}

/// Time directories after 0/ hold a run of an earlier sampling. They are not deleted (never lose data), but a run
/// with startFrom latestTime would continue them and saturationAnalysis would read them with the new 0/.
void warnOfEarlierRun(const fs::path& caseDir) {
  std::vector<std::string> later;
  for (const TimeDirectoryEntry& t : listTimeDirectories(caseDir))
    if (t.time > 0.0) later.push_back(t.name);
  const std::size_t subdomains = listProcessorDirectories(caseDir).size();
  if (later.empty() && subdomains == 0) return;
  std::ostringstream msg;
  msg << caseDir.string() << " holds ";
  if (!later.empty())
    msg << later.size() << " time director" << (later.size() == 1 ? "y" : "ies") << " after 0/ (" << later.front()
        << (later.size() > 1 ? " ... " + later.back() : std::string()) << ")" << (subdomains ? " and " : "");
  if (subdomains) msg << subdomains << " processor directories";
  msg << " from before this sampling. They stay as they are: a run with startFrom latestTime continues from them, "
         "and saturationAnalysis reads them with the new 0/. Remove them to start from this 0/.";
  log::warning(msg.str());
}

} // namespace

int main(int argc, char* argv[]) try {
  const Arguments args(argc, argv, "sampleParticles",
                       "Samples the regions of system/particleDict into particles and writes the initial time\n"
                       "directory 0/ (fluid.vtp, porous.vtp, boundary.vtp, uniform/time) and case.pvd. Porous regions\n"
                       "name a material of constant/porosityProperties; surface regions name a closed surface\n"
                       "of constant/triSurface (STL, OBJ, OFF or PLY).");
  if (args.help()) {
    std::cout << args.usage();
    return 0;
  }
  if (args.threads() > 0) parallel::setThreads(args.threads());
  const fs::path caseDir = args.caseDir();
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const CaseLock lock(caseDir, "sampleParticles"); // it rewrites 0/ and case.pvd
  const std::string dictPath = (caseDir / "system" / "particleDict").string();
  const std::vector<PorousMaterial> materials = readPorousMaterials(caseDir);
  const Dictionary particleDict = Dictionary::read(dictPath);
  const ParticleDict dict = ParticleDict::read(particleDict, materials, caseDir / "constant" / "triSurface");
  const bool binary = [&] {
    const fs::path control = caseDir / "system" / "controlDict";
    if (!fs::exists(control)) return true;
    const Dictionary d = Dictionary::read(control.string());
    return d.getWord("writeFormat", {"binary", "ascii"}, "binary") == "binary";
  }();

  // Sets in ParticleSystem order (fluid, one porous set per material in constant/porosityProperties order,
  // boundary), the order readParticles gives back, so a run from 0/ sees the sets as sampled.
  ParticleSystem particles(dict.particleRadius);
  ParticleSet& fluid = particles.add("fluid", SetKind::Fluid);
  std::vector<ParticleSet*> porous(materials.size(), nullptr);
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (hasRegion(dict, ParticleRegion::Phase::Porous, m)) {
      porous[m] = &particles.add(materials[m].name, SetKind::Porous);
      porous[m]->addInt(field::materialId, Restart);
      porous[m]->addInt(field::fixed, Restart);
    }
  ParticleSet* boundary =
      hasRegion(dict, ParticleRegion::Phase::Boundary) ? &particles.add("boundary", SetKind::Boundary) : nullptr;
  ParticleSet* rigid = // rigid bodies move: rigid.vtp goes into every time directory, the static walls do not
      hasRegion(dict, ParticleRegion::Phase::Rigid) ? &particles.add(kRigidSetName, SetKind::Boundary) : nullptr;

  long long nextId = 0; // ids are unique over all particles of the case
  for (std::size_t r = 0; r < dict.regions.size(); ++r) {
    const ParticleRegion& region = dict.regions[r];
    const std::vector<Vec3> points = region.sample(dict.particleRadius);
    ParticleSet* target = region.phase == ParticleRegion::Phase::Fluid    ? &fluid
                          : region.phase == ParticleRegion::Phase::Porous ? porous[region.materialId]
                          : region.phase == ParticleRegion::Phase::Rigid  ? rigid
                                                                          : boundary;
    const std::size_t first = appendRegion(*target, points, region.velocity, static_cast<long long>(r), nextId);
    std::ostringstream line;
    line << "region " << region.name << ": " << points.size() << " " << toString(target->kind()) << " particles";
    if (region.phase == ParticleRegion::Phase::Porous) {
      auto& materialIds = target->integer(field::materialId);
      auto& fixed = target->integer(field::fixed);
      for (std::size_t i = first; i < target->size(); ++i) {
        materialIds[i] = static_cast<std::int64_t>(region.materialId);
        fixed[i] = region.fixed ? 1 : 0;
      }
      line << " of material " << materials[region.materialId].name << (region.fixed ? ", fixed" : "");
    }
    if (region.rigid) {
      const RigidBody body(*region.rigid, points, dict.particleRadius);
      line << ", a rigid body of mass " << body.mass() << " kg, centre of mass " << body.restCentre().transpose();
    }
    if (region.motion) {
      double reach = 0.0; // the largest distance from the rotation axis, for the speed of a rotating wall
      for (const Vec3& p : points) reach = std::max(reach, region.motion->distanceFromAxis(p));
      line << ", moving (prescribed, at most " << region.motion->maxSpeed(reach) << " m/s"
           << (region.motion->rotates() ? ", turning" : "") << ")";
    }
    if (region.body && region.phase != ParticleRegion::Phase::Boundary) // how well the lattice fills the body
      line << " (enclosed volume / (2r)^3 = " << region.body->volume() / std::pow(2.0 * dict.particleRadius, 3) << ")";
    log::info(line.str());
  }

  checkRegionPlacement(dict, particles); // before 0/ is written: a refused case keeps its old 0/
  reportWallGaps(particles, dict);
  fs::create_directories(caseDir);
  // What 0/ was sampled from: poroSph refuses to run it once particleDict's regions or the materials' order change.
  TimeWriter::writeAll(caseDir, particles, RunState{}, binary,
                       samplingRecord(particleDict, caseDir / "constant" / "triSurface", particles, materials));
  warnOfEarlierRun(caseDir);
  std::ostringstream done;
  done << "Wrote " << (caseDir / "0").string() << " with " << particles.particleCount() << " particles (radius "
       << dict.particleRadius << " m) and " << (caseDir / "case.pvd").string() << "\nEnd";
  log::info(done.str());
  return 0;
} catch (const Error& e) {
  log::fatal(e);
  return 1;
} catch (const std::exception& e) {
  log::fatal(e.what());
  return 1;
}
