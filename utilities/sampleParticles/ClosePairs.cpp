#include "ClosePairs.hpp"

#include "core/Parallel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace poro {

namespace {

/// Bits of a cell index per axis in a key: key = ix + 2^21 iy + 2^42 iz.
constexpr int kBits = 21;
/// Cell indices run from 0 to kMaxCell on each axis: the cell size grows when the points span more (a key stays 63
/// bits, and ix + 1 never carries into iy).
constexpr double kMaxCell = static_cast<double>((std::int64_t(1) << kBits) - 3);
/// Cells a hair wider than the distance: with cells of exactly d, round-off could put two points closer than d
/// into cells two apart, which the 27-cell stencil would miss (as in sph/NeighbourSearch).
constexpr double kCellWidening = 1.0 + 1e-6;
/// Cells per parallel task.
constexpr std::size_t kChunk = 4096;

/// Distances within this share of each other are a tie: lattice pairs are equally far apart in exact arithmetic, and
/// their computed distances differ in the last bits, in an order any change of rounding (a build with fused
/// multiply-adds) may reverse.
constexpr double kTie = 1e-9;

/// Whether the pair (a, b) comes before (c, d) in coordinates rounded to nanometres, x before y before z: the pair a
/// message names among tied ones, whatever the rounding of their distances or positions.
bool comesFirst(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  auto nm = [](const Vec3& p, const Vec3& q) {
    return std::array<long long, 6>{std::llround(p.x() * 1e9), std::llround(p.y() * 1e9), std::llround(p.z() * 1e9),
                                    std::llround(q.x() * 1e9), std::llround(q.y() * 1e9), std::llround(q.z() * 1e9)};
  };
  return nm(a, b) < nm(c, d);
}

std::uint64_t keyOf(std::int64_t ix, std::int64_t iy, std::int64_t iz) {
  return static_cast<std::uint64_t>(ix) | static_cast<std::uint64_t>(iy) << kBits |
         static_cast<std::uint64_t>(iz) << (2 * kBits);
}

class HashGrid {
public:
  HashGrid(const std::vector<LabelledPoints>& points, double distance, const std::vector<std::vector<bool>>& apart)
      : points_(points), labels_(apart.size()), distance2_(distance * distance) {
    apart_.assign(labels_ * labels_, 0);
    std::vector<char> used(labels_, 0); // labels apart from some other label
    for (std::size_t a = 0; a < labels_; ++a)
      for (std::size_t b = 0; b < labels_; ++b)
        if (apart[a][b]) apart_[a * labels_ + b] = used[a] = 1;

    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
    Vec3 hi = Vec3::Constant(std::numeric_limits<double>::lowest());
    std::size_t n = 0;
    for (const LabelledPoints& set : points)
      for (std::size_t i = 0; i < set.x->size(); ++i)
        if (used[static_cast<std::size_t>((*set.label)[i])]) {
          lo = lo.cwiseMin((*set.x)[i]);
          hi = hi.cwiseMax((*set.x)[i]);
          ++n;
        }
    if (n == 0) return;
    origin_ = lo;
    cellSize_ = std::max(distance * kCellWidening, (hi - lo).maxCoeff() / kMaxCell);

    entries_.reserve(n);
    for (std::size_t s = 0; s < points.size(); ++s)
      for (std::size_t i = 0; i < points[s].x->size(); ++i)
        if (used[static_cast<std::size_t>((*points[s].label)[i])]) {
          const auto [ix, iy, iz] = cellOf((*points[s].x)[i]);
          entries_.push_back({keyOf(ix, iy, iz), static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(i)});
        }
    std::sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.key < b.key; });
    for (std::size_t k = 0; k < n; ++k)
      if (k == 0 || entries_[k].key != entries_[k - 1].key) {
        cellKey_.push_back(entries_[k].key);
        cellStart_.push_back(static_cast<std::uint32_t>(k));
      }
    cellStart_.push_back(static_cast<std::uint32_t>(n));
  }

  std::size_t cells() const { return cellKey_.size(); }

  /// Calls visit(c, p, q) for every pair p < q (in the grid's order) of a point p of a cell c in [first, last) and
  /// a point q of a neighbouring cell (or of c) closer than the distance whose labels are apart.
  template <class Visit> void scan(std::size_t first, std::size_t last, const Visit& visit) const {
    // The cells of one row offset (dy, dz) around cell (ix, iy, iz) are the keys from (ix - 1, iy + dy, iz + dz) to
    // (ix + 1, iy + dy, iz + dz); over cells in key order these ranges only move up, so after one binary search two
    // cursors per offset walk them.
    std::array<std::size_t, 9> begin{}, end{};
    std::array<bool, 9> placed{};
    for (std::size_t c = first; c < last; ++c) {
      const std::uint64_t key = cellKey_[c];
      const auto ix = static_cast<std::int64_t>(key & kMask), iy = static_cast<std::int64_t>((key >> kBits) & kMask),
                 iz = static_cast<std::int64_t>(key >> (2 * kBits));
      for (std::size_t offset = 0; offset < 9; ++offset) {
        const std::int64_t y = iy + static_cast<std::int64_t>(offset % 3) - 1,
                           z = iz + static_cast<std::int64_t>(offset / 3) - 1;
        if (y < 0 || z < 0) continue;
        const std::uint64_t from = keyOf(std::max<std::int64_t>(ix - 1, 0), y, z), to = keyOf(ix + 1, y, z);
        std::size_t& b = begin[offset];
        std::size_t& e = end[offset];
        if (!placed[offset]) {
          b = e = static_cast<std::size_t>(std::lower_bound(cellKey_.begin(), cellKey_.end(), from) - cellKey_.begin());
          placed[offset] = true;
        }
        while (b < cellKey_.size() && cellKey_[b] < from) ++b;
        e = std::max(e, b);
        while (e < cellKey_.size() && cellKey_[e] <= to) ++e;
        for (std::uint32_t p = cellStart_[c]; p < cellStart_[c + 1]; ++p)
          for (std::uint32_t q = std::max(cellStart_[b], p + 1); q < cellStart_[e]; ++q)
            if (apart_[label(p) * labels_ + label(q)] && (x(p) - x(q)).squaredNorm() < distance2_) visit(c, p, q);
      }
    }
  }

  /// The position and label of the point at `k` in the grid's order.
  const Vec3& x(std::size_t k) const { return (*points_[entries_[k].set].x)[entries_[k].index]; }
  std::size_t label(std::size_t k) const {
    return static_cast<std::size_t>((*points_[entries_[k].set].label)[entries_[k].index]);
  }

private:
  static constexpr std::uint64_t kMask = (std::uint64_t(1) << kBits) - 1;

  std::array<std::int64_t, 3> cellOf(const Vec3& p) const {
    std::array<std::int64_t, 3> c{};
    for (int d = 0; d < 3; ++d)
      c[static_cast<std::size_t>(d)] =
          static_cast<std::int64_t>(std::min(std::floor((p[d] - origin_[d]) / cellSize_), kMaxCell));
    return c;
  }

  /// A point in the grid: its cell's key and where it is in `points_`. Points are sampled row by row, so in key order
  /// they are read almost in memory order, and a copy of them would only cost memory.
  struct Entry {
    std::uint64_t key;
    std::uint32_t set, index;
  };

  const std::vector<LabelledPoints>& points_;
  std::size_t labels_;
  double distance2_;
  std::vector<char> apart_; ///< labels_ x labels_
  Vec3 origin_ = Vec3::Zero();
  double cellSize_ = 1.0;
  std::vector<Entry> entries_;           ///< in key order
  std::vector<std::uint64_t> cellKey_;   ///< the occupied cells' keys, increasing
  std::vector<std::uint32_t> cellStart_; ///< first point of each cell, and the number of points at the end
};

} // namespace

std::vector<ClosePairs> findClosePairs(const std::vector<LabelledPoints>& points, double distance,
                                       const std::vector<std::vector<bool>>& apart) {
  const HashGrid grid(points, distance, apart);
  // Counted in parallel per cell first: a valid case has no close pair, and only then is anything summed up.
  const std::size_t chunks = (grid.cells() + kChunk - 1) / kChunk;
  std::vector<std::size_t> counts(grid.cells(), 0);
  parallel::forEachTask(chunks, [&](std::size_t chunk) {
    const std::size_t first = chunk * kChunk;
    grid.scan(first, std::min(grid.cells(), first + kChunk),
              [&](std::size_t c, std::size_t, std::size_t) { ++counts[c]; }); // c is in this task's chunk
  });
  std::map<std::pair<std::size_t, std::size_t>, ClosePairs> byLabels;
  for (std::size_t c = 0; c < grid.cells(); ++c) {
    if (counts[c] == 0) continue;
    grid.scan(c, c + 1, [&](std::size_t, std::size_t p, std::size_t q) {
      std::size_t a = p, b = q;
      if (grid.label(a) > grid.label(b)) std::swap(a, b);
      ClosePairs& pairs = byLabels[{grid.label(a), grid.label(b)}];
      const double d = (grid.x(a) - grid.x(b)).norm();
      const bool first = pairs.count++ == 0;
      const bool closer = d < pairs.closest * (1.0 - kTie);
      const bool tied = !closer && d <= pairs.closest * (1.0 + kTie);
      if (first || closer || (tied && comesFirst(grid.x(a), grid.x(b), pairs.pointA, pairs.pointB))) {
        pairs.a = grid.label(a);
        pairs.b = grid.label(b);
        pairs.closest = d;
        pairs.pointA = grid.x(a);
        pairs.pointB = grid.x(b);
      }
    });
  }
  std::vector<ClosePairs> result;
  for (const auto& entry : byLabels) result.push_back(entry.second);
  return result;
}

} // namespace poro
