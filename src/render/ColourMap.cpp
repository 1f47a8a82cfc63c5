#include "render/ColourMap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace poro {

namespace {

/// Evenly spaced control points from 8-bit colours.
std::vector<std::array<double, 4>> even(const std::vector<std::array<int, 3>>& rgb) {
  std::vector<std::array<double, 4>> points;
  for (std::size_t k = 0; k < rgb.size(); ++k)
    points.push_back({double(k) / double(rgb.size() - 1), rgb[k][0] / 255.0, rgb[k][1] / 255.0, rgb[k][2] / 255.0});
  return points;
}

const std::vector<ColourMap>& all() {
  static const std::vector<ColourMap> maps = {
      ColourMap("wetness", even({{255, 255, 217}, {237, 248, 177}, {199, 233, 180}, {127, 205, 187}, {65, 182, 196},
                                 {29, 145, 192}, {34, 94, 168}, {37, 52, 148}, {8, 29, 88}})),
      ColourMap("blues", even({{247, 251, 255}, {222, 235, 247}, {198, 219, 239}, {158, 202, 225}, {107, 174, 214},
                               {66, 146, 198}, {33, 113, 181}, {8, 81, 156}, {8, 48, 107}})),
      ColourMap("viridis", even({{68, 1, 84}, {72, 40, 120}, {62, 74, 137}, {49, 104, 142}, {38, 130, 142},
                                 {31, 158, 137}, {53, 183, 121}, {109, 205, 89}, {180, 222, 44}, {253, 231, 37}})),
      ColourMap("coolToWarm", {{0.0, 0.230, 0.299, 0.754}, {0.5, 0.865, 0.865, 0.865}, {1.0, 0.706, 0.016, 0.150}}),
      ColourMap("greys", {{0.0, 1.0, 1.0, 1.0}, {1.0, 0.0, 0.0, 0.0}}),
  };
  return maps;
}

} // namespace

ColourMap::ColourMap(std::string name, std::vector<std::array<double, 4>> points)
    : name_(std::move(name)), points_(std::move(points)) {}

const ColourMap& ColourMap::named(const std::string& name) {
  for (const ColourMap& map : all())
    if (map.name() == name) return map;
  throw std::out_of_range("no colour map '" + name + "'");
}

std::vector<std::string> ColourMap::names() {
  std::vector<std::string> names;
  for (const ColourMap& map : all()) names.push_back(map.name());
  return names;
}

Vec3 ColourMap::at(double t) const {
  t = std::clamp(t, 0.0, 1.0);
  std::size_t k = 1;
  while (k + 1 < points_.size() && points_[k][0] < t) ++k;
  const auto& a = points_[k - 1];
  const auto& b = points_[k];
  const double s = b[0] > a[0] ? (t - a[0]) / (b[0] - a[0]) : 0.0;
  return Vec3(a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2]), a[3] + s * (b[3] - a[3]));
}

double ColourMap::lightness(const Vec3& rgb) {
  const auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  const double y = 0.2126 * linear(rgb[0]) + 0.7152 * linear(rgb[1]) + 0.0722 * linear(rgb[2]);
  return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : y * 24389.0 / 27.0;
}

} // namespace poro
