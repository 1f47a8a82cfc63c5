#pragma once
/// Lattice sampling of closed surfaces (METHOD.md §2.3): the lattice sampleBox gives the surface's bounding box
/// (spacing 2r), classified one row at a time. Each row asks the shape once for its crossings and keeps the points
/// with an odd number of crossings below them (parity), so a row costs one surface query, not one per point.
/// A point within kOnSurfaceTolerance * 2r of the surface counts as lying on it: it is neither inside nor
/// outside, and is not sampled. Rows are classified in parallel and concatenated in lattice order (x fastest, then
/// y, then z, as sampleBox), so the result is the same for any number of threads.

#include "geometry/ClosedShape.hpp"

#include <vector>

namespace poro {

/// Distance from a surface, relative to the spacing 2r, below which a lattice point counts as on the surface
/// (the 1e-9 of latticeCount: coordinates written to the round-off of their decimals still meet).
inline constexpr double kOnSurfaceTolerance = 1e-9;

/// The lattice points strictly inside `shape`.
std::vector<Vec3> sampleInside(const ClosedShape& shape, double particleRadius);

/// Which side of a closed surface a wall body lies on.
enum class WallSide {
  Inside, ///< a solid wall whose outer surface is the surface (an obstacle)
  Outside ///< a container whose inner surface is the surface
};

/// A wall body of `layers` lattice layers: the lattice points on `side` of the surface closer to it than
/// layers * 2r, so that the first layer lies about r behind the surface (METHOD.md §2.3). Outside, the lattice is
/// the bounding box's grown by `layers` points per face. Points far from the surface are passed over using
/// that the distance changes by at most 2r from one point of a row to the next.
std::vector<Vec3> sampleWallBody(const ClosedShape& shape, double particleRadius, int layers, WallSide side);

} // namespace poro
