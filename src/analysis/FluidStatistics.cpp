#include "analysis/FluidStatistics.hpp"

#include "physics/FieldNames.hpp"

#include <algorithm>

namespace poro {

FluidStatistics fluidStatistics(const ParticleSet& fluid, double restDensity, double particleVolume) {
  FluidStatistics stats;
  stats.particles = fluid.size();
  const double mass = restDensity * particleVolume;
  double twiceEnergy = 0.0;
  for (const Vec3& v : fluid.v()) {
    twiceEnergy += v.squaredNorm();
    stats.momentum += v;
  }
  stats.kineticEnergy = 0.5 * mass * twiceEnergy;
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
