#include "analysis/FluidStatistics.hpp"

#include "physics/FieldNames.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

FluidStatistics fluidStatistics(const ParticleSet& fluid, const AnalysisSettings& settings) {
  FluidStatistics stats;
  stats.particles = fluid.size();
  const double restDensity = settings.fluidDensity;
  const double mass = restDensity * settings.particleVolume();
  double twiceEnergy = 0.0, height = 0.0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vec3& v = fluid.v()[i];
    const Vec3& x = fluid.x()[i];
    twiceEnergy += v.squaredNorm();
    stats.momentum += v;
    stats.maxSpeed = std::max(stats.maxSpeed, v.norm());
    if (!x.allFinite()) continue; // cannot come from a readable file; kept out of the sums all the same
    height -= settings.gravity.dot(x);
    const double along = settings.axis.coordinate(x);
    stats.minPosition = std::min(stats.minPosition.value_or(along), along);
    stats.maxPosition = std::max(stats.maxPosition.value_or(along), along);
  }
  stats.kineticEnergy = 0.5 * mass * twiceEnergy;
  stats.potentialEnergy = mass * height;
  stats.momentum *= mass;
  if (fluid.has(field::density)) {
    double sum = 0.0, largest = 0.0;
    for (const double rho : fluid.real(field::density)) {
      const double error = 100.0 * std::max(rho / restDensity - 1.0, 0.0);
      sum += error;
      largest = std::max(largest, error);
    }
    stats.meanDensityError = fluid.size() > 0 ? sum / static_cast<double>(fluid.size()) : 0.0;
    stats.maxDensityError = largest;
  }
  return stats;
}

} // namespace poro
