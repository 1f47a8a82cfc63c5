#pragma once
/// A triangle surface as plain arrays: what SurfaceFile reads, SurfaceTransform places and SurfaceMesh samples.

#include "core/Types.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace poro {

struct TriangleMesh {
  std::vector<Vec3> vertices;                        ///< [m]
  std::vector<std::array<std::size_t, 3>> triangles; ///< vertex indices, counter-clockwise seen from outside
};

} // namespace poro
