#include "analysis/SaturationStatistics.hpp"

#include "core/Error.hpp"
#include "physics/FieldNames.hpp"

#include <algorithm>

namespace poro {

namespace {

double porosityOf(const ParticleSet& set, const std::vector<PorousMaterial>& materials) {
  for (const PorousMaterial& m : materials)
    if (m.name == set.name()) return m.porosity;
  throw InputError("porous particle set '" + set.name() + "': no such material in constant/porosityProperties");
}

/// Centre and extent of the object along the axis, and its largest density where the sets carry one.
void addPlacement(const ParticleSystem& particles, const PorousObject& object, const Axis& axis,
                  ObjectStatistics& stats) {
  if (object.particles.empty()) return;
  double sum = 0.0, lo = 0.0, hi = 0.0, densest = 0.0;
  bool first = true, densities = true;
  for (const auto& [set, i] : object.particles) {
    const double c = axis.coordinate(particles[set].x()[i]);
    sum += c;
    lo = first ? c : std::min(lo, c);
    hi = first ? c : std::max(hi, c);
    first = false;
    densities = densities && particles[set].has(field::density);
    if (densities) densest = std::max(densest, particles[set].real(field::density)[i]);
  }
  stats.centre = sum / static_cast<double>(object.particles.size());
  stats.minPosition = lo;
  stats.maxPosition = hi;
  if (densities) stats.maxDensity = densest;
}

} // namespace

ObjectStatistics objectStatistics(const ParticleSystem& particles, const PorousObject& object, std::size_t absorbed,
                                  const AnalysisSettings& settings) {
  const double volume = settings.particleVolume();
  ObjectStatistics stats;
  stats.objectId = object.objectId;
  stats.name = object.name;
  stats.solidParticles = object.particles.size();
  stats.absorbedParticles = absorbed;
  stats.absorbedVolume = static_cast<double>(absorbed) * volume;
  stats.absorbedMass = static_cast<double>(absorbed) * settings.fluidDensity * volume;

  // Pore volume per set as phi N V: the sum over particles would add round-off to a known product.
  bool saturated = true; // every set of the object has a saturation field
  std::vector<std::size_t> perSet(particles.size(), 0);
  for (const auto& particle : object.particles) {
    saturated = saturated && particles[particle.first].has(field::saturation);
    ++perSet[particle.first];
  }
  for (std::size_t set = 0; set < particles.size(); ++set)
    if (perSet[set] > 0)
      stats.poreVolume += porosityOf(particles[set], settings.materials) * static_cast<double>(perSet[set]) * volume;

  stats.fractionFilled = stats.poreVolume > 0.0 ? stats.absorbedVolume / stats.poreVolume : 0.0;
  addPlacement(particles, object, settings.axis, stats);
  if (!saturated || object.particles.empty()) return stats; // saturation unknown (0/ of sampleParticles)

  double sum = 0.0, largest = 0.0, lo = 0.0, hi = 0.0;
  for (const auto& [set, i] : object.particles) {
    const double s = particles[set].real(field::saturation)[i];
    sum += s;
    largest = std::max(largest, s);
    if (s < settings.wetThreshold) continue;
    const double c = settings.axis.coordinate(particles[set].x()[i]);
    lo = stats.wetParticles == 0 ? c : std::min(lo, c);
    hi = stats.wetParticles == 0 ? c : std::max(hi, c);
    ++stats.wetParticles;
  }
  stats.meanSaturation = sum / static_cast<double>(stats.solidParticles);
  stats.maxSaturation = largest;
  stats.wetHeight = 0.0;
  if (stats.wetParticles > 0) {
    stats.wetMin = lo;
    stats.wetMax = hi;
    stats.wetHeight = hi - lo;
  }
  return stats;
}

} // namespace poro
