#include "ParticleRegions.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include <unistd.h>

namespace poro {

namespace {

const std::vector<std::string> kFaces = {"xMin", "xMax", "yMin", "yMax", "zMin", "zMax"};
const char* const kAxes[] = {"x", "y", "z"};

/// Bytes sampleParticles holds per particle at its peak: the lattice points of a region (24), the set's fields
/// id, objectId, x, v (64, more while a set grows), the VTK copies of the integer fields and vertex cells (32).
/// Measured: 1.33 GB maximum resident size for 9.6 million particles (140 bytes each), ascii or binary.
constexpr double kSamplingBytesPerParticle = 150.0;

/// "[0.04, 0.16, 0.04]": Eigen's own format pads columns ("[  0.2 -0.32   0.2]").
std::string format(const Vec3& v) {
  std::ostringstream out;
  out << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
  return out.str();
}

/// A particle count for a message: exact while small, "about 1.2e+15" when it is an estimate of an absurd one.
std::string formatCount(double n) {
  std::ostringstream out;
  if (!std::isfinite(n)) return "more than 1e+308";
  if (n < 1e9)
    out << static_cast<long long>(n);
  else
    out << "about " << std::setprecision(2) << n;
  return out.str();
}

/// "25.3 GB", "2480 GB".
std::string formatGigabytes(double bytes) {
  std::ostringstream out;
  const double gb = bytes / 1e9;
  if (gb >= 100.0)
    out << std::fixed << std::setprecision(0);
  else
    out << std::setprecision(3);
  out << gb << " GB";
  return out.str();
}

double physicalMemoryBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 0.0;
}

/// Boxes and containers exactly; spheres and surfaces estimated from their volume, or as walls from the shell of
/// their thickness (layers 2r) over their area, which is all the checks of the totals need.
double pointCount(const ParticleRegion& r, double radius) {
  if (r.shape == ParticleRegion::Shape::Box) return boxPointCount(r.min, r.max, radius);
  if (r.shape == ParticleRegion::Shape::Container) return containerPointCount(r.min, r.max, radius, r.layers, r.open);
  const double cell = std::pow(2.0 * radius, 3);
  if (r.phase != ParticleRegion::Phase::Boundary) return r.body->volume() / cell;
  const double shell = r.body->area() * r.layers * 2.0 * radius;
  return (r.side == WallSide::Inside ? std::min(shell, r.body->volume()) : shell) / cell;
}

/// A region that samples to no particle is a mistake the user would otherwise only see as a missing body.
void checkNotEmpty(const Dictionary& region, const ParticleRegion& r, double radius, double count) {
  if (count > 0.0) return;
  std::ostringstream msg;
  if (r.shape == ParticleRegion::Shape::Container) {
    msg << "container '" << r.name << "' is open on every face, so it has no wall particles";
    region.fail("open", msg.str());
  }
  int axis = 0;
  for (int d = 0; d < 3; ++d)
    if (latticeCount(r.max[d] - r.min[d], 2.0 * radius) <= 0) axis = d;
  msg << "region '" << r.name << "' holds no particle: from min " << format(r.min) << " to max " << format(r.max)
      << " it is " << r.max[axis] - r.min[axis] << " m thick along " << kAxes[axis]
      << ", less than half a particle spacing 2 particleRadius = " << 2.0 * radius << " m";
  region.fail("max", msg.str());
}

/// Refuses a particleRadius that would sample more particles than a set can index or than fit in memory, before
/// any is allocated (a radius typed in millimetres instead of metres asks for 10^9 times as many).
void checkTotals(const Dictionary& dict, const ParticleDict& result, const std::vector<double>& counts) {
  std::map<std::pair<int, std::size_t>, double> perSet; // (phase, material) -> particles
  double total = 0.0, largest = 0.0;
  std::size_t largestRegion = 0;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    const ParticleRegion& r = result.regions[k];
    const std::size_t material = r.phase == ParticleRegion::Phase::Porous ? r.materialId : 0;
    perSet[{static_cast<int>(r.phase), material}] += counts[k];
    total += counts[k];
    if (counts[k] > largest) largest = counts[k], largestRegion = k;
  }
  double largestSet = 0.0;
  for (const auto& entry : perSet) largestSet = std::max(largestSet, entry.second);

  std::ostringstream msg;
  msg << result.particleRadius << " m would sample " << formatCount(total) << " particles";
  if (result.regions.size() > 1)
    msg << " (region '" << result.regions[largestRegion].name << "' alone " << formatCount(largest) << ")";
  constexpr double maxIndex = static_cast<double>(std::numeric_limits<Index>::max());
  if (largestSet > maxIndex) {
    msg << ", more than one particle set can hold (" << static_cast<long long>(maxIndex)
        << ", as particle indices are 32-bit); increase particleRadius or make the regions smaller";
    dict.fail("particleRadius", msg.str());
  }
  const double memory = physicalMemoryBytes();
  const double needed = total * kSamplingBytesPerParticle;
  if (memory > 0.0 && needed > memory) {
    msg << ", which need about " << formatGigabytes(needed) << " of memory to sample (" << kSamplingBytesPerParticle
        << " bytes each), more than the " << formatGigabytes(memory)
        << " this machine has; increase particleRadius or make the regions smaller";
    dict.fail("particleRadius", msg.str());
  }
}

/// The index of the material a porous region names.
std::size_t readMaterial(const Dictionary& region, const std::vector<PorousMaterial>& materials) {
  const std::string name = region.getString("material");
  if (materials.empty())
    region.fail("material", "porous regions need their materials in constant/porosityProperties, which this case "
                            "does not have; create it and define material '" +
                                name + "' there (template: etc/caseDicts/porosityProperties)");
  std::string defined;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (materials[m].name == name) return m;
    defined += (m == 0 ? "" : ", ") + materials[m].name;
  }
  region.fail("material", "unknown material '" + name + "'; constant/porosityProperties defines: " + defined);
}

ParticleRegion::Shape readShape(const Dictionary& region, ParticleRegion::Phase phase) {
  const std::string shape = phase != ParticleRegion::Phase::Boundary
                                ? region.getWord("shape", {"box", "sphere", "surface"})
                                : region.getWord("shape", {"box", "container", "sphere", "surface"});
  return shape == "box"         ? ParticleRegion::Shape::Box
         : shape == "container" ? ParticleRegion::Shape::Container
         : shape == "sphere"    ? ParticleRegion::Shape::Sphere
                                : ParticleRegion::Shape::Surface;
}

void readBox(const Dictionary& region, ParticleRegion& r) {
  r.min = region.getVec3("min");
  r.max = region.getVec3("max");
  for (int d = 0; d < 3; ++d)
    if (!(r.min[d] < r.max[d])) {
      std::ostringstream msg;
      msg << "expected max > min on every axis, got min " << format(r.min) << ", max " << format(r.max);
      region.fail("max", msg.str());
    }
}

FaceFlags readOpenFaces(const Dictionary& region) {
  FaceFlags open{};
  for (const std::string& face : region.getWordList("open", kFaces))
    for (std::size_t f = 0; f < kFaces.size(); ++f)
      if (kFaces[f] == face) open[f] = true;
  return open;
}

/// layers and open of a container; layers and side of a boundary sphere or surface (a wall body); the motion
/// of any wall.
void readWallKeys(const Dictionary& region, ParticleRegion& r) {
  if (const auto motion = region.optionalSubDict("motion")) {
    if (r.phase != ParticleRegion::Phase::Boundary)
      region.fail("motion", "only walls (phase: boundary) have a prescribed motion; fluid and porous particles "
                            "move by the physics (give them an initial velocity instead)");
    r.motion = WallMotion::read(*motion);
  }
  const bool wallBody = r.phase == ParticleRegion::Phase::Boundary &&
                        (r.shape == ParticleRegion::Shape::Sphere || r.shape == ParticleRegion::Shape::Surface);
  if (r.shape == ParticleRegion::Shape::Container || wallBody)
    r.layers = static_cast<int>(region.getInt("layers", 2, Range::closed(1, 100)));
  if (r.shape == ParticleRegion::Shape::Container) r.open = readOpenFaces(region);
  if (wallBody)
    r.side = region.getWord("side", {"inside", "outside"}, "inside") == "inside" ? WallSide::Inside : WallSide::Outside;
}

} // namespace

std::vector<Vec3> ParticleRegion::sample(double particleRadius) const {
  if (shape == Shape::Box) return sampleBox(min, max, particleRadius);
  if (shape == Shape::Container) return sampleContainer(min, max, particleRadius, layers, open);
  const bool wall = phase == Phase::Boundary;
  std::vector<Vec3> points =
      wall ? sampleWallBody(*body, particleRadius, layers, side) : sampleInside(*body, particleRadius);
  if (points.empty()) {
    std::ostringstream msg;
    msg << where << ": region '" << name
        << "' holds no particle: no point of the lattice of spacing 2 particleRadius = " << 2.0 * particleRadius
        << " m lies " << (wall ? "in its wall" : "inside its surface") << " (bounding box from "
        << format(body->boxMin()) << " to " << format(body->boxMax()) << "); make particleRadius smaller";
    throw InputError(msg.str());
  }
  return points;
}

ParticleDict ParticleDict::read(const Dictionary& dict, const std::vector<PorousMaterial>& materials,
                                const std::filesystem::path& surfaceDirectory) {
  ParticleDict result;
  result.particleRadius = dict.getReal("particleRadius", Range::positive());
  std::vector<double> counts; // particles of each region, before any is sampled
  bool hasMatter = false; // a fluid or porous region: walls alone simulate nothing
  for (const Dictionary& region : dict.getDictList("regions")) {
    ParticleRegion r;
    r.name = region.getString("name");
    // Names become file names (postProcessing/rigidBodies/<name>.csv, saturationAnalysis' plots).
    const bool fileName = !r.name.empty() && r.name != "." && r.name != ".." &&
                          r.name.find_first_of(std::string("/\\\0", 3)) == std::string::npos;
    const std::string expected = "expected a region name that can be a file name (not empty, '.' or '..', no '/' "
                                 "or '\\'), got '";
    if (!fileName) region.fail("name", expected + r.name + "'");
    const std::string phase = region.getWord("phase", {"fluid", "porous", "boundary", "rigid"});
    r.phase = phase == "fluid"    ? ParticleRegion::Phase::Fluid
              : phase == "porous" ? ParticleRegion::Phase::Porous
              : phase == "rigid"  ? ParticleRegion::Phase::Rigid
                                  : ParticleRegion::Phase::Boundary;
    hasMatter = hasMatter || r.phase == ParticleRegion::Phase::Fluid || r.phase == ParticleRegion::Phase::Porous;
    r.shape = readShape(region, r.phase);
    r.where = region.where("shape");
    std::optional<SurfaceSource> surface;
    if (r.shape == ParticleRegion::Shape::Sphere)
      r.body = readSphere(region);
    else if (r.shape == ParticleRegion::Shape::Surface)
      surface = readSurfaceKeys(region, surfaceDirectory);
    else
      readBox(region, r);
    if (r.phase == ParticleRegion::Phase::Rigid) { // its particles start at rest; the body has the velocities
      r.rigid = RigidBody::read(region, static_cast<long long>(result.regions.size()));
    } else if (r.phase != ParticleRegion::Phase::Boundary) {
      r.velocity = region.getVec3("velocity", Vec3::Zero());
    }
    if (r.phase == ParticleRegion::Phase::Porous) {
      r.materialId = readMaterial(region, materials);
      r.fixed = region.getBool("fixed", false);
    }
    readWallKeys(region, r);
    region.checkUnknownKeys();
    for (const ParticleRegion& other : result.regions)
      if (other.name == r.name) region.fail("name", "region name '" + r.name + "' is used twice");
    if (surface) r.body = loadSurface(*surface);
    counts.push_back(pointCount(r, result.particleRadius));
    if (!r.body) checkNotEmpty(region, r, result.particleRadius, counts.back()); // spheres, surfaces: in sample()
    result.regions.push_back(r);
  }
  dict.checkUnknownKeys();
  if (!hasMatter)
    dict.fail("regions", "no region has phase fluid or porous; walls alone have nothing to simulate, so add a "
                         "region with phase: fluid or phase: porous");
  checkTotals(dict, result, counts);
  return result;
}

} // namespace poro
