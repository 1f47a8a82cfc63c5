#include "RegionShapes.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "geometry/Sphere.hpp"
#include "geometry/SurfaceFile.hpp"
#include "geometry/SurfaceMesh.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace poro {

namespace fs = std::filesystem;

namespace {

std::string format(const Vec3& v) {
  std::ostringstream out;
  out << '[' << v.x() << ", " << v.y() << ", " << v.z() << ']';
  return out.str();
}

/// `scale` is a number or [sx, sy, sz]. A Dictionary getter reads one kind of value, so the number is tried first.
Vec3 readScale(const Dictionary& region) {
  if (!region.has("scale")) return Vec3::Ones();
  bool isNumber = true;
  try {
    region.getReal("scale");
  } catch (const InputError&) {
    isNumber = false;
  }
  if (isNumber) return Vec3::Constant(region.getReal("scale", Range::positive()));
  Vec3 scale;
  try {
    scale = region.getVec3("scale");
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + ", or a single number > 0");
  }
  if (!(scale.minCoeff() > 0.0))
    region.fail("scale", "expected scale factors > 0 (mirroring is not supported), got " + format(scale));
  return scale;
}

/// "there is no directory ..." or the files that are there, for a `file` that is missing.
std::string listSurfaces(const fs::path& directory) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return "there is no directory " + directory.string();
  std::vector<std::string> names; // directories with a trailing '/': a folder is not a surface file
  for (const auto& entry : fs::directory_iterator(directory, ec))
    if (entry.is_regular_file() || entry.is_directory())
      names.push_back(entry.path().filename().string() + (entry.is_directory() ? "/" : ""));
  if (names.empty()) return directory.string() + " is empty";
  std::sort(names.begin(), names.end());
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return directory.string() + " holds: " + list;
}

} // namespace

std::shared_ptr<const ClosedShape> readSphere(const Dictionary& region) {
  const Vec3 centre = region.getVec3("centre");
  return std::make_shared<Sphere>(centre, region.getReal("radius", Range::positive()));
}

SurfaceTransform readSurfaceTransform(const Dictionary& region) {
  SurfaceTransform transform;
  transform.scale = readScale(region);
  if (const auto rotate = region.optionalSubDict("rotate")) {
    transform.rotationAxis = rotate->getVec3("axis");
    if (!(transform.rotationAxis.norm() > 0.0))
      rotate->fail("axis", "expected a non-zero vector to rotate about, got " + format(transform.rotationAxis));
    transform.rotationDegrees = rotate->getReal("angle");
    rotate->checkUnknownKeys();
  }
  transform.translation = region.getVec3("translate", Vec3::Zero());
  return transform;
}

SurfaceSource readSurfaceKeys(const Dictionary& region, const fs::path& surfaceDirectory) {
  SurfaceSource source;
  source.path = surfaceDirectory / region.getString("file");
  std::error_code ec;
  if (fs::is_directory(source.path, ec))
    region.fail("file", source.path.string() + " is a directory; expected a surface file (STL, OBJ, OFF or PLY)");
  if (!fs::is_regular_file(source.path, ec))
    region.fail("file", "no surface file " + source.path.string() + "; " + listSurfaces(surfaceDirectory));
  source.transform = readSurfaceTransform(region);
  source.repair = region.getBool("repair", false);
  return source;
}

std::shared_ptr<const ClosedShape> loadSurface(const SurfaceSource& source) {
  SurfaceFile file = SurfaceFile::read(source.path.string(), source.repair);
  for (const std::string& note : file.notes) log::info("Note: " + source.path.string() + ": " + note);
  source.transform.applyTo(file.mesh);
  auto surface = std::make_shared<SurfaceMesh>(file.mesh);
  std::ostringstream line;
  line << "Read " << source.path.string() << ": " << surface->triangleCount() << " triangles enclosing "
       << surface->volume() << " m^3, placed in the box from " << format(surface->boxMin()) << " to "
       << format(surface->boxMax());
  log::info(line.str());
  return surface;
}

} // namespace poro
