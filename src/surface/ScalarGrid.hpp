#pragma once
/// Values at the points of a uniform grid: the colour field ColourField fills and IsoSurface contours.

#include "core/Types.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace poro {

struct ScalarGrid {
  Vec3 origin = Vec3::Zero();                ///< position of point (0, 0, 0) [m]
  double spacing = 1.0;                      ///< distance between neighbouring points [m]
  std::array<std::int64_t, 3> dims{0, 0, 0}; ///< points per axis
  std::vector<float> values;                 ///< values[(k dims[1] + j) dims[0] + i] at origin + spacing (i, j, k)

  std::size_t points() const { return static_cast<std::size_t>(dims[0] * dims[1] * dims[2]); }
  std::size_t index(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::size_t>((k * dims[1] + j) * dims[0] + i);
  }
  /// Trilinear interpolation at x; 0 outside the grid.
  double sample(const Vec3& x) const {
    const Vec3 local = (x - origin) / spacing;
    std::int64_t at[3];
    double frac[3];
    for (std::size_t a = 0; a < 3; ++a) {
      const double f = std::floor(local[static_cast<int>(a)]);
      if (!(f >= 0.0) || f >= double(dims[a] - 1)) return 0.0;
      at[a] = static_cast<std::int64_t>(f);
      frac[a] = local[static_cast<int>(a)] - f;
    }
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
      double weight = 1.0;
      std::int64_t ijk[3];
      for (int a = 0; a < 3; ++a) {
        const bool upper = (corner >> a) & 1;
        ijk[a] = at[a] + upper;
        weight *= upper ? frac[a] : 1.0 - frac[a];
      }
      sum += weight * values[index(ijk[0], ijk[1], ijk[2])];
    }
    return sum;
  }
};

} // namespace poro
