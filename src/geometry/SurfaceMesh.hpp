#pragma once
/// A closed triangle surface for the lattice samplers (particleDict `shape: surface`), its triangles in a CGAL
/// AABB tree (behind this header).
///
/// A row asks the tree once for the triangles that come within the tolerance of its line. Whether the line
/// crosses a triangle is decided exactly, with Simulation of Simplicity (Edelsbrunner & Mücke 1990): exact 2D
/// orientation tests of the row's (y, z) against the triangle's projection, ties broken as if (y, z) were moved
/// by (ε, ε²) with ε → 0. A row through an edge or a vertex is therefore counted by exactly one of the triangles
/// around it, and a row in the plane of a face by none, so the parity of the crossings is right for every point
/// off the surface. Only where the row meets a triangle (x) is computed in floating point; it is off by round-off,
/// far below the on-surface tolerance, so points it could misplace are those the tolerance removes anyway.

#include "geometry/ClosedShape.hpp"
#include "geometry/TriangleMesh.hpp"

#include <memory>

namespace poro {

class SurfaceMesh final : public ClosedShape {
public:
  /// `mesh` must be closed and free of self-intersections (SurfaceFile::read checks both).
  explicit SurfaceMesh(const TriangleMesh& mesh);
  ~SurfaceMesh() override;
  SurfaceMesh(const SurfaceMesh&) = delete;
  SurfaceMesh& operator=(const SurfaceMesh&) = delete;

  std::size_t triangleCount() const;

  Vec3 boxMin() const override;
  Vec3 boxMax() const override;
  double volume() const override;
  double area() const override;
  void crossRow(double y, double z, double tolerance, RowCrossings& row) const override;
  double distance(const Vec3& p) const override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace poro
