#pragma once
/// Where renderCase's camera stands when system/renderDict does not say.

#include "core/Types.hpp"

namespace poro {

struct CameraView {
  Vec3 position, focalPoint, viewUp;
  double viewAngle = 30.0; ///< vertical [degrees]

  /// Looks at the box [lo, hi] (what moves: fluid and porous bodies) with gravity pointing down the picture: from
  /// the front, across the box's thinnest horizontal extent (a dam break's slab is seen side on), turned 30 degrees
  /// to the side and raised 25 degrees, just far enough that the box's corners fit into the picture (of
  /// width / height `aspect`) with a margin, left of a strip of `reservedRight` of the picture's width kept free for
  /// colour legends.
  static CameraView framing(const Vec3& lo, const Vec3& hi, const Vec3& gravity, double viewAngle, double aspect,
                            double reservedRight = 0.0);
};

} // namespace poro
