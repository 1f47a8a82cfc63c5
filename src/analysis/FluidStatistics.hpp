#pragma once
/// Whole-fluid quantities per time: density error, energies, momentum, speed and extent along the axis.

#include "analysis/AnalysisSettings.hpp"
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
  /// sum -m g.x [J], zero at the origin: differences over time are what count. Like the extent, over the
  /// particles with a finite position.
  double potentialEnergy = 0.0;
  Vec3 momentum = Vec3::Zero(); ///< sum m v [kg m/s]
  double maxSpeed = 0.0;        ///< max |v| [m/s]
  double meanSpeed = 0.0;       ///< mean |v| [m/s]
  /// Hydrostatic check: minus the least-squares slope of the pressure against the height (along -g) over the
  /// particles between 15 % and 85 % of the way from the lowest to the highest one and three spacings inside the
  /// fluid's horizontal extent, divided by rho0 |g| (1 for a pool at rest). Empty without a pressure field,
  /// gravity or a height range.
  std::optional<double> pressureGradient;
  /// Lowest and highest particle centre along the analysis axis [m] (a surge front with -axis x, the free
  /// surface of a pool with the default axis). Empty without fluid particles.
  std::optional<double> minPosition, maxPosition;
};

/// Uses settings.fluidDensity rho0, particleVolume() V, gravity g and axis.
FluidStatistics fluidStatistics(const ParticleSet& fluid, const AnalysisSettings& settings);

} // namespace poro
