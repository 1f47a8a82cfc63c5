#include "geometry/LatticeSampling.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

long long latticeCount(double length, double spacing) {
  const double quotient = length / spacing;
  const double floorQ = std::floor(quotient);
  // A quotient within 1e-9 (relative) of a half-integer counts as that half-integer and rounds up.
  if (std::abs(quotient - (floorQ + 0.5)) <= 1e-9 * std::max(1.0, quotient)) return static_cast<long long>(floorQ) + 1;
  return static_cast<long long>(std::llround(quotient));
}

namespace {

// Beyond 2^53 lattice points per axis a double no longer counts one by one; the estimate is all that matters.
constexpr double kExactLimit = 9007199254740992.0;

/// latticeCount without its integer conversion (which would overflow for absurd quotients).
double axisCount(double length, double spacing) {
  const double quotient = length / spacing;
  if (!(quotient < kExactLimit)) return quotient; // also inf and NaN
  return static_cast<double>(std::max(0LL, latticeCount(length, spacing)));
}

/// Inner coordinates of a container along one axis (the loop bound of sampleContainer).
double innerCount(double length, double spacing) {
  const double quotient = length / spacing;
  if (!(quotient < kExactLimit)) return quotient;
  return std::max(1.0, std::ceil(quotient - 1e-9));
}

} // namespace

double boxPointCount(const Vec3& min, const Vec3& max, double particleRadius) {
  const double spacing = 2.0 * particleRadius;
  return axisCount(max.x() - min.x(), spacing) * axisCount(max.y() - min.y(), spacing) *
         axisCount(max.z() - min.z(), spacing);
}

double containerPointCount(const Vec3& min, const Vec3& max, double particleRadius, int layers, const FaceFlags& open) {
  const double spacing = 2.0 * particleRadius;
  double inner[3], total[3];
  for (int d = 0; d < 3; ++d) {
    const int closed =
        (open[static_cast<std::size_t>(2 * d)] ? 0 : 1) + (open[static_cast<std::size_t>(2 * d + 1)] ? 0 : 1);
    inner[d] = innerCount(max[d] - min[d], spacing);
    total[d] = inner[d] + static_cast<double>(closed * layers);
  }
  // All points minus the inner ones, as a sum of positive terms: a difference of two huge products would cancel.
  return (total[0] - inner[0]) * total[1] * total[2] + inner[0] * (total[1] - inner[1]) * total[2] +
         inner[0] * inner[1] * (total[2] - inner[2]);
}

BoxLattice boxLattice(const Vec3& min, const Vec3& max, double particleRadius, long long extra) {
  BoxLattice lattice;
  lattice.spacing = 2.0 * particleRadius;
  lattice.first = -extra;
  for (int d = 0; d < 3; ++d) {
    lattice.origin[d] = min[d] + particleRadius;
    lattice.count[static_cast<std::size_t>(d)] =
        std::max(0LL, latticeCount(max[d] - min[d], lattice.spacing)) + 2 * extra;
  }
  return lattice;
}

std::vector<Vec3> sampleBox(const Vec3& min, const Vec3& max, double particleRadius) {
  const BoxLattice lattice = boxLattice(min, max, particleRadius);
  const auto& n = lattice.count;
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(n[0] * n[1] * n[2]));
  for (long long k = 0; k < n[2]; ++k)
    for (long long j = 0; j < n[1]; ++j)
      for (long long i = 0; i < n[0]; ++i)
        points.emplace_back(lattice.coordinate(0, i), lattice.coordinate(1, j), lattice.coordinate(2, k));
  return points;
}

std::vector<Vec3> sampleContainer(const Vec3& min, const Vec3& max, double particleRadius, int layers,
                                  const FaceFlags& open) {
  // Per axis: wall layers r, 3r, ... behind each closed face, and the inner coordinates between them. Every
  // wall is placed from its own face, so the walls sit right even when the inner extent is not a multiple
  // of 2r. A point is a wall point when at least one of its coordinates lies in a wall layer.
  const double spacing = 2.0 * particleRadius;
  struct Coordinate {
    double value;
    bool wall;
  };
  std::array<std::vector<Coordinate>, 3> axes;
  for (int d = 0; d < 3; ++d) {
    auto& axis = axes[static_cast<std::size_t>(d)];
    if (!open[static_cast<std::size_t>(2 * d)])
      for (int l = layers - 1; l >= 0; --l) axis.push_back({min[d] - particleRadius - spacing * l, true});
    // Along the faces the wall must leave no seam wider than 2r (fluid leaks through one): the inner extent
    // is split into ceil(L/2r) equal steps, which is the 2r lattice itself when L is a multiple of 2r.
    const double length = max[d] - min[d];
    const long long n = std::max(1LL, static_cast<long long>(std::ceil(length / spacing - 1e-9)));
    const double step = length / static_cast<double>(n);
    for (long long k = 0; k < n; ++k) axis.push_back({min[d] + step * (static_cast<double>(k) + 0.5), false});
    if (!open[static_cast<std::size_t>(2 * d + 1)])
      for (int l = 0; l < layers; ++l) axis.push_back({max[d] + particleRadius + spacing * l, true});
  }
  std::vector<Vec3> points;
  for (const Coordinate& z : axes[2])
    for (const Coordinate& y : axes[1])
      for (const Coordinate& x : axes[0])
        if (x.wall || y.wall || z.wall) points.emplace_back(x.value, y.value, z.value);
  return points;
}

} // namespace poro
