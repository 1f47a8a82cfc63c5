#include "geometry/SurfaceFile.hpp"

#include "core/Error.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace poro {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Polygon = std::vector<std::size_t>;
using Mesh = CGAL::Surface_mesh<Point>;

/// The largest coordinate magnitude a surface may have: cubes of differences of such coordinates, summed over millions
/// of faces, stay below the largest double (1.8e308).
constexpr double kMaxCoordinate = 1e100;

std::string format(const Point& p) {
  std::ostringstream out;
  out << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return out.str();
}

std::string plural(std::size_t n, const std::string& word, const std::string& words = "") {
  return std::to_string(n) + " " + (n == 1 ? word : words.empty() ? word + "s" : words);
}

/// Sends std::cerr to nowhere while it lives: CGAL's readers print what they did not understand there even when not
/// asked to, and the InputError says what the user needs to know.
class SilentCerr {
public:
  SilentCerr() : saved_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~SilentCerr() { std::cerr.rdbuf(saved_); }
  SilentCerr(const SilentCerr&) = delete;
  SilentCerr& operator=(const SilentCerr&) = delete;

private:
  std::ostringstream sink_;
  std::streambuf* saved_;
};

/// The checks of one file, in the order they can be made: each relies on the ones before.
class SurfaceReader {
public:
  explicit SurfaceReader(std::string path) : path_(std::move(path)) {}

  SurfaceFile read(bool repair) {
    readSoup();
    const std::size_t polygons = countPolygons(repair);
    PMP::merge_duplicate_points_in_polygon_soup(points_, polygons_);
    checkDegenerateFaces();
    checkEdges();
    orientSoup();
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points_, polygons_, mesh);
    if (polygons > 0) {
      if (!PMP::triangulate_faces(mesh))
        fail("cannot triangulate its faces with more than three corners (are they far from flat?)");
      notes_.push_back("triangulated " + plural(polygons, "face") + " with more than three corners (repair: true)");
    }
    checkSelfIntersections(mesh);
    checkVolume(mesh);
    if (const std::size_t reversed = orientOutward(mesh); reversed > 0)
      notes_.push_back(plural(reversed, "face") + " pointed into the body; reversed them so that the surface bounds "
                                                  "its volume");
    return {toTriangleMesh(mesh), notes_};
  }

private:
  [[noreturn]] void fail(const std::string& message) const { throw InputError(path_ + ": " + message); }

  void readSoup() {
    std::string extension = std::filesystem::path(path_).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::string name = extension == ".stl"   ? "STL"
                             : extension == ".obj" ? "OBJ"
                             : extension == ".off" ? "OFF"
                             : extension == ".ply" ? "PLY"
                                                   : "";
    if (name.empty())
      fail("unknown surface format '" + (extension.empty() ? std::string("(no extension)") : extension) +
           "'; expected .stl (ASCII or binary), .obj, .off or .ply");
    if (std::filesystem::is_directory(path_)) fail("cannot open file (it is a directory)");
    if (!std::ifstream(path_)) fail(std::string("cannot open file (") + std::strerror(errno) + ")");
    bool read = false;
    try {
      const SilentCerr silent;
      read = CGAL::IO::read_polygon_soup(path_, points_, polygons_);
    } catch (const std::exception&) { // some readers throw on malformed input
      read = false;
    }
    if (!read) fail("cannot read it as " + name + ": the file is damaged, empty or not " + name);
    if (polygons_.empty()) fail("holds no faces; expected a closed surface of triangles in " + name);
    for (std::size_t v = 0; v < points_.size(); ++v) {
      const Point& p = points_[v];
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
        fail("vertex " + std::to_string(v + 1) + " has a coordinate that is not a finite number");
      // The volume sums products of three coordinates and the size squares them: beyond this they overflow to inf
      // and the surface would seem to enclose no volume.
      if (std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())}) > kMaxCoordinate) {
        std::ostringstream msg;
        msg << "vertex " << v + 1 << " at " << format(p) << " has a coordinate beyond +-" << kMaxCoordinate
            << ", too large to compute the enclosed volume with (products of three coordinates overflow); check "
            << "the file's units and what its exporter wrote";
        fail(msg.str());
      }
    }
    for (std::size_t f = 0; f < polygons_.size(); ++f)
      for (std::size_t v : polygons_[f])
        if (v >= points_.size())
          fail("face " + std::to_string(f + 1) + " refers to vertex " + std::to_string(v + 1) +
               ", but there are only " + plural(points_.size(), "vertex", "vertices"));
  }

  /// The number of faces with more than three corners; an error unless `repair` allows triangulating them.
  std::size_t countPolygons(bool repair) const {
    std::size_t count = 0, first = 0;
    for (std::size_t f = 0; f < polygons_.size(); ++f) {
      if (polygons_[f].size() < 3)
        fail("face " + std::to_string(f + 1) + " has " + plural(polygons_[f].size(), "corner") +
             "; a face needs at least three");
      if (polygons_[f].size() > 3 && count++ == 0) first = f;
    }
    if (count > 0 && !repair)
      fail(std::to_string(count) + " of " + plural(polygons_.size(), "face") + " are not triangles, e.g. face " +
           std::to_string(first + 1) + " with " + std::to_string(polygons_[first].size()) + " corners at " +
           format(points_[polygons_[first][0]]) + ", ...; export the surface triangulated, or set repair: true on " +
           "the region to triangulate them");
    return count;
  }

  void checkDegenerateFaces() const {
    std::size_t count = 0, first = 0;
    for (std::size_t f = 0; f < polygons_.size(); ++f) {
      const Polygon& p = polygons_[f];
      Polygon sorted = p;
      std::sort(sorted.begin(), sorted.end());
      const bool repeated = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      const bool flat = p.size() == 3 && CGAL::collinear(points_[p[0]], points_[p[1]], points_[p[2]]);
      if ((repeated || flat) && count++ == 0) first = f;
    }
    if (count > 0)
      fail(plural(count, "degenerate face") + " (corners that coincide or lie on one line), e.g. face " +
           std::to_string(first + 1) + " at " + format(points_[polygons_[first][0]]) +
           "; remove them with a mesh tool (e.g. MeshLab: Remove Zero Area Faces)");
  }

  /// Every edge must belong to exactly two faces: one face is an open boundary, more is not a manifold.
  void checkEdges() const {
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    for (const Polygon& p : polygons_)
      for (std::size_t k = 0; k < p.size(); ++k) {
        const std::size_t a = p[k], b = p[(k + 1) % p.size()];
        edges.emplace_back(std::min(a, b), std::max(a, b));
      }
    std::sort(edges.begin(), edges.end());
    std::size_t open = 0, shared = 0;
    std::pair<std::size_t, std::size_t> firstOpen, firstShared;
    for (std::size_t k = 0; k < edges.size();) {
      std::size_t end = k;
      while (end < edges.size() && edges[end] == edges[k]) ++end;
      if (end - k == 1 && open++ == 0) firstOpen = edges[k];
      if (end - k > 2 && shared++ == 0) firstShared = edges[k];
      k = end;
    }
    const auto edge = [&](const std::pair<std::size_t, std::size_t>& e) {
      return "from " + format(points_[e.first]) + " to " + format(points_[e.second]);
    };
    if (open > 0)
      fail("the surface is not closed: " + plural(open, "open boundary edge") + " (edges of only one face), e.g. " +
           edge(firstOpen) + "; close the holes so that it has an inside");
    if (shared > 0)
      fail("the surface is not a manifold: " + plural(shared, "edge") + " shared by more than two faces, e.g. " +
           edge(firstShared) + "; separate the bodies that touch there");
  }

  /// Reports what orient_polygon_soup finds and does.
  struct OrientationVisitor : PMP::Default_orientation_visitor {
    std::size_t* reversed;
    std::size_t* pinchedVertex; ///< a vertex where faces meet only at that point, or SIZE_MAX
    void polygon_orientation_reversed(std::size_t) { ++*reversed; }
    void non_manifold_vertex(std::size_t v, std::size_t) {
      if (*pinchedVertex == SIZE_MAX) *pinchedVertex = v;
    }
  };

  void orientSoup() {
    std::size_t reversed = 0, pinched = SIZE_MAX;
    OrientationVisitor visitor;
    visitor.reversed = &reversed;
    visitor.pinchedVertex = &pinched;
    if (!PMP::orient_polygon_soup(points_, polygons_, CGAL::parameters::visitor(visitor))) {
      if (pinched != SIZE_MAX) // orienting appends copies of such vertices, so the index still names the original
        fail("the surface is not a manifold: faces meet only at the vertex " + format(points_[pinched]) +
             "; separate the bodies that touch there");
      fail("the surface cannot be oriented consistently (it is one-sided, like a Klein bottle)");
    }
    if (reversed > 0)
      notes_.push_back(plural(reversed, "face") + " were oriented against their neighbours; reversed them");
  }

  void checkSelfIntersections(const Mesh& mesh) const {
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
    PMP::self_intersections(mesh, std::back_inserter(pairs));
    if (pairs.empty()) return;
    const auto triangle = [&](Mesh::Face_index f) {
      const Mesh::Halfedge_index h = mesh.halfedge(f);
      return Kernel::Triangle_3(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                mesh.point(mesh.target(mesh.next(h))));
    };
    // Degenerate faces made by triangulation come first, as pairs (f, f).
    if (pairs.front().first == pairs.front().second)
      fail("triangulating its polygons made degenerate faces, e.g. at " + format(triangle(pairs.front().first)[0]) +
           "; triangulate the surface with a mesh tool instead");
    const Kernel::Triangle_3 a = triangle(pairs.front().first), b = triangle(pairs.front().second);
    Point where = CGAL::centroid(a);
    if (const auto common = CGAL::intersection(a, b)) {
      if (const Point* p = boost::get<Point>(&*common))
        where = *p;
      else if (const auto* s = boost::get<Kernel::Segment_3>(&*common))
        where = CGAL::midpoint(s->source(), s->target());
      else if (const auto* t = boost::get<Kernel::Triangle_3>(&*common))
        where = CGAL::centroid(*t);
      else if (const auto* polygon = boost::get<std::vector<Point>>(&*common))
        where = polygon->front();
    }
    fail("the surface intersects itself: " + plural(pairs.size(), "pair") + " of faces intersect, e.g. at " +
         format(where) + "; remove the overlap (e.g. a boolean union of the bodies) so that the inside is clear");
  }

  void checkVolume(const Mesh& mesh) const {
    const double volume = PMP::volume(mesh);
    const CGAL::Bbox_3 box = PMP::bbox(mesh);
    const double diagonal = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) +
                                      std::pow(box.zmax() - box.zmin(), 2));
    // Relative to the cube on the diagonal: the round-off of the volume sum, not a size judgement.
    if (!(std::abs(volume) > 1e-12 * diagonal * diagonal * diagonal)) {
      std::ostringstream msg;
      msg << "the surface encloses no volume (" << volume << " m^3 inside a bounding box of diagonal " << diagonal
          << " m); a closed surface must bound a body";
      fail(msg.str());
    }
  }

  /// Orients every component so that the surface bounds its volume with faces pointing out; returns how many
  /// faces that reversed (orient_to_bound_a_volume keeps the face indices and reverses their corner order).
  static std::size_t orientOutward(Mesh& mesh) {
    std::vector<std::pair<Mesh::Vertex_index, Mesh::Vertex_index>> firstEdge;
    for (const Mesh::Face_index f : mesh.faces())
      firstEdge.emplace_back(mesh.source(mesh.halfedge(f)), mesh.target(mesh.halfedge(f)));
    PMP::orient_to_bound_a_volume(mesh);
    std::size_t reversed = 0, k = 0;
    for (const Mesh::Face_index f : mesh.faces()) {
      const auto [from, to] = firstEdge[k++];
      for (const Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
        if (mesh.source(h) == from && mesh.target(h) != to) ++reversed;
    }
    return reversed;
  }

  static TriangleMesh toTriangleMesh(const Mesh& mesh) {
    TriangleMesh out;
    out.vertices.reserve(mesh.number_of_vertices());
    for (const Mesh::Vertex_index v : mesh.vertices()) {
      const Point& p = mesh.point(v);
      out.vertices.emplace_back(p.x(), p.y(), p.z());
    }
    out.triangles.reserve(mesh.number_of_faces());
    for (const Mesh::Face_index f : mesh.faces()) {
      const Mesh::Halfedge_index h = mesh.halfedge(f);
      out.triangles.push_back({static_cast<std::size_t>(mesh.source(h)), static_cast<std::size_t>(mesh.target(h)),
                               static_cast<std::size_t>(mesh.target(mesh.next(h)))});
    }
    return out;
  }

  std::string path_;
  std::vector<Point> points_;
  std::vector<Polygon> polygons_;
  std::vector<std::string> notes_;
};

} // namespace

SurfaceFile SurfaceFile::read(const std::string& path, bool repair) { return SurfaceReader(path).read(repair); }

} // namespace poro
