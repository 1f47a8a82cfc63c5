#pragma once
/// Uniform cell-grid neighbour search over several particle sets (METHOD.md §6.1): cell size H, 27-cell
/// stencil, strict ||x_ab|| < H, one compressed (CSR) list per requested ordered pair of sets.
/// Neighbours come in a fixed order (stencil cell, then index), so sums are reproducible.

#include "core/Types.hpp"

#include <cstdint>
#include <vector>

namespace poro {

/// Neighbours in set b of every particle of set a, in CSR form.
class NeighbourList {
public:
  struct Range {
    const Index* first;
    const Index* last;
    const Index* begin() const { return first; }
    const Index* end() const { return last; }
    std::size_t size() const { return static_cast<std::size_t>(last - first); }
  };
  Range of(std::size_t i) const { return {indices_.data() + offsets_[i], indices_.data() + offsets_[i + 1]}; }
  /// Position of particle i's first neighbour in the pair arrays (for per-pair data stored alongside).
  std::size_t offset(std::size_t i) const { return static_cast<std::size_t>(offsets_[i]); }
  std::size_t particles() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  std::size_t totalPairs() const { return indices_.size(); }

private:
  friend class NeighbourSearch;
  std::vector<std::int64_t> offsets_;
  std::vector<Index> indices_;
};

class NeighbourSearch {
public:
  explicit NeighbourSearch(double supportRadius) : h_(supportRadius) {}

  /// Positions of every set, by set number. `wanted[a][b]` says whether the list a->b is needed.
  /// Lists of a set with itself exclude the particle itself.
  void update(const std::vector<const std::vector<Vec3>*>& positions, const std::vector<std::vector<bool>>& wanted);

  /// The list of set a against set b (empty if it was not requested).
  const NeighbourList& list(std::size_t a, std::size_t b) const { return lists_[a * sets_ + b]; }

  /// Permutation that puts the particles into Morton (Z-curve) order of their cells; stable for ties.
  std::vector<Index> mortonOrder(const std::vector<Vec3>& x) const;

  double supportRadius() const { return h_; }

private:
  struct CellGrid {
    Vec3 origin = Vec3::Zero();
    std::int64_t dims[3] = {0, 0, 0};
  };
  CellGrid makeGrid(const std::vector<const std::vector<Vec3>*>& positions) const;

  double h_;
  std::size_t sets_ = 0;
  std::vector<NeighbourList> lists_;
};

} // namespace poro
