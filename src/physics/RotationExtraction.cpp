#include "physics/RotationExtraction.hpp"

#include <Eigen/Geometry>

namespace poro {

namespace {
constexpr int kMaxIterations = 10;
constexpr double kStop = 1e-9;
constexpr double kDenominatorOffset = 1e-9;
} // namespace

Mat3 extractRotation(const Mat3& f, const Mat3& previous) {
  Eigen::Quaterniond q{Eigen::Matrix3d(previous)};
  q.normalize();
  for (int k = 0; k < kMaxIterations; ++k) {
    const Eigen::Matrix3d r = q.toRotationMatrix();
    Vec3 numerator = Vec3::Zero();
    double denominator = 0.0;
    for (int c = 0; c < 3; ++c) {
      numerator += Vec3(r.col(c)).cross(Vec3(f.col(c)));
      denominator += r.col(c).dot(f.col(c));
    }
    const Vec3 omega = numerator / (std::abs(denominator) + kDenominatorOffset);
    const double angle = omega.norm();
    if (angle < kStop) break;
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * q;
    q.normalize();
  }
  return Mat3(q.toRotationMatrix());
}

} // namespace poro
