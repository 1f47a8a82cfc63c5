#pragma once
/// Named colour maps for renderCase: piecewise-linear RGB through control points. Every sequential map changes
/// lightness monotonically, so a picture printed in grey still orders its values.

#include "core/Types.hpp"

#include <array>
#include <string>
#include <vector>

namespace poro {

class ColourMap {
public:
  /// Control points (t in [0, 1] increasing, r, g, b in [0, 1]).
  ColourMap(std::string name, std::vector<std::array<double, 4>> points);

  /// The map of that name: "wetness" (ColorBrewer YlGnBu: dry pale yellow to wet dark blue; lightness falls from
  /// 99 to 15 %, so wet reads dark and saturated, the default for saturation), "blues" (ColorBrewer Blues, white to
  /// dark blue), "viridis" (perceptually uniform, dark to light, the default for other fields), "coolToWarm"
  /// (Moreland's diverging map, for fields about a middle value such as pressure) and "greys" (white to black).
  /// Throws std::out_of_range for another name; names() lists them.
  static const ColourMap& named(const std::string& name);
  static std::vector<std::string> names();

  const std::string& name() const { return name_; }
  const std::vector<std::array<double, 4>>& points() const { return points_; }
  /// The colour at t (clamped to [0, 1]).
  Vec3 at(double t) const;
  /// CIE L* (0 black .. 100 white) of a colour in sRGB.
  static double lightness(const Vec3& rgb);

private:
  std::string name_;
  std::vector<std::array<double, 4>> points_;
};

} // namespace poro
