#pragma once
/// Saturation profile of a porous object along the axis: its particles binned by their position along the
/// axis in bins of width 2r (one lattice layer each for an axis-aligned lattice), mean saturation per bin.

#include "analysis/Axis.hpp"
#include "analysis/PorousObjects.hpp"

#include <vector>

namespace poro {

struct ProfileBin {
  double position = 0.0;       ///< centre of the bin along the axis [m]
  double meanSaturation = 0.0; ///< mean saturation of the particles in the bin
  std::size_t particles = 0;   ///< particles in the bin (> 0)
};

/// Bins of width 2r from (lowest particle position along the axis) - r up, so that a lattice layer at c lands
/// in the bin centred on c; empty bins are left out. Empty when the object's sets have no saturation field.
std::vector<ProfileBin> saturationProfile(const ParticleSystem& particles, const PorousObject& object, const Axis& axis,
                                          double particleRadius);

} // namespace poro
