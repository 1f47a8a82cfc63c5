#pragma once
/// Pairs of points closer than a distance d whose labels must keep apart (sampleParticles: particles of two regions
/// that overlap, RegionPlacement.hpp). A hash grid of cell size >= d: the points are sorted by their cell's key and
/// every cell is compared with its 27 neighbours, whose keys the sorted cells are walked past once per row offset, so
/// the search costs O(N) after an O(N log N) sort and holds 16 bytes per point and 12 per occupied cell.
/// Unlike sph/NeighbourSearch it allocates nothing per empty cell: the walls of a large container sampled at a
/// small radius span far more cells than they have particles.

#include "core/Types.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace poro {

/// Points with a label each (a particle set's positions and its objectId, the index of the region it was sampled
/// from). Both vectors have the same length and outlive the search.
struct LabelledPoints {
  const std::vector<Vec3>* x = nullptr;
  const std::vector<std::int64_t>* label = nullptr;
};

/// The pairs of one pair of labels (a < b) closer than the distance searched for.
struct ClosePairs {
  std::size_t a = 0, b = 0;   ///< labels, a < b
  std::size_t count = 0;      ///< pairs closer than the distance
  double closest = 0.0;       ///< the smallest distance among them [m]
  Vec3 pointA = Vec3::Zero(); ///< the closest pair: the point labelled a
  Vec3 pointB = Vec3::Zero(); ///< and the point labelled b
};

/// Every pair (p, q) of `points` with |x_p - x_q| < `distance` whose labels differ and `apart[label p][label q]`
/// holds, counted once per pair, summed per pair of labels; sorted by (a, b). Labels are in [0, apart.size()), and
/// `apart` is symmetric. Points whose label is apart from no other label are left out of the grid.
std::vector<ClosePairs> findClosePairs(const std::vector<LabelledPoints>& points, double distance,
                                       const std::vector<std::vector<bool>>& apart);

} // namespace poro
