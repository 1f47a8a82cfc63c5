#include "sph/NeighbourSearch.hpp"

#include "core/Error.hpp"
#include "core/Memory.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>

namespace poro {

namespace {

/// A dense grid larger than this means particles have spread far beyond any sensible domain.
constexpr std::int64_t kMaxCells = std::int64_t(1) << 27;
/// Particles per task of the list build: large enough to amortise, small enough to balance.
constexpr std::size_t kChunk = 512;
/// Cells are a hair wider than H. With cells of exactly H, round-off in (x - origin) * (1/H) can put two
/// particles whose distance is within an ulp of H into cells two apart (e.g. x = 0.7999999999999999 and
/// 0.8999999999999999 at H = 0.1 land in cells 7 and 9), and the 27-cell stencil misses the pair. The
/// margin exceeds the relative round-off (a few 1e-16) times the largest cell index (kMaxCells).
constexpr double kCellWidening = 1.0 + 1e-6;
/// The skin is used when the candidates will last two updates at least: 2 x 2 x largestStep < skin.
constexpr double kStepsPerSkin = 4.0;

/// Insertion sort: a list gathered cell by cell from Morton-ordered particles is nearly ascending already.
void sortAscending(Index* first, Index* last) {
  for (Index* k = first + (first != last); k < last; ++k) {
    const Index value = *k;
    Index* m = k;
    for (; m > first && *(m - 1) > value; --m) *m = *(m - 1);
    *m = value;
  }
}

struct CellIndex {
  std::int64_t ix, iy, iz;
};

/// Particles of one set sorted by cell (counting sort), with a copy of their positions in that order.
struct SortedSet {
  std::vector<std::int64_t> cellStart; // nCells + 1
  std::vector<Index> index;            // original index in cell order
  std::vector<Vec3> x;                 // positions in cell order
};

} // namespace

NeighbourSearch::CellGrid NeighbourSearch::makeGrid(const std::vector<const std::vector<Vec3>*>& positions,
                                                    double radius) const {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 hi = Vec3::Constant(std::numeric_limits<double>::lowest());
  for (const auto* xs : positions)
    for (const Vec3& p : *xs) {
      if (!p.allFinite()) throw NumericalError("neighbour search: a particle position is not finite (NaN or inf)");
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  CellGrid grid;
  if (lo.x() > hi.x()) return grid; // no particles
  grid.origin = lo;
  const double cellSize = radius * kCellWidening;
  double cells = 1.0;
  for (int d = 0; d < 3; ++d) {
    grid.dims[d] = static_cast<std::int64_t>(std::floor((hi[d] - lo[d]) / cellSize)) + 1;
    cells *= static_cast<double>(grid.dims[d]);
  }
  if (cells > static_cast<double>(kMaxCells)) {
    std::ostringstream msg;
    msg << "neighbour search: particles span [" << lo.transpose() << "] to [" << hi.transpose() << "] m, more than "
        << kMaxCells << " cells of size " << cellSize
        << " m; particles are leaving the domain (reduce deltaT or maxCourant, or close the container)";
    throw NumericalError(msg.str());
  }
  return grid;
}

void NeighbourSearch::clearLists(std::vector<NeighbourList>& lists) const {
  // Emptied, not freed: the next lists reuse the memory instead of faulting in fresh pages every step.
  lists.resize(sets_ * sets_);
  for (NeighbourList& list : lists) {
    list.offsets_.clear();
    list.indices_.clear();
  }
}

template <class AppendNeighbours>
void NeighbourSearch::assemble(std::size_t n, NeighbourList& list, const AppendNeighbours& append) {
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::vector<Index>> chunkIndices(chunks);
  std::vector<std::uint32_t> counts(n, 0);
  parallel::forEachTask(chunks, [&](std::size_t chunk) {
    std::vector<Index>& out = chunkIndices[chunk];
    out.reserve(kChunk * 40);
    const std::size_t end = std::min(n, (chunk + 1) * kChunk);
    for (std::size_t i = chunk * kChunk; i < end; ++i) {
      const std::size_t before = out.size();
      append(i, out);
      counts[i] = static_cast<std::uint32_t>(out.size() - before);
    }
  });
  std::uint64_t pairs = 0;
  for (const std::vector<Index>& out : chunkIndices) pairs += out.size();
  if (pairs > std::numeric_limits<std::uint32_t>::max())
    throw NumericalError(
        "neighbour search: " + std::to_string(pairs) + " pairs in one list, more than the " +
        std::to_string(std::numeric_limits<std::uint32_t>::max()) +
        " its 32-bit offsets hold (some hundred million particles in one set); decompose the case (mpirun, -parallel)");
  parallel::exclusiveScan(counts, list.offsets_);
  memory::resizeForRefill(list.indices_, static_cast<std::size_t>(list.offsets_[n]));
  parallel::forEach(chunks, [&](std::size_t chunk) {
    const auto& src = chunkIndices[chunk];
    std::copy(src.begin(), src.end(), list.indices_.begin() + list.offsets_[chunk * kChunk]);
  });
}

void NeighbourSearch::update(const std::vector<const std::vector<Vec3>*>& positions,
                             const std::vector<std::vector<bool>>& wanted, double largestStep,
                             const std::vector<std::size_t>& listed) {
  sets_ = positions.size();
  listed_ = listed;
  ++updates_;
  if (!skinPays(largestStep)) {
    // A fast flow would cross the skin every step or two, and the grid search at H + skin would cost more
    // than it saves: search at H, in stencil order (the mode is a function of the state, so a restarted run
    // picks the same one).
    valid_ = false;
    build(positions, wanted, h_, lists_, false);
    return;
  }
  if (mustRebuild(positions, wanted)) {
    build(positions, wanted, h_ + skin_, candidates_, true);
    builtAt_.resize(sets_);
    for (std::size_t s = 0; s < sets_; ++s) builtAt_[s] = *positions[s];
    builtWanted_ = wanted;
    builtListed_ = listed;
    valid_ = true;
  }
  // The lists at H: the candidates within H + skin that are within H now, ascending like the candidates, so
  // they do not depend on when the candidates were searched.
  clearLists(lists_);
  const double h2 = h_ * h_;
  for (std::size_t a = 0; a < sets_; ++a)
    for (std::size_t b = 0; b < sets_; ++b) {
      if (!wanted[a][b]) continue;
      const auto& xa = *positions[a];
      const auto& xb = *positions[b];
      const NeighbourList& candidates = candidates_[a * sets_ + b];
      const std::size_t withList = listedOf(a, xa.size());
      assemble(xa.size(), lists_[a * sets_ + b], [&](std::size_t i, std::vector<Index>& out) {
        if (i >= withList) return;
        // Branch-free: three candidates in four are neighbours, in no order a predictor could learn.
        const Vec3& p = xa[i];
        const std::size_t used = out.size();
        out.resize(used + candidates.of(i).size());
        Index* const dst = out.data() + used;
        std::size_t kept = 0;
        for (const Index j : candidates.of(i)) {
          dst[kept] = j;
          kept += static_cast<std::size_t>((p - xb[static_cast<std::size_t>(j)]).squaredNorm() < h2);
        }
        out.resize(used + kept);
      });
    }
}

bool NeighbourSearch::skinPays(double largestStep) const { return skin_ > 0.0 && kStepsPerSkin * largestStep < skin_; }

bool NeighbourSearch::mustRebuild(const std::vector<const std::vector<Vec3>*>& positions,
                                  const std::vector<std::vector<bool>>& wanted) const {
  if (!valid_ || wanted != builtWanted_ || listed_ != builtListed_ || builtAt_.size() != positions.size()) return true;
  double largest = 0.0;
  for (std::size_t s = 0; s < positions.size(); ++s) {
    const auto& x = *positions[s];
    const auto& x0 = builtAt_[s];
    if (x.size() != x0.size()) return true;
    largest = std::max(largest, parallel::max(x.size(), 0.0, [&](std::size_t i) { return (x[i] - x0[i]).norm(); }));
  }
  // Two particles that each moved less than skin / 2 since the build are still listed if within H.
  return 2.0 * largest >= skin_;
}

void NeighbourSearch::build(const std::vector<const std::vector<Vec3>*>& positions,
                            const std::vector<std::vector<bool>>& wanted, double radius,
                            std::vector<NeighbourList>& lists, bool ascending) {
  ++gridSearches_;
  clearLists(lists);
  const CellGrid grid = makeGrid(positions, radius);
  const std::int64_t nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  const std::int64_t nCells = nx * ny * nz;
  const double invCell = 1.0 / (radius * kCellWidening);
  const double radius2 = radius * radius;

  auto cellOf = [&](const Vec3& p) {
    CellIndex c{static_cast<std::int64_t>((p.x() - grid.origin.x()) * invCell),
                static_cast<std::int64_t>((p.y() - grid.origin.y()) * invCell),
                static_cast<std::int64_t>((p.z() - grid.origin.z()) * invCell)};
    c.ix = std::min(c.ix, nx - 1);
    c.iy = std::min(c.iy, ny - 1);
    c.iz = std::min(c.iz, nz - 1);
    return c;
  };

  // Sort every set that is searched in by cell.
  std::vector<SortedSet> sorted(sets_);
  for (std::size_t b = 0; b < sets_; ++b) {
    bool searched = false;
    for (std::size_t a = 0; a < sets_; ++a) searched = searched || wanted[a][b];
    if (!searched) continue;
    const auto& xs = *positions[b];
    const std::size_t n = xs.size();
    std::vector<std::int64_t> cell(n);
    parallel::forEach(n, [&](std::size_t i) {
      const CellIndex c = cellOf(xs[i]);
      cell[i] = c.ix + nx * (c.iy + ny * c.iz);
    });
    SortedSet& s = sorted[b];
    s.cellStart.assign(static_cast<std::size_t>(nCells) + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++s.cellStart[static_cast<std::size_t>(cell[i]) + 1];
    for (std::int64_t c = 0; c < nCells; ++c) s.cellStart[c + 1] += s.cellStart[c];
    std::vector<std::int64_t> fill(s.cellStart.begin(), s.cellStart.end() - 1);
    s.index.resize(n);
    s.x.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t k = fill[static_cast<std::size_t>(cell[i])]++;
      s.index[static_cast<std::size_t>(k)] = static_cast<Index>(i);
      s.x[static_cast<std::size_t>(k)] = xs[i];
    }
  }

  for (std::size_t a = 0; a < sets_; ++a) {
    const auto& xa = *positions[a];
    for (std::size_t b = 0; b < sets_; ++b) {
      if (!wanted[a][b]) continue;
      const SortedSet& s = sorted[b];
      const bool self = a == b;
      const std::size_t withList = listedOf(a, xa.size());
      assemble(xa.size(), lists[a * sets_ + b], [&](std::size_t i, std::vector<Index>& out) {
        if (i >= withList) return;
        const Vec3& p = xa[i];
        const CellIndex c = cellOf(p);
        const std::size_t before = out.size();
        for (std::int64_t z = std::max<std::int64_t>(c.iz - 1, 0); z <= std::min(c.iz + 1, nz - 1); ++z)
          for (std::int64_t y = std::max<std::int64_t>(c.iy - 1, 0); y <= std::min(c.iy + 1, ny - 1); ++y) {
            // The x-neighbours of one (y, z) row are consecutive cells: one contiguous range.
            const std::int64_t row = nx * (y + ny * z);
            const std::int64_t c0 = row + std::max<std::int64_t>(c.ix - 1, 0);
            const std::int64_t c1 = row + std::min(c.ix + 1, nx - 1);
            for (std::int64_t k = s.cellStart[c0]; k < s.cellStart[c1 + 1]; ++k) {
              const Index j = s.index[static_cast<std::size_t>(k)];
              if (self && static_cast<std::size_t>(j) == i) continue;
              if ((p - s.x[static_cast<std::size_t>(k)]).squaredNorm() < radius2) out.push_back(j);
            }
          }
        if (ascending) sortAscending(out.data() + before, out.data() + out.size());
      });
    }
  }
}

std::vector<Index> NeighbourSearch::mortonOrder(const std::vector<Vec3>& x) const {
  const std::size_t n = x.size();
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index{0});
  if (n == 0) return order;
  const CellGrid grid = makeGrid({&x}, h_);
  auto spread = [](std::uint64_t v) { // 21 bits -> every third bit
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  std::vector<std::uint64_t> code(n);
  const double invH = 1.0 / h_;
  parallel::forEach(n, [&](std::size_t i) {
    const Vec3 c = (x[i] - grid.origin) * invH;
    code[i] = spread(static_cast<std::uint64_t>(c.x())) | spread(static_cast<std::uint64_t>(c.y())) << 1 |
              spread(static_cast<std::uint64_t>(c.z())) << 2;
  });
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return code[a] < code[b]; });
  return order;
}

} // namespace poro
