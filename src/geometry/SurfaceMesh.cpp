#include "geometry/SurfaceMesh.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <Eigen/Geometry>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace poro {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Point2 = Kernel::Point_2;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

/// What a row query needs of one triangle, in doubles.
struct Face {
  Vec3 a, b, c;
  Vec3 normal;         ///< (b - a) x (c - a), not normalised
  double normalLength; ///< twice the area
  double xMin, xMax;
};

/// Sign of the orientation of (a, b, p) with p moved by (ε, ε²), ε → 0: exact, never 0 unless a = b, and
/// opposite for the edge (b, a) of the neighbouring face (Simulation of Simplicity).
int perturbedSide(const Point2& a, const Point2& b, const Point2& p) {
  const CGAL::Orientation o = CGAL::orientation(a, b, p);
  if (o != CGAL::COLLINEAR) return o == CGAL::LEFT_TURN ? 1 : -1;
  // orient(a, b, p + (ε, ε²)) = orient(a, b, p) - ε (b_2 - a_2) + ε² (b_1 - a_1)
  if (a.y() != b.y()) return a.y() > b.y() ? 1 : -1;
  if (a.x() != b.x()) return b.x() > a.x() ? 1 : -1;
  return 0;
}

/// Twice the signed area of (p, q, r) in floating point.
double area2(const Point2& p, const Point2& q, const Point2& r) {
  return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
}

/// x where the row through (y, z) crosses the face, if the perturbed row crosses it.
std::optional<double> crossing(const Face& f, double y, double z) {
  const Point2 a(f.a.y(), f.a.z()), b(f.b.y(), f.b.z()), c(f.c.y(), f.c.z()), p(y, z);
  const CGAL::Orientation o = CGAL::orientation(a, b, c);
  if (o == CGAL::COLLINEAR) return std::nullopt; // the face contains the row direction: the perturbed row misses it
  const int s = o == CGAL::LEFT_TURN ? 1 : -1;
  if (perturbedSide(a, b, p) != s || perturbedSide(b, c, p) != s || perturbedSide(c, a, p) != s) return std::nullopt;
  // Barycentric weights of (y, z), clamped to be non-negative so that x stays within the face's extent.
  const double wa = std::max(0.0, s * area2(p, b, c)), wb = std::max(0.0, s * area2(a, p, c)),
               wc = std::max(0.0, s * area2(a, b, p));
  const double sum = wa + wb + wc;
  if (!(sum > 0.0)) return (f.a.x() + f.b.x() + f.c.x()) / 3.0;
  return (wa * f.a.x() + wb * f.b.x() + wc * f.c.x()) / sum;
}

/// The x interval of the row through (y, z) whose points may lie within `tolerance` of the face: within it of
/// the face's plane, n.(p - a) = n_x (x - a_x) + g, and of its x extent. Twice the tolerance: a round-off margin.
std::optional<std::pair<double, double>> nearFace(const Face& f, double y, double z, double tolerance) {
  const double slack = 2.0 * tolerance * f.normalLength;
  const double g = f.normal.y() * (y - f.a.y()) + f.normal.z() * (z - f.a.z());
  double lo = f.xMin - 2.0 * tolerance, hi = f.xMax + 2.0 * tolerance;
  const double nx = f.normal.x();
  if (nx == 0.0) {
    if (std::abs(g) > slack) return std::nullopt;
  } else {
    const double x1 = f.a.x() + (-g - slack) / nx, x2 = f.a.x() + (-g + slack) / nx;
    lo = std::max(lo, std::min(x1, x2));
    hi = std::min(hi, std::max(x1, x2));
  }
  if (lo > hi) return std::nullopt;
  return std::make_pair(lo, hi);
}

} // namespace

struct SurfaceMesh::Impl {
  std::vector<Triangle> triangles; ///< the tree's primitives point into this
  std::vector<Face> faces;         ///< same order
  Tree tree;
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
  double volume = 0.0, area = 0.0;
};

SurfaceMesh::SurfaceMesh(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.triangles.reserve(mesh.triangles.size());
  m.faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    Face f;
    f.a = mesh.vertices[t[0]];
    f.b = mesh.vertices[t[1]];
    f.c = mesh.vertices[t[2]];
    f.normal = (f.b - f.a).cross(f.c - f.a);
    f.normalLength = f.normal.norm();
    f.xMin = std::min({f.a.x(), f.b.x(), f.c.x()});
    f.xMax = std::max({f.a.x(), f.b.x(), f.c.x()});
    m.volume += f.a.dot(f.b.cross(f.c)) / 6.0; // divergence theorem: positive for outward faces
    m.area += 0.5 * f.normalLength;
    // The box of the faces' corners, not of all vertices: a stray unused vertex must not move the lattice.
    m.min = m.min.cwiseMin(f.a).cwiseMin(f.b).cwiseMin(f.c);
    m.max = m.max.cwiseMax(f.a).cwiseMax(f.b).cwiseMax(f.c);
    m.triangles.emplace_back(Point(f.a.x(), f.a.y(), f.a.z()), Point(f.b.x(), f.b.y(), f.b.z()),
                             Point(f.c.x(), f.c.y(), f.c.z()));
    m.faces.push_back(f);
  }
  m.volume = std::abs(m.volume);
  m.tree.insert(m.triangles.begin(), m.triangles.end());
  // Both built now, so that the queries of parallel rows only read the tree.
  m.tree.build();
  m.tree.accelerate_distance_queries();
}

SurfaceMesh::~SurfaceMesh() = default;

std::size_t SurfaceMesh::triangleCount() const { return impl_->faces.size(); }
Vec3 SurfaceMesh::boxMin() const { return impl_->min; }
Vec3 SurfaceMesh::boxMax() const { return impl_->max; }
double SurfaceMesh::volume() const { return impl_->volume; }
double SurfaceMesh::area() const { return impl_->area; }

void SurfaceMesh::crossRow(double y, double z, double tolerance, RowCrossings& row) const {
  const Impl& m = *impl_;
  // Every face within `tolerance` of the row line meets this thin box around it, and so does every face the
  // line crosses, with room to spare for the round-off of the box test.
  const CGAL::Bbox_3 tube(m.min.x(), y - tolerance, z - tolerance, m.max.x(), y + tolerance, z + tolerance);
  const auto visit = [&](const Primitive::Id& id) {
    const Face& f = m.faces[static_cast<std::size_t>(id - m.triangles.begin())];
    if (const auto x = crossing(f, y, z)) row.crossings.push_back(*x);
    if (const auto interval = nearFace(f, y, z, tolerance)) row.nearSurface.push_back(*interval);
  };
  m.tree.all_intersected_primitives(tube, boost::make_function_output_iterator(visit));
}

double SurfaceMesh::distance(const Vec3& p) const {
  return std::sqrt(impl_->tree.squared_distance(Point(p.x(), p.y(), p.z())));
}

} // namespace poro
