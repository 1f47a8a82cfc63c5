#include "analysis/SaturationProfiles.hpp"

#include "physics/FieldNames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

namespace poro {

std::vector<ProfileBin> saturationProfile(const ParticleSystem& particles, const PorousObject& object, const Axis& axis,
                                          double particleRadius) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& [set, i] : object.particles) {
    if (!particles[set].has(field::saturation)) return {};
    const double c = axis.coordinate(particles[set].x()[i]);
    if (std::isfinite(c)) lowest = std::min(lowest, c);
  }
  if (!std::isfinite(lowest)) return {};

  // Bin b covers [lowest - r + 2r b, lowest + r + 2r b). A map, not an array: a body torn apart may span
  // far more bins than it has particles.
  const double width = 2.0 * particleRadius;
  std::map<std::int64_t, std::pair<double, std::size_t>> bins;
  for (const auto& [set, i] : object.particles) {
    const double c = axis.coordinate(particles[set].x()[i]);
    if (!std::isfinite(c)) continue;
    const double b = std::min(std::floor((c - lowest + particleRadius) / width), 1e18);
    auto& [sum, count] = bins[static_cast<std::int64_t>(b)];
    sum += particles[set].real(field::saturation)[i];
    ++count;
  }
  std::vector<ProfileBin> profile;
  for (const auto& [b, bin] : bins)
    profile.push_back(
        {lowest + static_cast<double>(b) * width, bin.first / static_cast<double>(bin.second), bin.second});
  return profile;
}

} // namespace poro
