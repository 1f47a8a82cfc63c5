#pragma once
/// Where a surface of constant/triSurface goes (particleDict keys scale, rotate, translate):
///   x' = R (s * x) + t,
/// applied in the order scale, rotate, translate: the file's origin is the centre of scaling and rotation and
/// lands at t. Scale factors are positive, so the transform keeps the orientation of the faces (no mirroring).

#include "core/Types.hpp"
#include "geometry/TriangleMesh.hpp"

namespace poro {

struct SurfaceTransform {
  Vec3 scale = Vec3::Ones();         ///< per axis, > 0
  Vec3 rotationAxis = Vec3::UnitZ(); ///< any length > 0
  double rotationDegrees = 0.0;      ///< right-handed about rotationAxis [degrees]
  Vec3 translation = Vec3::Zero();   ///< [m]

  /// Moves every vertex of `mesh`.
  void applyTo(TriangleMesh& mesh) const;
};

} // namespace poro
