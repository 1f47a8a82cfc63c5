#include "sph/NeighbourSearch.hpp"

#include "core/Error.hpp"
#include "core/Memory.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#if defined(__AVX2__)
#include <immintrin.h>
#endif
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>

namespace poro {

namespace {

/// A dense grid larger than this means particles have spread far beyond any sensible domain.
constexpr std::int64_t kMaxCells = std::int64_t(1) << 27;
/// Particles per task of the list build: large enough to amortise, small enough to balance.
constexpr std::size_t kChunk = 512;
/// A list is assembled in rounds of at least this many chunks per thread (fewer rounds cost less waiting at their
/// ends) and at most kRounds rounds (more keep less memory).
constexpr std::size_t kChunksPerThreadAndRound = 16;
constexpr std::size_t kRounds = 8;
/// Cells are a hair wider than H. With cells of exactly H, round-off in (x - origin) * (1/H) can put two
/// particles whose distance is within an ulp of H into cells two apart (e.g. x = 0.7999999999999999 and
/// 0.8999999999999999 at H = 0.1 land in cells 7 and 9), and the 27-cell stencil misses the pair. The
/// margin exceeds the relative round-off (a few 1e-16) times the largest cell index (kMaxCells).
constexpr double kCellWidening = 1.0 + 1e-6;

/// Insertion sort: a list gathered cell by cell from Morton-ordered particles is nearly ascending already.
void sortAscending(Index* first, Index* last) {
  for (Index* k = first + (first != last); k < last; ++k) {
    const Index value = *k;
    Index* m = k;
    for (; m > first && *(m - 1) > value; --m) *m = *(m - 1);
    *m = value;
  }
}

/// Bit t of the result: whether sorted particle start + t (t < n <= 64) is closer than sqrt(radius2) to p, given
/// in the frame of the sorted coordinates. With AVX2 four doubles or eight floats at a time, reading up to seven
/// past n (into the next cell or the padding).
template <class Coordinates>
std::uint64_t withinMask(const Coordinates& sorted, std::size_t start, std::size_t n, const Vec3& p, double radius2) {
  using T = typename decltype(Coordinates::x)::value_type;
  const T* const x = sorted.x.data() + start;
  const T* const y = sorted.y.data() + start;
  const T* const z = sorted.z.data() + start;
  std::uint64_t mask = 0;
#if defined(__AVX2__)
  if constexpr (std::is_same_v<T, float>) {
    const __m256 px = _mm256_set1_ps(static_cast<float>(p.x())), py = _mm256_set1_ps(static_cast<float>(p.y())),
                 pz = _mm256_set1_ps(static_cast<float>(p.z()));
    const __m256 r2 = _mm256_set1_ps(static_cast<float>(radius2));
    for (std::size_t t = 0; t < n; t += 8) {
      const __m256 dx = _mm256_sub_ps(px, _mm256_loadu_ps(x + t));
      const __m256 dy = _mm256_sub_ps(py, _mm256_loadu_ps(y + t));
      const __m256 dz = _mm256_sub_ps(pz, _mm256_loadu_ps(z + t));
      const __m256 d2 =
          _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
      mask |= static_cast<std::uint64_t>(_mm256_movemask_ps(_mm256_cmp_ps(d2, r2, _CMP_LT_OQ))) << t;
    }
  } else {
    const __m256d px = _mm256_set1_pd(p.x()), py = _mm256_set1_pd(p.y()), pz = _mm256_set1_pd(p.z());
    const __m256d r2 = _mm256_set1_pd(radius2);
    for (std::size_t t = 0; t < n; t += 4) {
      const __m256d dx = _mm256_sub_pd(px, _mm256_loadu_pd(x + t));
      const __m256d dy = _mm256_sub_pd(py, _mm256_loadu_pd(y + t));
      const __m256d dz = _mm256_sub_pd(pz, _mm256_loadu_pd(z + t));
      const __m256d d2 =
          _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
      mask |= static_cast<std::uint64_t>(_mm256_movemask_pd(_mm256_cmp_pd(d2, r2, _CMP_LT_OQ))) << t;
    }
  }
#else
  const T px = static_cast<T>(p.x()), py = static_cast<T>(p.y()), pz = static_cast<T>(p.z());
  const T r2 = static_cast<T>(radius2);
  for (std::size_t t = 0; t < n; ++t) {
    const T dx = px - x[t], dy = py - y[t], dz = pz - z[t];
    mask |= static_cast<std::uint64_t>(dx * dx + dy * dy + dz * dz < r2) << t;
  }
#endif
  return n == 64 ? mask : mask & ((std::uint64_t(1) << n) - 1);
}

/// The squared radius at which the float test of the candidates keeps every pair closer than `radius` (and a few
/// farther): coordinates up to `extent` from the grid's origin are rounded by at most 2^-24 of it, p and the
/// difference too, so a distance is off by at most sqrt(3) 2^-24 (2 extent + radius); the squares and their sum
/// add a few float roundings (the factor).
double floatTestRadius2(double radius, double extent) {
  const double widened = radius + std::sqrt(3.0) * 0x1p-24 * (2.0 * extent + radius);
  return widened * widened * (1.0 + 0x1p-20);
}

/// Writes to dst the indices index[k] of the sorted particles k in [first, last) closer than sqrt(radius2) to p,
/// but not `skipped`, in their sorted order; returns how many. In blocks of 64: a mask of the candidates within,
/// then only those are visited. About one candidate in six is within; testing and keeping one candidate at a time
/// took twice as long.
template <class Coordinates>
std::size_t keepWithin(const Coordinates& sorted, const Index* index, std::size_t first, std::size_t last,
                       const Vec3& p, double radius2, Index skipped, Index* dst) {
  std::size_t kept = 0;
  for (std::size_t start = first; start < last; start += 64) {
    for (std::uint64_t mask = withinMask(sorted, start, std::min<std::size_t>(64, last - start), p, radius2); mask != 0;
         mask &= mask - 1) {
      const Index j = index[start + static_cast<std::size_t>(__builtin_ctzll(mask))];
      dst[kept] = j;
      kept += static_cast<std::size_t>(j != skipped);
    }
  }
  return kept;
}

struct CellIndex {
  std::int64_t ix, iy, iz;
};

/// Cell coordinate of x along one axis of `cells` cells, floor-based: -2 or cells + 1 when x is farther outside
/// (clamped before the conversion, which a particle far away would overflow).
std::int64_t cellCoordinate(double x, double origin, double invCell, std::int64_t cells) {
  return static_cast<std::int64_t>(
      std::clamp(std::floor((x - origin) * invCell), -2.0, static_cast<double>(cells) + 1.0));
}

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
  const double cellSize = radius * kCellWidening;
  grid.cellSize = cellSize;
  // On multiples of the cell size, so that grids of one cell size share their cells whatever the particles'
  // extent: the Morton order's cells are then the grid search's (mortonOrder()).
  for (int d = 0; d < 3; ++d) grid.origin[d] = std::floor(lo[d] / cellSize) * cellSize;
  double cells = 1.0;
  for (int d = 0; d < 3; ++d) {
    grid.dims[d] = static_cast<std::int64_t>(std::floor((hi[d] - grid.origin[d]) / cellSize)) + 1;
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

template <class List> void NeighbourSearch::clearLists(std::vector<List>& lists) const {
  // Emptied, not freed: the next lists reuse the memory instead of faulting in fresh pages every step.
  lists.resize(sets_ * sets_);
  for (List& list : lists) {
    list.offsets_.clear();
    list.indices_.clear();
  }
}

void NeighbourSearch::encodeCandidates(const Index* first, const Index* last, CodeBuffer& out) {
  if (first == last) return;
  const std::size_t before = out.size();
  out.resize(before + 3 * static_cast<std::size_t>(last - first)); // at most three codes each
  std::uint16_t* code = out.data() + before;
  const auto index = [&code](Index j) {
    *code++ = static_cast<std::uint16_t>(static_cast<std::uint32_t>(j) & 0xffffu);
    *code++ = static_cast<std::uint16_t>(static_cast<std::uint32_t>(j) >> 16);
  };
  index(*first);
  for (const Index* k = first + 1; k < last; ++k) {
    const std::uint32_t step = static_cast<std::uint32_t>(*k - *(k - 1)); // >= 1: ascending and distinct
    if (step <= 0xffffu) {
      *code++ = static_cast<std::uint16_t>(step);
    } else {
      *code++ = 0;
      index(*k);
    }
  }
  out.resize(static_cast<std::size_t>(code - out.data()));
}

namespace {
/// Writes the values [first, last) into `array` from position `at` on.
template <class T> void storeAt(ReallocVector<T>& array, std::size_t at, const T* first, const T* last) {
  std::copy(first, last, array.begin() + at);
}
void storeAt(PackedIndices& array, std::size_t at, const Index* first, const Index* last) {
  array.store(at, first, last);
}
/// Empties `array` and gives its block back.
template <class T> void release(ReallocVector<T>& array) { memory::freeAll(array); }
void release(PackedIndices& array) { array.release(); }
} // namespace

template <class List, class AppendNeighbours>
void NeighbourSearch::assemble(std::size_t n, List& list, const AppendNeighbours& append) {
  using Element = typename decltype(list.indices_)::value_type;
  using Buffer = std::vector<Element, UninitialisedAllocator<Element>>;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  // In rounds of a few chunks per thread: the chunks' buffers then hold one round's pairs beside the list, not a
  // second copy of all of it (the largest list of the published Seep at r = 1 cm holds 18 MB of indices, and its
  // copy was the peak of the run's memory). Small lists take one round.
  const std::size_t perRound = std::max(kChunksPerThreadAndRound * static_cast<std::size_t>(parallel::threads()),
                                        (chunks + kRounds - 1) / kRounds);
  std::vector<Buffer> buffers(std::min(chunks, perRound));
  list.offsets_.resize(n + 1);
  list.offsets_[0] = 0;
  list.indices_.clear(); // the capacity stays: most updates need about what the last one did
  for (std::size_t first = 0; first < chunks; first += perRound) {
    const std::size_t last = std::min(chunks, first + perRound);
    parallel::forEachTask(last - first, [&](std::size_t k) {
      // Filled in a buffer held by the task itself and put back at the end: the headers of neighbouring chunks'
      // buffers share cache lines, which every append wrote from both threads (Climb's search phase 1.10 -> 1.06 s).
      Buffer out = std::move(buffers[k]);
      out.clear();
      out.reserve(kChunk * 40);
      const std::size_t end = std::min(n, (first + k + 1) * kChunk);
      for (std::size_t i = (first + k) * kChunk; i < end; ++i) {
        const std::size_t before = out.size();
        append(i, out);
        list.offsets_[i + 1] = static_cast<std::uint32_t>(out.size() - before); // a count until the scan below
      }
      buffers[k] = std::move(out);
    });
    const std::size_t lastParticle = std::min(n, last * kChunk);
    std::uint64_t pairs = list.offsets_[first * kChunk];
    for (std::size_t i = first * kChunk; i < lastParticle; ++i) {
      pairs += list.offsets_[i + 1];
      if (pairs > std::numeric_limits<std::uint32_t>::max())
        throw NumericalError("neighbour search: a list of more than " +
                             std::to_string(std::numeric_limits<std::uint32_t>::max()) +
                             " pairs, which its 32-bit offsets cannot hold (some hundred million particles in one "
                             "set); decompose the case (mpirun, -parallel)");
      list.offsets_[i + 1] = static_cast<std::uint32_t>(pairs);
    }
    if (pairs > list.indices_.capacity()) { // grown to what the rounds so far suggest for the whole list
      // A later round's growth keeps the pairs so far, moved in place (ReallocVector). In the first, nothing is
      // kept: a fresh block, not the old one's pages moved.
      if (first == 0) release(list.indices_);
      list.indices_.reserve(std::max<std::uint64_t>(pairs, pairs * chunks / last) + pairs / 32);
    }
    list.indices_.resize(pairs);
    parallel::forEach(last - first, [&](std::size_t k) {
      const Buffer& src = buffers[k];
      storeAt(list.indices_, list.offsets_[(first + k) * kChunk], src.data(), src.data() + src.size());
    });
  }
}

void NeighbourSearch::update(const std::vector<const std::vector<Vec3>*>& positions,
                             const std::vector<std::vector<bool>>& wanted, double bulkStep,
                             const std::vector<std::size_t>& listed) {
  sets_ = positions.size();
  listed_ = listed;
  ++updates_;
  if (!skinPays(bulkStep)) {
    // A fast flow would cross the skin every step or two, and the grid search at H + skin would cost more
    // than it saves: search at H, in stencil order (the mode is a function of the state, so a restarted run
    // picks the same one).
    valid_ = false;
    build(positions, wanted, h_, lists_);
    return;
  }
  std::size_t listedParticles = 0;
  for (std::size_t a = 0; a < sets_; ++a)
    if (std::find(wanted[a].begin(), wanted[a].end(), true) != wanted[a].end())
      listedParticles += listedOf(a, positions[a]->size());
  // Movers of every set count (ghosts, walls), against the particles that get lists: on the safe side.
  if (candidatesStale(positions, wanted) || findMovers(positions) * particlesPerMover > listedParticles) {
    // The lists at H are formed afresh from the new candidates below: their blocks are given back first, so that
    // the grid search's sorted positions and buffers take their place instead of adding to the run's peak memory
    // (a grid search is where it was). Fresh pages for the lists once per grid search cost little beside it.
    for (NeighbourList& list : lists_) {
      memory::freeAll(list.offsets_);
      list.indices_.release();
    }
    build(positions, wanted, h_ + skin_, candidates_);
    builtAt_.resize(sets_);
    for (std::size_t s = 0; s < sets_; ++s) {
      const auto& x = *positions[s];
      builtAt_[s].resize(x.size());
      parallel::forEach(x.size(), [&](std::size_t i) { builtAt_[s][i] = x[i].cast<float>(); });
    }
    builtWanted_ = wanted;
    builtListed_ = listed;
    valid_ = true;
    isMover_.resize(sets_);
    movers_.resize(sets_);
    for (std::size_t s = 0; s < sets_; ++s) {
      isMover_[s].clear();
      movers_[s].clear();
    }
  }
  // Most steps have no movers: nothing to sort then.
  if (std::any_of(movers_.begin(), movers_.end(), [](const std::vector<Index>& m) { return !m.empty(); }))
    sortMovers(positions);

  // The lists at H: the neighbours within H now, ascending like the candidates, so they do not depend on when
  // the candidates were searched.
  clearLists(lists_);
  for (std::size_t a = 0; a < sets_; ++a)
    for (std::size_t b = 0; b < sets_; ++b)
      if (wanted[a][b]) filterCandidates(positions, a, b);
}

void NeighbourSearch::sortMovers(const std::vector<const std::vector<Vec3>*>& positions) {
  std::vector<std::vector<Vec3>> moverX(sets_);
  std::vector<const std::vector<Vec3>*> moverPositions;
  for (std::size_t s = 0; s < sets_; ++s) {
    for (const Index j : movers_[s]) moverX[s].push_back((*positions[s])[static_cast<std::size_t>(j)]);
    moverPositions.push_back(&moverX[s]);
  }
  // Cells as wide as the grid search's, so that this grid is never refused where a grid search would not be.
  moverGrid_ = makeGrid(moverPositions, h_ + skin_);
  moverCells_.resize(sets_);
  for (std::size_t s = 0; s < sets_; ++s) {
    if (movers_[s].empty())
      moverCells_[s].cellStart.clear(); // nothing to visit
    else
      sortIntoCells(moverX[s], moverGrid_, moverCells_[s]);
  }
}

void NeighbourSearch::filterCandidates(const std::vector<const std::vector<Vec3>*>& positions, std::size_t a,
                                       std::size_t b) {
  const auto& xa = *positions[a];
  const auto& xb = *positions[b];
  const CandidateList& candidates = candidates_[a * sets_ + b];
  const std::size_t withList = listedOf(a, xa.size());
  const double h2 = h_ * h_;
  const std::uint8_t* const aMoves = isMover_[a].empty() ? nullptr : isMover_[a].data();
  const std::uint8_t* const bMoves = isMover_[b].empty() ? nullptr : isMover_[b].data();

  // Particles of a that b's movers came near, as (particle, mover) pairs grouped by particle, movers ascending:
  // particle i's are extras[extraStart[i] .. extraStart[i + 1]).
  std::vector<std::uint32_t>& extraStart = extraStart_;
  std::vector<Index>& extras = extras_;
  extras.clear();
  if (bMoves) {
    const std::vector<Index>& movers = movers_[b];
    const std::size_t chunks = (movers.size() + kChunk - 1) / kChunk;
    std::vector<std::vector<std::pair<Index, Index>>> chunkPairs(chunks);
    parallel::forEachTask(chunks, [&](std::size_t chunk) {
      IndexBuffer near;
      std::vector<std::pair<Index, Index>> pairs; // the task's own, as in assemble()
      for (std::size_t k = chunk * kChunk; k < std::min(movers.size(), (chunk + 1) * kChunk); ++k) {
        const Index f = movers[k];
        near.clear();
        searchAround(positions, a, xb[static_cast<std::size_t>(f)], a == b ? static_cast<std::int64_t>(f) : -1, false,
                     near);
        for (const Index i : near)
          if (static_cast<std::size_t>(i) < withList && !(aMoves && aMoves[i])) pairs.emplace_back(i, f);
      }
      chunkPairs[chunk] = std::move(pairs);
    });
    // Counting sort by particle, stable, so each particle's movers stay ascending.
    memory::resizeForRefill(extraStart, xa.size() + 2);
    std::fill(extraStart.begin(), extraStart.end(), 0u);
    for (const auto& pairs : chunkPairs)
      for (const auto& pair : pairs) ++extraStart[static_cast<std::size_t>(pair.first) + 2];
    for (std::size_t i = 2; i < extraStart.size(); ++i) extraStart[i] += extraStart[i - 1];
    extras.resize(extraStart.back());
    for (const auto& pairs : chunkPairs)
      for (const auto& pair : pairs) extras[extraStart[static_cast<std::size_t>(pair.first) + 1]++] = pair.second;
  }

  lists_[a * sets_ + b].indices_.setWidthFor(xb.size());
  assemble(xa.size(), lists_[a * sets_ + b], [&](std::size_t i, IndexBuffer& out) {
    if (i >= withList) return;
    const Vec3& p = xa[i];
    const std::size_t used = out.size();
    if (aMoves && aMoves[i]) { // its candidates are out of date: searched afresh
      searchAround(positions, b, p, a == b ? static_cast<std::int64_t>(i) : -1, true, out);
      sortAscending(out.data() + used, out.data() + out.size());
      return;
    }
    // Branch-free keeping: three candidates in four are neighbours, in no order a predictor could learn. The
    // movers of b are left out here: they come from the search around them, in `extras`. A particle has at least
    // as many codes as candidates.
    const std::uint16_t* code = candidates.indices_.data() + candidates.offsets_[i];
    const std::uint16_t* const codesEnd = candidates.indices_.data() + candidates.offsets_[i + 1];
    out.resize(used + static_cast<std::size_t>(codesEnd - code));
    Index* const dst = out.data() + used;
    std::size_t kept = 0;
    const auto keep = [&](std::uint32_t j) {
      dst[kept] = static_cast<Index>(j);
      const bool within = (p - xb[j]).squaredNorm() < h2;
      kept += static_cast<std::size_t>(bMoves ? within & (bMoves[j] == 0) : within);
    };
    const auto index = [&code]() { // an index in two codes
      const std::uint32_t j = static_cast<std::uint32_t>(code[0]) | static_cast<std::uint32_t>(code[1]) << 16;
      code += 2;
      return j;
    };
    std::uint32_t j = 0;
    if (code < codesEnd) keep(j = index());
    while (code < codesEnd) {
      const std::uint16_t step = *code++;
      j = step != 0 ? j + step : index();
      keep(j);
    }
    out.resize(used + kept);
    if (bMoves && extraStart[i] != extraStart[i + 1]) {
      out.insert(out.end(), extras.begin() + extraStart[i], extras.begin() + extraStart[i + 1]);
      sortAscending(out.data() + used, out.data() + out.size());
    }
  });
}

void NeighbourSearch::searchAround(const std::vector<const std::vector<Vec3>*>& positions, std::size_t b, const Vec3& p,
                                   std::int64_t self, bool withMovers, IndexBuffer& out) const {
  const auto& xb = *positions[b];
  const double h2 = h_ * h_;
  const std::uint8_t* const moves = isMover_[b].empty() ? nullptr : isMover_[b].data();
  auto visit = [&](const CellGrid& grid, const CellSort& cells, const auto& particle) {
    if (cells.cellStart.empty()) return;
    std::int64_t lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      const std::int64_t c = cellCoordinate(p[d], grid.origin[d], 1.0 / grid.cellSize, grid.dims[d]);
      lo[d] = std::max<std::int64_t>(c - 1, 0);
      hi[d] = std::min(c + 1, grid.dims[d] - 1);
      if (lo[d] > hi[d]) return; // p is more than a cell outside the grid
    }
    for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y) {
        const std::int64_t row = grid.dims[0] * (y + grid.dims[1] * z);
        for (std::int64_t k = cells.cellStart[row + lo[0]]; k < cells.cellStart[row + hi[0] + 1]; ++k) {
          const Index j = particle(cells.index[static_cast<std::size_t>(k)]);
          if (j < 0 || j == self) continue;
          if ((p - xb[static_cast<std::size_t>(j)]).squaredNorm() < h2) out.push_back(j);
        }
      }
  };
  // Particles that moved less than skin / 2 since the grid search: within H of p now, they were within H + skin
  // of it then, in the 27 cells of H + skin around p.
  visit(builtGrid_, builtCells_[b], [&](Index j) { return moves && moves[j] ? Index(-1) : j; });
  if (withMovers) visit(moverGrid_, moverCells_[b], [&](Index k) { return movers_[b][static_cast<std::size_t>(k)]; });
}

bool NeighbourSearch::skinPays(double bulkStep) const { return skin_ > 0.0 && stepsPerSkin * bulkStep < skin_; }

bool NeighbourSearch::candidatesStale(const std::vector<const std::vector<Vec3>*>& positions,
                                      const std::vector<std::vector<bool>>& wanted) const {
  if (!valid_ || wanted != builtWanted_ || listed_ != builtListed_ || builtAt_.size() != positions.size()) return true;
  for (std::size_t s = 0; s < positions.size(); ++s)
    if (positions[s]->size() != builtAt_[s].size()) return true;
  return false;
}

std::size_t NeighbourSearch::findMovers(const std::vector<const std::vector<Vec3>*>& positions) {
  isMover_.resize(sets_);
  movers_.resize(sets_);
  std::size_t total = 0;
  for (std::size_t s = 0; s < sets_; ++s) {
    const auto& x = *positions[s];
    const auto& x0 = builtAt_[s];
    std::vector<std::uint8_t>& moves = isMover_[s];
    movers_[s].clear();
    // Two particles that each moved less than skin / 2 since the grid search are still candidates if within H.
    // The position then is known to within half a float ulp per coordinate, at most 2^-24 of its magnitude: the
    // distance moved is bounded by the distance from the rounded position plus that. A position that is not finite
    // moves too: the search around it then stops the run, as a grid search would.
    constexpr double kRounding = 0x1p-24;
    auto moved = [&](std::size_t i) {
      const Vec3 then = x0[i].cast<double>();
      return !(2.0 * ((x[i] - then).norm() + kRounding * then.lpNorm<1>()) < skin_);
    };
    const std::size_t count = parallel::sum<std::size_t>(x.size(), [&](std::size_t i) { return moved(i) ? 1 : 0; });
    if (count == 0) {
      moves.clear();
      continue;
    }
    moves.resize(x.size());
    parallel::forEach(x.size(), [&](std::size_t i) { moves[i] = moved(i) ? 1 : 0; });
    movers_[s].reserve(count);
    for (std::size_t i = 0; i < x.size(); ++i)
      if (moves[i]) movers_[s].push_back(static_cast<Index>(i));
    total += count;
  }
  return total;
}

void NeighbourSearch::sortIntoCells(const std::vector<Vec3>& xs, const CellGrid& grid, CellSort& cells) {
  const std::int64_t nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  const std::int64_t nCells = nx * ny * nz;
  const double invCell = 1.0 / grid.cellSize;
  const std::size_t n = xs.size();
  std::vector<std::int64_t> cell(n);
  parallel::forEach(n, [&](std::size_t i) {
    const Vec3& p = xs[i];
    const std::int64_t ix = std::min(static_cast<std::int64_t>((p.x() - grid.origin.x()) * invCell), nx - 1);
    const std::int64_t iy = std::min(static_cast<std::int64_t>((p.y() - grid.origin.y()) * invCell), ny - 1);
    const std::int64_t iz = std::min(static_cast<std::int64_t>((p.z() - grid.origin.z()) * invCell), nz - 1);
    cell[i] = ix + nx * (iy + ny * iz);
  });
  cells.cellStart.assign(static_cast<std::size_t>(nCells) + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++cells.cellStart[static_cast<std::size_t>(cell[i]) + 1];
  for (std::int64_t c = 0; c < nCells; ++c) cells.cellStart[c + 1] += cells.cellStart[c];
  std::vector<std::int64_t> fill(cells.cellStart.begin(), cells.cellStart.end() - 1);
  cells.index.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    cells.index[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell[i])]++)] = static_cast<Index>(i);
}

template <class T>
void NeighbourSearch::gatherInOrder(const std::vector<Vec3>& xs, const Vec3& origin, const CellSort& cells,
                                    SortedCoordinates<T>& out) {
  const std::size_t n = cells.index.size();
  out.x.assign(n + kCoordinatePadding, T(0));
  out.y.assign(n + kCoordinatePadding, T(0));
  out.z.assign(n + kCoordinatePadding, T(0));
  parallel::forEach(n, [&](std::size_t k) {
    const Vec3 p = xs[static_cast<std::size_t>(cells.index[k])] - origin;
    out.x[k] = static_cast<T>(p.x());
    out.y[k] = static_cast<T>(p.y());
    out.z[k] = static_cast<T>(p.z());
  });
}

template <class List>
void NeighbourSearch::build(const std::vector<const std::vector<Vec3>*>& positions,
                            const std::vector<std::vector<bool>>& wanted, double radius, std::vector<List>& lists) {
  constexpr bool ascending = std::is_same_v<List, CandidateList>;
  ++gridSearches_;
  clearLists(lists);
  const CellGrid grid = makeGrid(positions, radius);
  const std::int64_t nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  const double invCell = 1.0 / grid.cellSize;
  double extent = 0.0;
  for (int d = 0; d < 3; ++d) extent = std::max(extent, static_cast<double>(grid.dims[d]) * grid.cellSize);
  const double radius2 = ascending ? floatTestRadius2(radius, extent) : radius * radius;
  // Float coordinates are taken relative to the grid's origin, which keeps their rounding to the grid's extent. The
  // lists at H test in double, as filterCandidates() does: there x - 0 and p - 0 are exact.
  const Vec3 origin = ascending ? grid.origin : Vec3::Zero();

  auto cellOf = [&](const Vec3& p) {
    CellIndex c{static_cast<std::int64_t>((p.x() - grid.origin.x()) * invCell),
                static_cast<std::int64_t>((p.y() - grid.origin.y()) * invCell),
                static_cast<std::int64_t>((p.z() - grid.origin.z()) * invCell)};
    c.ix = std::min(c.ix, nx - 1);
    c.iy = std::min(c.iy, ny - 1);
    c.iz = std::min(c.iz, nz - 1);
    return c;
  };

  // Sort every set that is searched in by cell, with a copy of its positions in that order. A grid search at
  // H + skin also sorts the sets that only get lists, and keeps the sorting: the movers' searches use it.
  // The sorted copy of a set's positions lives while the lists searched in it are filled, one set at a time: the
  // grid search is where a run's memory peaks.
  std::vector<CellSort> sorted(sets_);
  for (std::size_t b = 0; b < sets_; ++b) {
    bool needed = false, searchedIn = false;
    for (std::size_t a = 0; a < sets_; ++a) {
      needed = needed || wanted[a][b] || (ascending && wanted[b][a]);
      searchedIn = searchedIn || wanted[a][b];
    }
    if (!needed) continue;
    SortedCoordinates<std::conditional_t<ascending, float, double>> sx;
    sortIntoCells(*positions[b], grid, sorted[b]);
    if (searchedIn) gatherInOrder(*positions[b], origin, sorted[b], sx);
    const CellSort& s = sorted[b];
    for (std::size_t a = 0; a < sets_; ++a) {
      if (!wanted[a][b]) continue;
      const auto& xa = *positions[a];
      const bool self = a == b;
      const std::size_t withList = listedOf(a, xa.size());
      const auto find = [&](std::size_t i, IndexBuffer& out) {
        const Vec3& p = xa[i];
        const CellIndex c = cellOf(p);
        const Vec3 fromOrigin = p - origin;
        const Index skipped = self ? static_cast<Index>(i) : Index(-1);
        // The x-neighbours of one (y, z) row are consecutive cells: one contiguous range of the sorted particles.
        // In the Morton order of these cells (mortonOrder()) a row's cells are runs of consecutive indices, so
        // candidates come out as a few ascending runs for the insertion sort below.
        std::int64_t first[9], last[9];
        int rows = 0;
        std::size_t candidates = 0;
        for (std::int64_t z = std::max<std::int64_t>(c.iz - 1, 0); z <= std::min(c.iz + 1, nz - 1); ++z)
          for (std::int64_t y = std::max<std::int64_t>(c.iy - 1, 0); y <= std::min(c.iy + 1, ny - 1); ++y) {
            const std::int64_t row = nx * (y + ny * z);
            first[rows] = s.cellStart[row + std::max<std::int64_t>(c.ix - 1, 0)];
            last[rows] = s.cellStart[row + std::min(c.ix + 1, nx - 1) + 1];
            candidates += static_cast<std::size_t>(last[rows] - first[rows]);
            ++rows;
          }
        const std::size_t before = out.size();
        out.resize(before + candidates);
        Index* const dst = out.data() + before;
        std::size_t kept = 0;
        for (int r = 0; r < rows; ++r)
          kept += keepWithin(sx, s.index.data(), static_cast<std::size_t>(first[r]), static_cast<std::size_t>(last[r]),
                             fromOrigin, radius2, skipped, dst + kept);
        out.resize(before + kept);
      };
      if constexpr (ascending) {
        assemble(xa.size(), lists[a * sets_ + b], [&](std::size_t i, CodeBuffer& out) {
          if (i >= withList) return;
          thread_local IndexBuffer found; // the task's, encoded as soon as found
          found.clear();
          find(i, found);
          sortAscending(found.data(), found.data() + found.size());
          encodeCandidates(found.data(), found.data() + found.size(), out);
        });
      } else {
        lists[a * sets_ + b].indices_.setWidthFor(positions[b]->size());
        assemble(xa.size(), lists[a * sets_ + b], [&](std::size_t i, IndexBuffer& out) {
          if (i < withList) find(i, out);
        });
      }
    }
  }
  if constexpr (ascending) {
    builtGrid_ = grid;
    builtCells_ = std::move(sorted);
  }
}

std::vector<Index> NeighbourSearch::mortonOrder(const std::vector<Vec3>& x) const {
  const std::size_t n = x.size();
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index{0});
  if (n == 0) return order;
  // The cells of the grid search at H + skin (makeGrid() puts them on multiples of their size): each is then a
  // run of consecutive indices until particles move, and the grid search's candidates come out as a few ascending
  // runs, which its insertion sort merges fast (bench_kernels' BM_SearchSkin: 20.9 against 28.9 ms, bench/README).
  const CellGrid grid = makeGrid({&x}, h_ + skin_);
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
  const double invCell = 1.0 / grid.cellSize;
  parallel::forEach(n, [&](std::size_t i) {
    const Vec3 c = (x[i] - grid.origin) * invCell;
    code[i] = spread(static_cast<std::uint64_t>(c.x())) | spread(static_cast<std::uint64_t>(c.y())) << 1 |
              spread(static_cast<std::uint64_t>(c.z())) << 2;
  });
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return code[a] < code[b]; });
  return order;
}

} // namespace poro
