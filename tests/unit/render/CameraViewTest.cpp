// The default camera: gravity down the picture, the box in view, the thin side of a slab facing the camera.

#include "render/CameraView.hpp"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace poro {
namespace {

/// Where x lands in normalised picture coordinates (-1..1 across each axis) for the camera.
Eigen::Vector2d project(const CameraView& view, double aspect, const Vec3& x) {
  const Vec3 back = (view.position - view.focalPoint).normalized();
  const Vec3 right = view.viewUp.cross(back).normalized(), up = back.cross(right);
  const Vec3 d = x - view.position;
  const double depth = -d.dot(back), t = std::tan(0.5 * view.viewAngle * M_PI / 180.0);
  return {d.dot(right) / (depth * t * aspect), d.dot(up) / (depth * t)};
}

TEST(CameraView, FramesTheBoxWithGravityDown) {
  const Vec3 lo(0.0, 0.0, 0.0), hi(1.6, 0.6, 0.1); // a dam break's slab, gravity along -y
  const CameraView view = CameraView::framing(lo, hi, Vec3(0, -9.81, 0), 30.0, 16.0 / 9.0);
  EXPECT_TRUE(view.viewUp.isApprox(Vec3::UnitY()));
  EXPECT_TRUE(view.focalPoint.isApprox(0.5 * (lo + hi)));
  const Vec3 towards = (view.position - view.focalPoint).normalized();
  EXPECT_GT(towards.z(), 0.7); // across the thin z extent: the slab is seen side on
  EXPECT_GT(towards.y(), 0.3); // from above
  double widest = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z());
    const Eigen::Vector2d at = project(view, 16.0 / 9.0, p);
    EXPECT_LE(std::abs(at.x()), 0.86) << corner;
    EXPECT_LE(std::abs(at.y()), 0.86) << corner;
    widest = std::max({widest, std::abs(at.x()), std::abs(at.y())});
  }
  EXPECT_GT(widest, 0.8); // no farther than needed
}

TEST(CameraView, KeepsTheLegendsStripFree) {
  const Vec3 lo(-0.1, 0.0, 0.0), hi(1.0, 0.1, 0.1); // a long beam, whose near end would reach the legend
  const double aspect = 16.0 / 9.0, reserved = 0.15;
  const CameraView view = CameraView::framing(lo, hi, Vec3(0, -9.81, 0), 30.0, aspect, reserved);
  double left = 1.0, right = -1.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z());
    const Eigen::Vector2d at = project(view, aspect, p);
    left = std::min(left, at.x()), right = std::max(right, at.x());
    EXPECT_LE(std::abs(at.y()), 0.86) << corner;
  }
  // The strip is the rightmost 15 % of the width: x > 1 - 2 * 0.15 in picture coordinates.
  EXPECT_LE(right, 1.0 - 2.0 * reserved);
  EXPECT_GE(left, -1.0);
  // No farther than needed: the widest corner (the near end) fills what is left, -1 .. 1 - 2 * 0.15, up to the
  // 0.85 margin: centre -0.15 + half-width 0.85 * 0.85 = 0.57, less what the pan, exact in the focal plane only,
  // moves the near end further (a few hundredths here).
  EXPECT_GT(right, 0.85 * (1.0 - reserved) - reserved - 0.05);
}

TEST(CameraView, GravityAlongZPutsZUp) {
  const CameraView view = CameraView::framing(Vec3::Zero(), Vec3::Ones(), Vec3(0, 0, -9.81), 30.0, 1.0);
  EXPECT_TRUE(view.viewUp.isApprox(Vec3::UnitZ()));
  EXPECT_GT((view.position - view.focalPoint).z(), 0.0);
}

} // namespace
} // namespace poro
