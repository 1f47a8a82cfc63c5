#include "geometry/LatticeSampling.hpp"

#include <cmath>

namespace poro {

long long latticeCount(double length, double spacing) {
  const double quotient = length / spacing;
  const double floorQ = std::floor(quotient);
  // A quotient within 1e-9 (relative) of a half-integer counts as that half-integer and rounds up.
  if (std::abs(quotient - (floorQ + 0.5)) <= 1e-9 * std::max(1.0, quotient)) return static_cast<long long>(floorQ) + 1;
  return static_cast<long long>(std::llround(quotient));
}

std::vector<Vec3> sampleBox(const Vec3& min, const Vec3& max, double particleRadius) {
  const double spacing = 2.0 * particleRadius;
  long long n[3];
  for (int d = 0; d < 3; ++d) n[d] = std::max(0LL, latticeCount(max[d] - min[d], spacing));
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(n[0] * n[1] * n[2]));
  for (long long k = 0; k < n[2]; ++k)
    for (long long j = 0; j < n[1]; ++j)
      for (long long i = 0; i < n[0]; ++i)
        points.emplace_back(min.x() + particleRadius + spacing * static_cast<double>(i),
                            min.y() + particleRadius + spacing * static_cast<double>(j),
                            min.z() + particleRadius + spacing * static_cast<double>(k));
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
