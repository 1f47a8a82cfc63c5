#pragma once
/// A triangle mesh with per-point fields: what fluidSurface writes and renderCase draws. VTK-free, so that tests
/// and other libraries can measure it.

#include "core/Types.hpp"

#include <array>
#include <string>
#include <vector>

namespace poro {

class TriangleSurface {
public:
  struct Field {
    std::string name;
    int components = 1;
    std::vector<double> values; ///< values[point components + c]
  };
  /// Edges that make a mesh not a closed, consistently oriented 2-manifold.
  struct Defects {
    std::size_t openEdges = 0;        ///< used by one triangle only
    std::size_t nonManifoldEdges = 0; ///< used by more than two triangles
    std::size_t misorientedEdges = 0; ///< used twice in the same direction (neighbours facing opposite ways)
    bool none() const { return openEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0; }
  };

  std::vector<Vec3> points;
  std::vector<std::array<Index, 3>> triangles;
  std::vector<Field> fields;

  bool empty() const { return triangles.empty(); }
  /// The field of that name, or nullptr.
  const Field* field(const std::string& name) const;

  double area() const;
  /// Signed volume enclosed (divergence theorem): positive when the triangles face outward (counter-clockwise
  /// seen from outside). Exact for a closed mesh.
  double enclosedVolume() const;
  Defects defects() const;
  /// Reverses every triangle (turns inward faces outward).
  void flip();
};

} // namespace poro
