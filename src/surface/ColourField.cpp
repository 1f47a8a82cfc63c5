#include "surface/ColourField.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "sph/Kernel.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poro {

namespace {

constexpr std::int64_t kSlabLayers = 8; // grid layers per parallel task

/// Bounds of the finite particles; false when there are none.
bool finiteBounds(const std::vector<Vec3>& x, Vec3& lo, Vec3& hi) {
  bool any = false;
  for (const Vec3& p : x) {
    if (!p.allFinite()) continue;
    lo = any ? Vec3(lo.cwiseMin(p)) : p;
    hi = any ? Vec3(hi.cwiseMax(p)) : p;
    any = true;
  }
  return any;
}

} // namespace

ScalarGrid colourField(const ParticleCloud& cloud, double supportRadius, double spacing, const std::string& where) {
  ScalarGrid grid;
  grid.spacing = spacing;
  Vec3 lo, hi;
  if (!finiteBounds(cloud.positions, lo, hi)) return grid;

  const double margin = supportRadius + 2.0 * spacing;
  grid.origin = lo - Vec3::Constant(margin);
  double total = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double cells = std::ceil((hi[a] - lo[a] + 2.0 * margin) / spacing);
    total *= cells + 1.0;
    grid.dims[static_cast<std::size_t>(a)] = static_cast<std::int64_t>(std::min(cells, 1e9)) + 1;
  }
  if (total > kMaxGridPoints) {
    std::ostringstream msg;
    msg << where << ": key 'gridSpacing': expected a spacing that gives at most " << kMaxGridPoints
        << " grid points, got " << total << " points of " << spacing << " m over the particles' extent ["
        << lo.transpose() << "] to [" << hi.transpose() << "]; raise gridSpacing";
    throw InputError(msg.str());
  }
  grid.values.assign(grid.points(), 0.0f);

  // Particles by grid layer (a stable counting sort), so that a slab finds the particles reaching it at once.
  const std::int64_t nz = grid.dims[2];
  const auto layerOf = [&](const Vec3& p) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((p.z() - grid.origin.z()) / spacing)), 0,
                                    nz - 1);
  };
  std::vector<std::size_t> start(static_cast<std::size_t>(nz) + 1, 0);
  for (const Vec3& p : cloud.positions)
    if (p.allFinite()) ++start[static_cast<std::size_t>(layerOf(p)) + 1];
  for (std::size_t k = 0; k < static_cast<std::size_t>(nz); ++k) start[k + 1] += start[k];
  std::vector<std::size_t> order(start.back());
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t p = 0; p < cloud.positions.size(); ++p)
      if (cloud.positions[p].allFinite()) order[next[static_cast<std::size_t>(layerOf(cloud.positions[p]))]++] = p;
  }

  // W tabulated over d^2 (linear in between): no square root or branch per grid point. 4096 intervals keep the
  // table's error below 1e-6 W(0), far under what a surface drawn through the grid can show.
  const CubicKernel kernel(supportRadius);
  const double h2 = supportRadius * supportRadius;
  constexpr std::size_t kTable = 4096;
  std::vector<float> table(kTable + 2);
  for (std::size_t t = 0; t <= kTable + 1; ++t)
    table[t] = static_cast<float>(kernel.w(supportRadius * std::sqrt(std::min(1.0, double(t) / kTable))));
  const float toTable = static_cast<float>(kTable / h2);

  const std::int64_t reach = static_cast<std::int64_t>(std::ceil(supportRadius / spacing));
  const std::int64_t slabs = (nz + kSlabLayers - 1) / kSlabLayers;
  const std::int64_t nx = grid.dims[0], ny = grid.dims[1];
  float* const out = grid.values.data();
  // The grid indices within `reach` grid units of `centre` (in grid units), clipped to [0, n).
  const auto span = [](double centre, double reach, std::int64_t n) {
    return std::pair<std::int64_t, std::int64_t>{
        std::max<std::int64_t>(0, static_cast<std::int64_t>(std::ceil(centre - reach))),
        std::min(n - 1, static_cast<std::int64_t>(std::floor(centre + reach)))};
  };
  parallel::forEachTask(static_cast<std::size_t>(slabs), [&](std::size_t slab) {
    const std::int64_t k0 = static_cast<std::int64_t>(slab) * kSlabLayers, k1 = std::min(nz, k0 + kSlabLayers);
    const std::size_t first = start[static_cast<std::size_t>(std::max<std::int64_t>(0, k0 - reach))];
    const std::size_t last = start[static_cast<std::size_t>(std::min(nz, k1 + reach))];
    for (std::size_t n = first; n < last; ++n) {
      const std::size_t p = order[n];
      const float volume = static_cast<float>(cloud.volumes[p]);
      const Vec3 local = (cloud.positions[p] - grid.origin) / spacing; // in grid units
      const double r = supportRadius / spacing;
      const std::int64_t kLo = std::max(k0, static_cast<std::int64_t>(std::ceil(local.z() - r)));
      const std::int64_t kHi = std::min(k1 - 1, static_cast<std::int64_t>(std::floor(local.z() + r)));
      for (std::int64_t k = kLo; k <= kHi; ++k) {
        const double dz = (double(k) - local.z()) * spacing, restZ = h2 - dz * dz;
        if (restZ <= 0.0) continue;
        const auto [jLo, jHi] = span(local.y(), std::sqrt(restZ) / spacing, ny);
        for (std::int64_t j = jLo; j <= jHi; ++j) {
          const double dy = (double(j) - local.y()) * spacing, restY = restZ - dy * dy;
          if (restY <= 0.0) continue;
          const auto [iLo, iHi] = span(local.x(), std::sqrt(restY) / spacing, nx);
          const double dyz = h2 - restY; // dy^2 + dz^2
          float* target = out + grid.index(0, j, k);
          for (std::int64_t i = iLo; i <= iHi; ++i) {
            const double dx = (double(i) - local.x()) * spacing;
            const float at = static_cast<float>(dx * dx + dyz) * toTable;
            const std::size_t t = std::min(static_cast<std::size_t>(at), kTable);
            const float frac = std::min(at - static_cast<float>(t), 1.0f);
            target[i] += volume * (table[t] + frac * (table[t + 1] - table[t]));
          }
        }
      }
    }
  });
  return grid;
}

} // namespace poro
