#pragma once
/// A closed surface as the lattice samplers see it (ShapeSampling.hpp): its bounding box, where a lattice row
/// crosses it, and distances to it. Sphere is analytic; SurfaceMesh is a triangle mesh (CGAL stays in its .cpp).

#include "core/Types.hpp"

#include <utility>
#include <vector>

namespace poro {

/// What a closed surface tells about one lattice row, the line {(x, y, z) : x real}.
struct RowCrossings {
  /// x of every crossing of the row with the surface, in any order: a point of the row lies inside when an odd
  /// number of crossings lie below its x.
  std::vector<double> crossings;
  /// Intervals [first, second] of x outside of which no point of the row comes within the tolerance asked for
  /// of the surface (in any order, may overlap): only points inside them need a distance query.
  std::vector<std::pair<double, double>> nearSurface;

  void clear() {
    crossings.clear();
    nearSurface.clear();
  }
};

class ClosedShape {
public:
  virtual ~ClosedShape() = default;

  /// Bounding box of the surface [m].
  virtual Vec3 boxMin() const = 0;
  virtual Vec3 boxMax() const = 0;
  /// Enclosed volume [m^3] and surface area [m^2], for particle-count estimates before sampling.
  virtual double volume() const = 0;
  virtual double area() const = 0;
  /// Adds to `row` the crossings of the row line through (y, z) and the x intervals where its points may lie
  /// within `tolerance` [m] of the surface. Safe to call from several threads at once.
  virtual void crossRow(double y, double z, double tolerance, RowCrossings& row) const = 0;
  /// Distance from p to the surface [m]. Safe to call from several threads at once.
  virtual double distance(const Vec3& p) const = 0;
};

} // namespace poro
