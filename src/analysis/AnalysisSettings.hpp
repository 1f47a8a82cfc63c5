#pragma once
/// What saturationAnalysis needs to know about a case besides its particles: particle radius, fluid rest
/// density, porous materials and the names of the sampled regions, plus the user's axis and wet threshold.

#include "analysis/Axis.hpp"
#include "physics/PorousMaterial.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

struct AnalysisSettings {
  double particleRadius = 0.0;           ///< r [m] (system/particleDict); particle volume V = (2r)^3
  double fluidDensity = 1000.0;          ///< rho0 [kg/m^3] (constant/fluidProperties density)
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);  ///< g [m/s^2] (constant/fluidProperties): potential energy
  std::vector<PorousMaterial> materials; ///< constant/porosityProperties, file order (porous sets are named so)
  std::vector<std::string> regionNames;  ///< names of system/particleDict's regions; index = objectId
  Axis axis;                             ///< fronts and profiles are measured along it (default: up)
  double wetThreshold = 0.5;             ///< a porous particle with saturation >= this is wet

  double particleVolume() const { return 8.0 * particleRadius * particleRadius * particleRadius; }
};

/// Reads system/particleDict (particleRadius; region names, best effort: a region list it cannot read leaves
/// objects named "object<k>"), constant/fluidProperties (density, gravity; the axis defaults to Axis::up of it)
/// and constant/porosityProperties. Missing or invalid files are InputErrors naming the file.
AnalysisSettings readAnalysisSettings(const std::filesystem::path& caseDir);

/// The names of the regions the particles of `timeDir` were sampled from (its uniform/sampling), which name its
/// objects even after system/particleDict changed; `current` (particleDict's) for a time written before the record.
std::vector<std::string> sampledRegionNames(const std::filesystem::path& timeDir,
                                            const std::vector<std::string>& current);

} // namespace poro
