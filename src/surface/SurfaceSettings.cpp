#include "surface/SurfaceSettings.hpp"

#include "core/Dictionary.hpp"

#include <sstream>

namespace poro {

namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

ReconstructionSettings readReconstruction(const Dictionary& dict, const ReconstructionSettings& defaults) {
  ReconstructionSettings s = defaults;
  // Below 2 the kernel reaches fewer than the 6 nearest lattice neighbours and c ripples by more than the iso-level.
  s.kernelRadius = dict.getReal("kernelRadius", defaults.kernelRadius, Range::closed(2.0, 16.0));
  s.isoValue = dict.getReal("isoValue", defaults.isoValue, Range::open(0.0, 1.0));
  s.gridSpacing = dict.getReal("gridSpacing", defaults.gridSpacing, Range::closed(0.05, 8.0));
  s.smoothingIterations =
      static_cast<int>(dict.getInt("smoothingIterations", defaults.smoothingIterations, Range::closed(0, 200)));
  s.where = dict.where("gridSpacing");
  // A grid coarser than the kernel's support cannot resolve c, which rises from 0 to 1 over that width: the surface
  // would miss features and could break apart.
  if (s.gridSpacing > s.kernelRadius)
    dict.fail(dict.has("gridSpacing") ? "gridSpacing" : "kernelRadius",
              "expected gridSpacing (" + formatNumber(s.gridSpacing) + ") at most kernelRadius (" +
                  formatNumber(s.kernelRadius) + "): a grid coarser than the kernel's support cannot resolve the "
                  "colour field");
  return s;
}

} // namespace

SurfaceSettings readSurfaceSettings(const std::filesystem::path& caseDir) {
  SurfaceSettings s;
  const std::filesystem::path path = caseDir / "system" / "surfaceDict";
  s.fluid.where = s.porous.where = "system/surfaceDict (not present; defaults)";
  if (!std::filesystem::exists(path)) return s;
  const Dictionary dict = Dictionary::read(path.string());
  s.fluid.where = s.porous.where = dict.where("fluid");
  if (const auto fluid = dict.optionalSubDict("fluid")) {
    s.writeFluid = fluid->getBool("write", true);
    s.fluid = readReconstruction(*fluid, s.fluid);
    s.poreFluid = fluid->getWord("poreFluid", {"exclude", "include"}, "exclude") == "include" ? PoreFluid::Include
                                                                                              : PoreFluid::Exclude;
    fluid->checkUnknownKeys();
  }
  if (const auto porous = dict.optionalSubDict("porous")) {
    s.writePorous = porous->getBool("write", true);
    s.porous = readReconstruction(*porous, s.porous);
    porous->checkUnknownKeys();
  }
  dict.checkUnknownKeys();
  return s;
}

} // namespace poro
