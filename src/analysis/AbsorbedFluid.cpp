#include "analysis/AbsorbedFluid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace poro {

namespace {

/// Solid particles hashed by their cell of the grid of edge 2r. Keys wrap every 2^21 cells per axis; the
/// distance test below makes a collision cost time only, never a wrong answer.
class SolidCells {
public:
  explicit SolidCells(double cellSize) : inverse_(1.0 / cellSize) {}

  void insert(const Vec3& x, std::size_t object) {
    const Cell c = cellOf(x);
    cells_[key(c.x, c.y, c.z)].push_back({x, object});
  }

  /// Calls visit(object) for every solid particle with |x - x_s|_inf <= r.
  template <class Visit> void forEachContaining(const Vec3& x, double r, const Visit& visit) const {
    const Cell c = cellOf(x);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const auto it = cells_.find(key(c.x + dx, c.y + dy, c.z + dz));
          if (it == cells_.end()) continue;
          for (const Solid& s : it->second)
            if ((x - s.x).cwiseAbs().maxCoeff() <= r) visit(s.object);
        }
  }

private:
  struct Cell {
    std::int64_t x, y, z;
  };
  struct Solid {
    Vec3 x;
    std::size_t object;
  };
  Cell cellOf(const Vec3& x) const {
    // Clamped: a particle that flew far away must not overflow the conversion.
    const auto at = [&](double v) {
      return static_cast<std::int64_t>(std::clamp(std::floor(v * inverse_), -4e18, 4e18));
    };
    return {at(x.x()), at(x.y()), at(x.z())};
  }
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    constexpr std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
    return (static_cast<std::uint64_t>(x) & mask) << 42 | (static_cast<std::uint64_t>(y) & mask) << 21 |
           (static_cast<std::uint64_t>(z) & mask);
  }
  double inverse_;
  std::unordered_map<std::uint64_t, std::vector<Solid>> cells_;
};

/// Round-off in the sampled lattice (min + r + 2r k) must not decide whether a particle on a face is inside.
double insideDistance(double particleRadius) { return particleRadius * (1.0 + 1e-9); }

SolidCells cellsOf(const ParticleSystem& particles, const std::vector<PorousObject>& objects, double particleRadius) {
  SolidCells cells(2.0 * particleRadius);
  for (std::size_t k = 0; k < objects.size(); ++k)
    for (const auto& [set, i] : objects[k].particles) {
      const Vec3& x = particles[set].x()[i];
      if (x.allFinite()) cells.insert(x, k);
    }
  return cells;
}

} // namespace

std::vector<std::size_t> countAbsorbedFluid(const std::vector<Vec3>& fluid, const ParticleSystem& particles,
                                            const std::vector<PorousObject>& objects, double particleRadius) {
  const double r = insideDistance(particleRadius);
  const SolidCells cells = cellsOf(particles, objects, particleRadius);

  std::vector<std::size_t> counts(objects.size(), 0);
  std::vector<std::size_t> lastCounted(objects.size(), fluid.size()); // the fluid particle an object last counted
  for (std::size_t f = 0; f < fluid.size(); ++f) {
    if (!fluid[f].allFinite()) continue;
    cells.forEachContaining(fluid[f], r, [&](std::size_t object) {
      if (lastCounted[object] == f) return;
      lastCounted[object] = f;
      ++counts[object];
    });
  }
  return counts;
}

std::vector<bool> absorbedFluid(const std::vector<Vec3>& fluid, const ParticleSystem& particles,
                                const std::vector<PorousObject>& objects, double particleRadius) {
  const double r = insideDistance(particleRadius);
  const SolidCells cells = cellsOf(particles, objects, particleRadius);
  std::vector<bool> inside(fluid.size(), false);
  for (std::size_t f = 0; f < fluid.size(); ++f)
    if (fluid[f].allFinite()) cells.forEachContaining(fluid[f], r, [&](std::size_t) { inside[f] = true; });
  return inside;
}

} // namespace poro
