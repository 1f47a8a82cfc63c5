#pragma once
/// system/surfaceDict: how fluidSurface (and renderCase) turn particles into surfaces. The file and each of its
/// keys are optional; etc/caseDicts/surfaceDict documents them.

#include <filesystem>
#include <string>

namespace poro {

/// The surface of one phase: the level c = isoValue of the colour field c(x) = sum_j V_j W(x - x_j) (ColourField),
/// sampled on a grid and contoured.
struct ReconstructionSettings {
  double kernelRadius = 4.0; ///< support H of the cubic kernel in particle radii r: the smoothing (solver: 4)
  double isoValue = 0.5;     ///< c is 1 inside a lattice of particles and 0 away from it; 0.5 lies on its faces
  double gridSpacing = 1.0;  ///< grid spacing in particle radii r
  int smoothingIterations = 0; ///< windowed-sinc smoothing of the mesh (IsoSurface.hpp); 0: none
  std::string where;         ///< "system/surfaceDict:7" of gridSpacing (or of the file), for size errors
};

/// What happens to fluid inside porous bodies (within the lattice cell of a porous particle, as
/// saturationAnalysis counts it) in the fluid surface.
enum class PoreFluid {
  Exclude, ///< left out: it shows as the saturation of the porous surface, not as a second skin around the body
  Include  ///< part of the fluid like any other
};

struct SurfaceSettings {
  bool writeFluid = true;  ///< fluid.write: <t>/fluidSurface.vtp
  bool writePorous = true; ///< porous.write: <t>/porousSurface.vtp (cases with porous bodies)
  ReconstructionSettings fluid, porous;
  PoreFluid poreFluid = PoreFluid::Exclude;
};

/// Reads `<caseDir>/system/surfaceDict` (defaults without it). Unknown keys, wrong types and out-of-range values
/// are InputErrors naming file, line and key.
SurfaceSettings readSurfaceSettings(const std::filesystem::path& caseDir);

} // namespace poro
