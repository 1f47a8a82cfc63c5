#pragma once
/// Per porous object: absorbed fluid, pore volume, saturation statistics and the wet region along the axis
/// (issue 6; definitions in saturationAnalysis -help and README "Using it").

#include "analysis/AnalysisSettings.hpp"
#include "analysis/PorousObjects.hpp"

#include <optional>

namespace poro {

struct ObjectStatistics {
  std::int64_t objectId = 0;
  std::string name;
  std::size_t solidParticles = 0;    ///< N_s, the object's porous particles
  std::size_t absorbedParticles = 0; ///< fluid particles inside the object (analysis/AbsorbedFluid.hpp)
  double absorbedVolume = 0.0;       ///< absorbedParticles V [m^3]
  double absorbedMass = 0.0;         ///< absorbedParticles rho0 V [kg]
  double poreVolume = 0.0;           ///< sum over its particles of phi V (phi of each particle's material) [m^3]
  double fractionFilled = 0.0;       ///< absorbedVolume / poreVolume (0 when there are no pores)
  /// Saturation statistics; empty when the particles carry no saturation field (0/ of sampleParticles,
  /// written before any step computed one).
  std::optional<double> meanSaturation, maxSaturation;
  std::size_t wetParticles = 0;         ///< saturation >= wetThreshold
  std::optional<double> wetMin, wetMax; ///< extent of the wet particles along the axis [m]; empty when none is wet
  std::optional<double> wetHeight;      ///< wetMax - wetMin [m]; 0 when none is wet, empty without saturation
  /// Where the solid is: mean, lowest and highest coordinate of its particles along the axis [m] (floating,
  /// sinking, squeezing); empty for an object without particles.
  std::optional<double> centre, minPosition, maxPosition;
  /// Largest density of its particles [kg/m^3] (a compressed skeleton stays <= rho_s^0); empty without data.
  std::optional<double> maxDensity;
};

/// Statistics of `object`; `absorbed` is its count from countAbsorbedFluid. Throws InputError when one of
/// its sets names no material of settings.materials.
ObjectStatistics objectStatistics(const ParticleSystem& particles, const PorousObject& object, std::size_t absorbed,
                                  const AnalysisSettings& settings);

} // namespace poro
