#pragma once
/// Uniform cell-grid neighbour search over several particle sets (METHOD.md §6.1): 27-cell stencil, strict
/// ||x_ab|| < H, one compressed (CSR) list per requested ordered pair of sets.
/// With a skin s > 0 (Verlet lists), the grid search runs at H + s and is kept as candidates; each update keeps
/// the candidates within H. Particles that have moved s / 2 or more since the grid search ("movers": a jet, a
/// splash) are searched afresh at every update, and added to the lists of the others, until they are more than
/// a small share of all; then the grid search runs again. A flow that would cross the skin within two updates
/// is searched at H every update instead.
/// Neighbours come in a fixed order, so sums are reproducible: stencil cell, then index, for a search at H;
/// ascending index with the skin, where candidates searched earlier must give the same lists as a search now.
/// Either way a list is a function of the positions and of the bulk step (update()), so a run restarted at any
/// step continues bit for bit.

#include "core/ReallocVector.hpp"
#include "core/Types.hpp"
#include "sph/PackedIndices.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

namespace poro {

/// Neighbours in set b of every particle of set a, in CSR form.
class NeighbourList {
public:
  struct Range {
    PackedIndices::Iterator first;
    std::size_t count;
    PackedIndices::Iterator begin() const { return first; }
    PackedIndices::Iterator end() const { return first + count; }
    std::size_t size() const { return count; }
    /// The k-th neighbour.
    Index operator[](std::size_t k) const { return *(first + k); }
  };
  Range of(std::size_t i) const { return {indices_.at(offsets_[i]), std::size_t{offsets_[i + 1] - offsets_[i]}}; }
  /// Position of particle i's first neighbour in the pair arrays (for per-pair data stored alongside).
  std::size_t offset(std::size_t i) const { return static_cast<std::size_t>(offsets_[i]); }
  std::size_t particles() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  std::size_t totalPairs() const { return indices_.size(); }

private:
  friend class NeighbourSearch;
  /// 32 bits: a list of more than 2^32 - 1 pairs is refused by the search.
  std::vector<std::uint32_t> offsets_;
  PackedIndices indices_;
};

class NeighbourSearch {
public:
  explicit NeighbourSearch(double supportRadius, double skin = 0.0) : h_(supportRadius), skin_(skin) {}

  /// Positions of every set, by set number. `wanted[a][b]` says whether the list a->b is needed.
  /// Lists of a set with itself exclude the particle itself. `bulkStep` bounds how far particles move before the
  /// next update [m] (speed times the step), all but at most one listed particle in `particlesPerMover` (a jet,
  /// which the skin handles as movers): the skin is used when it is below skin / 4.
  /// `listed[a]` (when given) is how many of set a's first particles get lists; the others have empty ones but are
  /// found as neighbours (a parallel run's ghosts, whose owners compute them).
  void update(const std::vector<const std::vector<Vec3>*>& positions, const std::vector<std::vector<bool>>& wanted,
              double bulkStep = 0.0, const std::vector<std::size_t>& listed = {});

  /// The list of set a against set b (empty if it was not requested).
  const NeighbourList& list(std::size_t a, std::size_t b) const { return lists_[a * sets_ + b]; }

  /// Permutation that puts the particles into Morton (Z-curve) order of the grid search's cells (H + skin);
  /// stable for ties.
  std::vector<Index> mortonOrder(const std::vector<Vec3>& x) const;

  double supportRadius() const { return h_; }
  /// The grid search runs again once the movers (of all sets, ghosts and walls included) are more than one in this
  /// many of the particles that get lists: each mover costs a search of its own at every update, and a few times
  /// that in the others' lists.
  static constexpr std::size_t particlesPerMover = 32;
  /// The skin is used when the candidates will last two updates at least: 2 x 2 x bulkStep < skin.
  static constexpr double stepsPerSkin = 4.0;

  /// The next update runs the grid search, whatever the particles' displacements (after a reordering).
  void invalidate() { valid_ = false; }
  /// Updates so far, and the grid searches among them (all of them without a skin).
  std::size_t updates() const { return updates_; }
  std::size_t gridSearches() const { return gridSearches_; }

private:
  /// Leaves the elements a resize adds uninitialised: the lists' buffers grow by all candidates, are written, and
  /// shrink to the neighbours kept, so zero-filling them first would be wasted.
  template <class T> struct UninitialisedAllocator : std::allocator<T> {
    template <class U> struct rebind { using other = UninitialisedAllocator<U>; };
    UninitialisedAllocator() = default;
    template <class U> UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
    template <class U> void construct(U* p) noexcept { ::new (static_cast<void*>(p)) U; } // others: placement new
  };
  using IndexBuffer = std::vector<Index, UninitialisedAllocator<Index>>;

  /// The candidates of one list a->b at H + skin, ascending per particle, in codes of 16 bits: the first candidate
  /// as its index in two codes, each further one as its step from the one before (a grid search over Morton-sorted
  /// particles finds runs of near-consecutive indices), a step of 2^16 or more as a 0 and the index in two codes.
  /// About half the bytes of indices: the candidates outnumber the lists at H by a third and live beside them from
  /// one grid search to the next (25 MB less for the published Seep at r = 1 cm).
  struct CandidateList {
    std::vector<std::uint32_t> offsets_;   ///< particle i's codes are indices_[offsets_[i] .. offsets_[i + 1])
    ReallocVector<std::uint16_t> indices_; ///< the codes (named like NeighbourList's, which assemble() fills alike)
  };
  using CodeBuffer = std::vector<std::uint16_t, UninitialisedAllocator<std::uint16_t>>;
  /// Appends the codes of the ascending, distinct indices [first, last) to `out`.
  static void encodeCandidates(const Index* first, const Index* last, CodeBuffer& out);

  /// Whether update() uses the skin for a step of `bulkStep` (else it searches at H in stencil order).
  bool skinPays(double bulkStep) const;
  struct CellGrid {
    Vec3 origin = Vec3::Zero();
    std::int64_t dims[3] = {0, 0, 0};
    double cellSize = 1.0;
  };
  CellGrid makeGrid(const std::vector<const std::vector<Vec3>*>& positions, double radius) const;
  /// One set's particles sorted by cell of a grid: cell c holds index[cellStart[c] .. cellStart[c + 1]).
  struct CellSort {
    std::vector<std::int64_t> cellStart;
    std::vector<Index> index;
  };
  /// The grid search at `radius` into `lists`: each particle's neighbours in stencil order (NeighbourList), or
  /// ascending as candidates (CandidateList).
  template <class List>
  void build(const std::vector<const std::vector<Vec3>*>& positions, const std::vector<std::vector<bool>>& wanted,
             double radius, std::vector<List>& lists);
  /// Whether the candidates cannot serve these sets and lists at all (first update, other lists or sizes).
  bool candidatesStale(const std::vector<const std::vector<Vec3>*>& positions,
                       const std::vector<std::vector<bool>>& wanted) const;
  /// Flags and lists the movers of every set; returns how many there are.
  std::size_t findMovers(const std::vector<const std::vector<Vec3>*>& positions);
  /// Sorts the movers of every set, by their positions now, into moverGrid_ for the searches around them.
  void sortMovers(const std::vector<const std::vector<Vec3>*>& positions);
  /// The list a->b at H from the candidates, the movers searched afresh.
  void filterCandidates(const std::vector<const std::vector<Vec3>*>& positions, std::size_t a, std::size_t b);
  /// Appends to `out` the particles of set b within H of p that are not movers, searched in b's cells of the last
  /// grid search, and (withMovers) b's movers; `self` (skipped) is p's index when p is of set b, else -1.
  void searchAround(const std::vector<const std::vector<Vec3>*>& positions, std::size_t b, const Vec3& p,
                    std::int64_t self, bool withMovers, IndexBuffer& out) const;
  /// Positions in the order of a CellSort, one array per coordinate, padded by kCoordinatePadding: the grid
  /// search's distance tests vectorise. In double for lists at H; in float, relative to the grid's origin, for the
  /// candidates, which may then hold a few pairs beyond H + skin (the lists filter them exactly): half the memory
  /// while the grid search runs, and twice the tests per instruction.
  template <class T> struct SortedCoordinates { std::vector<T> x, y, z; };
  static constexpr std::size_t kCoordinatePadding = 7;
  /// Sorts positions xs (all inside `grid`) by cell.
  static void sortIntoCells(const std::vector<Vec3>& xs, const CellGrid& grid, CellSort& cells);
  /// The positions xs relative to `origin` in the order of `cells`.
  template <class T>
  static void gatherInOrder(const std::vector<Vec3>& xs, const Vec3& origin, const CellSort& cells,
                            SortedCoordinates<T>& out);
  /// Particles of set a that get lists in this update.
  std::size_t listedOf(std::size_t a, std::size_t size) const {
    return a < listed_.size() ? std::min(listed_[a], size) : size;
  }
  /// Sets² empty lists, keeping their memory.
  template <class List> void clearLists(std::vector<List>& lists) const;
  /// Fills `list` for n particles in parallel; append(i, out) appends particle i's neighbours (or codes) to out.
  template <class List, class AppendNeighbours>
  static void assemble(std::size_t n, List& list, const AppendNeighbours& append);

  double h_;
  double skin_;
  std::size_t sets_ = 0;
  std::vector<NeighbourList> lists_;
  std::vector<CandidateList> candidates_; ///< lists at H + skin from the last grid search
  /// Positions at the last grid search, in single precision: they only tell movers, with the rounding added to the
  /// distance moved (findMovers()).
  std::vector<std::vector<Eigen::Vector3f>> builtAt_;
  std::vector<std::vector<bool>> builtWanted_;     ///< the lists requested then
  std::vector<std::size_t> listed_;                ///< this update's `listed`
  std::vector<std::size_t> builtListed_;           ///< the candidates' `listed`
  CellGrid builtGrid_;                             ///< the grid of the last grid search at H + skin
  std::vector<CellSort> builtCells_;               ///< every searched set sorted into it, by the positions then
  std::vector<std::vector<std::uint8_t>> isMover_; ///< per set, 1 for a mover (empty while the set has none)
  std::vector<std::vector<Index>> movers_;         ///< per set, its movers in ascending order
  CellGrid moverGrid_;                             ///< a grid of cells H + skin over the movers' positions now
  std::vector<CellSort> moverCells_;               ///< per set, its movers (by rank in movers_) sorted into it
  std::vector<std::uint32_t> extraStart_;          ///< scratch of filterCandidates: where particle i's extras start
  std::vector<Index> extras_;                      ///< scratch of filterCandidates: movers near each particle
  bool valid_ = false;
  std::size_t updates_ = 0;
  std::size_t gridSearches_ = 0;
};

} // namespace poro
