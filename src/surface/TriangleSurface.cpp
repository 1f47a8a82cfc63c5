#include "surface/TriangleSurface.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <unordered_map>

namespace poro {

const TriangleSurface::Field* TriangleSurface::field(const std::string& name) const {
  for (const Field& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

double TriangleSurface::area() const {
  double sum = 0.0;
  for (const auto& t : triangles)
    sum += 0.5 * (points[static_cast<std::size_t>(t[1])] - points[static_cast<std::size_t>(t[0])])
                     .cross(points[static_cast<std::size_t>(t[2])] - points[static_cast<std::size_t>(t[0])])
                     .norm();
  return sum;
}

double TriangleSurface::enclosedVolume() const {
  double sum = 0.0;
  for (const auto& t : triangles)
    sum += points[static_cast<std::size_t>(t[0])].dot(
        points[static_cast<std::size_t>(t[1])].cross(points[static_cast<std::size_t>(t[2])]));
  return sum / 6.0;
}

TriangleSurface::Defects TriangleSurface::defects() const {
  // Per undirected edge: how often it is used a -> b (a < b) and b -> a.
  struct Uses {
    std::size_t forward = 0, backward = 0;
  };
  std::unordered_map<std::uint64_t, Uses> edges;
  edges.reserve(triangles.size() * 2);
  for (const auto& t : triangles)
    for (int e = 0; e < 3; ++e) {
      const auto a = static_cast<std::uint32_t>(t[static_cast<std::size_t>(e)]);
      const auto b = static_cast<std::uint32_t>(t[static_cast<std::size_t>((e + 1) % 3)]);
      Uses& uses = edges[(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
      (a < b ? uses.forward : uses.backward) += 1;
    }
  Defects d;
  for (const auto& [key, uses] : edges) {
    const std::size_t n = uses.forward + uses.backward;
    if (n == 1) ++d.openEdges;
    else if (n > 2) ++d.nonManifoldEdges;
    else if (uses.forward != 1) ++d.misorientedEdges;
  }
  return d;
}

void TriangleSurface::flip() {
  for (auto& t : triangles) std::swap(t[1], t[2]);
}

} // namespace poro
