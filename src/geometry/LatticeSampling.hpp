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
