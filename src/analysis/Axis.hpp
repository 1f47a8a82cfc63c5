#pragma once
/// The direction along which saturationAnalysis measures wet fronts and saturation profiles: one coordinate
/// axis with a sign. A particle's position along it is x·a (a = ±e_x, ±e_y or ±e_z) [m].

#include "core/Types.hpp"

#include <string>

namespace poro {

struct Axis {
  int component = 1; ///< 0 = x, 1 = y, 2 = z
  double sign = 1.0; ///< +1 or -1

  /// "x", "y", "z", "-x", "-y" or "-z".
  std::string name() const;
  /// The position along the axis [m].
  double coordinate(const Vec3& x) const { return sign * x[component]; }

  /// Parses x, y, z, -x, -y, -z (a leading + is accepted). Anything else is an InputError naming `option`.
  static Axis parse(const std::string& text, const std::string& option = "-axis");
  /// "Up": the axis of gravity's largest component, pointing against gravity; +y when gravity is zero.
  static Axis up(const Vec3& gravity);
};

} // namespace poro
