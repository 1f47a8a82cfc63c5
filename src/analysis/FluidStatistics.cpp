#include "analysis/FluidStatistics.hpp"

#include "physics/FieldNames.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

namespace {

std::optional<double> pressureGradient(const ParticleSet& fluid, const AnalysisSettings& settings) {
  const double g = settings.gravity.norm();
  if (!fluid.has(field::pressure) || g == 0.0 || fluid.size() == 0) return std::nullopt;
  const Vec3 up = -settings.gravity / g;
  int vertical = 0;
  up.cwiseAbs().maxCoeff(&vertical);
  double lo = up.dot(fluid.x()[0]), hi = lo;
  Vec3 boxMin = fluid.x()[0], boxMax = boxMin;
  for (const Vec3& x : fluid.x()) {
    lo = std::min(lo, up.dot(x));
    hi = std::max(hi, up.dot(x));
    boxMin = boxMin.cwiseMin(x);
    boxMax = boxMax.cwiseMax(x);
  }
  // The band leaves out the floor's and the surface's layers, the margin the particles next to side walls: the
  // one-sided wall pressure term (METHOD.md §6.2) holds them up with a steeper gradient (about 1.6 rho0 g).
  const double bottom = lo + 0.15 * (hi - lo), top = lo + 0.85 * (hi - lo);
  const double margin = 3.0 * std::cbrt(settings.particleVolume()); // three spacings 2r
  const auto& p = fluid.real(field::pressure);
  double n = 0, sh = 0, sp = 0, shh = 0, shp = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    const Vec3& x = fluid.x()[i];
    const double h = up.dot(x);
    bool inside = h >= bottom && h <= top;
    for (int d = 0; d < 3; ++d)
      if (d != vertical) inside = inside && x[d] > boxMin[d] + margin && x[d] < boxMax[d] - margin;
    if (!inside) continue;
    n += 1;
    sh += h;
    sp += p[i];
    shh += h * h;
    shp += h * p[i];
  }
  const double spread = n * shh - sh * sh;
  if (n < 2 || !(spread > 0.0)) return std::nullopt;
  return -(n * shp - sh * sp) / spread / (settings.fluidDensity * g);
}

} // namespace

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
    stats.meanSpeed += v.norm();
    if (!x.allFinite()) continue; // cannot come from a readable file; kept out of the sums all the same
    height -= settings.gravity.dot(x);
    const double along = settings.axis.coordinate(x);
    stats.minPosition = std::min(stats.minPosition.value_or(along), along);
    stats.maxPosition = std::max(stats.maxPosition.value_or(along), along);
  }
  if (fluid.size() > 0) stats.meanSpeed /= static_cast<double>(fluid.size());
  stats.pressureGradient = pressureGradient(fluid, settings);
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
