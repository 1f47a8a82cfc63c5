#pragma once
/// Whole-fluid quantities per time: density error, kinetic energy and momentum.

#include "sph/ParticleSet.hpp"

#include <optional>

namespace poro {

struct FluidStatistics {
  std::size_t particles = 0;
  /// Density error e_i = max(rho_i / rho0 - 1, 0) in % of the stored `density` field, mean over all fluid
  /// particles and largest. Compression only, as the pressure solver measures it (PressureSolver: residual
  /// max(-r, 0)); the density deficit at a free surface is no error. Empty without a density field (0/).
  std::optional<double> meanDensityError, maxDensityError;
  double kineticEnergy = 0.0;   ///< sum 1/2 m |v|^2, m = rho0 V [J]
  Vec3 momentum = Vec3::Zero(); ///< sum m v [kg m/s]
};

/// `restDensity` rho0 [kg/m^3], `particleVolume` V = (2r)^3 [m^3].
FluidStatistics fluidStatistics(const ParticleSet& fluid, double restDensity, double particleVolume);

} // namespace poro
