#include "ParticleRegions.hpp"

#include "core/Dictionary.hpp"

#include <sstream>

namespace poro {

namespace {

const std::vector<std::string> kFaces = {"xMin", "xMax", "yMin", "yMax", "zMin", "zMax"};

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

FaceFlags readOpenFaces(const Dictionary& region) {
  FaceFlags open{};
  for (const std::string& face : region.getWordList("open", kFaces))
    for (std::size_t f = 0; f < kFaces.size(); ++f)
      if (kFaces[f] == face) open[f] = true;
  return open;
}

} // namespace

ParticleDict ParticleDict::read(const Dictionary& dict, const std::vector<PorousMaterial>& materials) {
  ParticleDict result;
  result.particleRadius = dict.getReal("particleRadius", Range::positive());
  for (const Dictionary& region : dict.getDictList("regions")) {
    ParticleRegion r;
    r.name = region.getString("name");
    const std::string phase = region.getWord("phase", {"fluid", "porous", "boundary"});
    r.phase = phase == "fluid"    ? ParticleRegion::Phase::Fluid
              : phase == "porous" ? ParticleRegion::Phase::Porous
                                  : ParticleRegion::Phase::Boundary;
    const std::string shape = r.phase != ParticleRegion::Phase::Boundary
                                  ? region.getWord("shape", {"box"})
                                  : region.getWord("shape", {"box", "container"});
    r.shape = shape == "box" ? ParticleRegion::Shape::Box : ParticleRegion::Shape::Container;
    r.min = region.getVec3("min");
    r.max = region.getVec3("max");
    for (int d = 0; d < 3; ++d)
      if (!(r.min[d] < r.max[d])) {
        std::ostringstream msg;
        msg << "expected max > min on every axis, got min [" << r.min.transpose() << "], max [" << r.max.transpose()
            << "]";
        region.fail("max", msg.str());
      }
    if (r.phase != ParticleRegion::Phase::Boundary) r.velocity = region.getVec3("velocity", Vec3::Zero());
    if (r.phase == ParticleRegion::Phase::Porous) {
      r.materialId = readMaterial(region, materials);
      r.fixed = region.getBool("fixed", false);
    }
    if (r.shape == ParticleRegion::Shape::Container) {
      r.layers = static_cast<int>(region.getInt("layers", 2, Range::closed(1, 100)));
      r.open = readOpenFaces(region);
    }
    region.checkUnknownKeys();
    for (const ParticleRegion& other : result.regions)
      if (other.name == r.name) region.fail("name", "region name '" + r.name + "' is used twice");
    result.regions.push_back(r);
  }
  dict.checkUnknownKeys();
  return result;
}

} // namespace poro
