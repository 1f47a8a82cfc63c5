#include "physics/PorousMaterial.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace poro {

namespace {

/// Names that already mean a particle set and a file of a time directory (fluid.vtp, boundary.vtp).
const char* const kReservedNames[] = {"fluid", "boundary", "rigid"};

bool isIdentifier(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}

void checkName(const Dictionary& dict, const std::string& name) {
  if (!isIdentifier(name))
    dict.fail(name, "a material name must be an identifier (a letter or '_', then letters, digits or '_'), got '" +
                        name + "'");
  for (const char* reserved : kReservedNames)
    if (name == reserved)
      dict.fail(name, "'" + name + "' cannot name a porous material: it is the name of the " + name +
                          " particle set (choose another name, e.g. sand)");
}

std::pair<Vec3, Vec3> readFixedBox(const Dictionary& box) {
  const Vec3 min = box.getVec3("min");
  const Vec3 max = box.getVec3("max");
  box.checkUnknownKeys();
  for (int d = 0; d < 3; ++d)
    if (!(min[d] < max[d])) {
      std::ostringstream msg;
      msg << "expected max > min on every axis, got min [" << min.x() << ", " << min.y() << ", " << min.z()
          << "], max [" << max.x() << ", " << max.y() << ", " << max.z() << "]";
      box.fail("max", msg.str());
    }
  return {min, max};
}

PorousMaterial readMaterial(const std::string& name, const Dictionary& m) {
  PorousMaterial p;
  p.name = name;
  p.porosity = m.getReal("porosity", Range::halfOpen(0.0, 1.0));
  // Exactly one of the two densities; read both with their range first so a bad value names its own key.
  const bool hasSolid = m.has("solidDensity"), hasBulk = m.has("bulkDensity");
  const double solid = m.getReal("solidDensity", 0.0, Range::positive());
  const double bulk = m.getReal("bulkDensity", 0.0, Range::positive());
  p.compressible = m.getBool("compressible", p.compressible);
  p.dragViscosity = m.getReal("dragViscosity", p.dragViscosity, Range::nonNegative());
  // Upper bounds beyond any material, so that a slip of the exponent is an input error, not a failed solve: diamond's
  // E is 1.2e12 Pa, and hourglassControl 1 already removes the modes it is for.
  p.youngsModulus = m.getReal("youngsModulus", p.youngsModulus, Range::closed(0.0, kMaxYoungsModulus));
  p.poissonsRatio = m.getReal("poissonsRatio", p.poissonsRatio, Range::open(-1.0, 0.5));
  p.hourglassControl = m.getReal("hourglassControl", p.hourglassControl, Range::closed(0.0, kMaxHourglassControl));
  p.capillaryStrength = m.getReal("capillaryStrength", p.capillaryStrength, Range::nonNegative());
  p.capillaryFalloff = m.getReal("capillaryFalloff", p.capillaryFalloff, Range::closed(0.0, 1.0));
  p.bloating = m.getReal("bloating", p.bloating, Range::any());
  p.shearSoftening = m.getReal("shearSoftening", p.shearSoftening, Range::any());
  p.volumeSoftening = m.getReal("volumeSoftening", p.volumeSoftening, Range::any());
  p.dampingViscosity = m.getReal("dampingViscosity", p.dampingViscosity, Range::nonNegative());
  p.boundaryDampingViscosity =
      m.getReal("boundaryDampingViscosity", p.boundaryDampingViscosity, Range::nonNegative());
  if (const auto box = m.optionalSubDict("fixedBox")) p.fixedBox = readFixedBox(*box);
  // The elastic terms' keys do nothing without elasticity: say so rather than run as if they were taken.
  if (!(p.youngsModulus > 0.0)) {
    const PorousMaterial defaults;
    const std::pair<const char*, bool> elastic[] = {
        {"poissonsRatio", p.poissonsRatio != defaults.poissonsRatio},
        {"hourglassControl", p.hourglassControl != defaults.hourglassControl},
        {"bloating", p.bloating != defaults.bloating},
        {"shearSoftening", p.shearSoftening != defaults.shearSoftening},
        {"volumeSoftening", p.volumeSoftening != defaults.volumeSoftening}};
    for (const auto& [key, set] : elastic)
      if (set)
        log::warning(m.where(key) + ": key '" + name + "." + key +
                     "' has no effect: it belongs to the elastic terms, which need youngsModulus > 0 (here 0)");
  }
  // Before the density checks: a misspelt "solidDensty" gets its "did you mean" rather than "missing".
  m.checkUnknownKeys();

  if (hasSolid && hasBulk) {
    const auto keys = m.keys();
    const bool solidFirst =
        std::find(keys.begin(), keys.end(), "solidDensity") < std::find(keys.begin(), keys.end(), "bulkDensity");
    const std::string first = solidFirst ? "solidDensity" : "bulkDensity";
    const std::string second = solidFirst ? "bulkDensity" : "solidDensity";
    m.fail(second, "give either solidDensity or bulkDensity, not both: " + first + " is given at " + m.where(first) +
                       ", and bulkDensity = (1 - porosity) solidDensity follows from it");
  }
  if (!hasSolid && !hasBulk)
    throw InputError(m.where("") + ": material '" + name +
                     "': missing required key 'solidDensity' or 'bulkDensity' (give exactly one: the density of "
                     "the solid phase, or the bulk density (1 - porosity) solidDensity, in kg/m^3)");
  if (hasSolid) {
    p.solidDensity = solid;
    p.bulkDensity = (1.0 - p.porosity) * solid;
  } else {
    p.bulkDensity = bulk;
    p.solidDensity = bulk / (1.0 - p.porosity);
  }
  return p;
}

} // namespace

std::vector<PorousMaterial> PorousMaterial::readAll(const Dictionary& dict) {
  std::vector<PorousMaterial> materials;
  for (const std::string& name : dict.keys()) {
    checkName(dict, name);
    materials.push_back(readMaterial(name, dict.subDict(name)));
  }
  dict.checkUnknownKeys();
  if (materials.empty())
    throw InputError(dict.where("") + ": no material; constant/porosityProperties maps material names to their "
                                      "properties (see etc/caseDicts/porosityProperties)");
  return materials;
}

} // namespace poro
