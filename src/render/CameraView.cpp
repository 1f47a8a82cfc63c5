#include "render/CameraView.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace poro {

CameraView CameraView::framing(const Vec3& lo, const Vec3& hi, const Vec3& gravity, double viewAngle,
                               double aspect, double reservedRight) {
  const double degree = M_PI / 180.0;
  const Vec3 up = gravity.norm() > 0.0 ? Vec3(-gravity.normalized()) : Vec3(Vec3::UnitY());
  // The horizontal coordinate axis along which the box is thinnest faces the camera.
  const Vec3 extent = hi - lo;
  Vec3 front = Vec3::Zero();
  double thinnest = HUGE_VAL;
  for (int a = 2; a >= 0; --a) {
    Vec3 axis = Vec3::Zero();
    axis[a] = 1.0;
    const Vec3 horizontal = axis - axis.dot(up) * up;
    if (horizontal.norm() < 0.5) continue; // (nearly) vertical
    if (extent[a] < thinnest) thinnest = extent[a], front = horizontal.normalized();
  }
  const Vec3 side = up.cross(front).normalized();
  const double turn = 30.0 * degree, rise = 25.0 * degree;
  const Vec3 towardsCamera =
      std::cos(rise) * (std::cos(turn) * front + std::sin(turn) * side) + std::sin(rise) * up;
  CameraView view;
  view.focalPoint = 0.5 * (lo + hi);
  view.viewUp = up;
  view.viewAngle = viewAngle;
  // Each corner must lie within the view's half-angles (shrunk by the margin): with the camera at distance d along
  // towardsCamera, a corner at (right, up, towards) offsets from the focal point appears at
  // |right| / (d - towards) <= tan(horizontal half-angle), likewise upward.
  // The box is fitted into the width left of the reserved strip, then the camera pans right by half the strip so
  // the box is centred in what is left.
  const double margin = 0.85;
  const double tanV = margin * std::tan(0.5 * viewAngle * degree), tanH = aspect * tanV * (1.0 - reservedRight);
  const Vec3 right = up.cross(towardsCamera).normalized(), upward = towardsCamera.cross(right);
  double distance = 1e-6;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z());
    const Vec3 offset = p - view.focalPoint;
    const double towards = offset.dot(towardsCamera);
    distance = std::max({distance, towards + std::abs(offset.dot(right)) / tanH,
                         towards + std::abs(offset.dot(upward)) / tanV});
  }
  view.position = view.focalPoint + towardsCamera * distance;
  const Vec3 pan = right * (reservedRight * aspect * std::tan(0.5 * viewAngle * degree) * distance);
  view.position += pan;
  view.focalPoint += pan;
  return view;
}

} // namespace poro
