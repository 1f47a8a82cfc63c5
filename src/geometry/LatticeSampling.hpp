#pragma once
/// Lattice sampling of boxes and box containers (METHOD.md §2.3): a simple cubic lattice of spacing 2r,
/// n = round(L/2r) points per axis (half-integers round up), centres at min + r + 2r k, so a box whose edges
/// are multiples of 2r is tiled exactly and holds the mass rho * volume.

#include "core/Types.hpp"

#include <array>
#include <vector>

namespace poro {

/// Number of lattice points along an edge of length `length` at `spacing` = 2r.
long long latticeCount(double length, double spacing);

/// The lattice sampleBox fills [min, max] with, for samplers that walk it row by row (closed surfaces): point
/// (i, j, k) is at origin + spacing (i, j, k), for indices first <= i < first + count[0] (likewise j, k).
struct BoxLattice {
  Vec3 origin = Vec3::Zero();       ///< min + r: the centre of point (0, 0, 0)
  double spacing = 0.0;             ///< 2r
  long long first = 0;              ///< index of the first point on every axis: 0, or -extra
  std::array<long long, 3> count{}; ///< points per axis

  double coordinate(int axis, long long index) const { return origin[axis] + spacing * static_cast<double>(index); }
};

/// The lattice of sampleBox(min, max, particleRadius), grown by `extra` points beyond every face (wall bodies
/// outside a surface), so that the grown lattice continues the box's own.
BoxLattice boxLattice(const Vec3& min, const Vec3& max, double particleRadius, long long extra = 0);

/// Lattice points filling the box [min, max].
std::vector<Vec3> sampleBox(const Vec3& min, const Vec3& max, double particleRadius);

/// Faces of a box, in the order xMin, xMax, yMin, yMax, zMin, zMax.
using FaceFlags = std::array<bool, 6>;

/// Wall particles of a container whose inner faces are the box [min, max]: `layers` lattice layers behind
/// every face (the first r behind the surface, METHOD.md §2.3), edges and corners filled, no particles on
/// the faces flagged in `open` (e.g. an open top).
std::vector<Vec3> sampleContainer(const Vec3& min, const Vec3& max, double particleRadius, int layers,
                                  const FaceFlags& open);

/// The number of points sampleBox and sampleContainer return, in floating point so that it neither overflows nor
/// allocates: a radius far too small for the regions is refused before sampling (sampleParticles).
double boxPointCount(const Vec3& min, const Vec3& max, double particleRadius);
double containerPointCount(const Vec3& min, const Vec3& max, double particleRadius, int layers, const FaceFlags& open);

} // namespace poro
