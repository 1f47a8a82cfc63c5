#include "physics/RotationExtraction.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace poro {

namespace {
constexpr int kMaxIterations = 10;
constexpr double kStop = 1e-9;
constexpr double kDenominatorOffset = 1e-9;
/// Newton steps longer than this are left to the plain step: far from the maximum the quadratic model of
/// tr(R^T F) over rotations is poor, and the plain step is the robust one (inverted and degenerate F).
constexpr double kLargestNewtonAngle = 0.5; // [rad]
} // namespace

Mat3 extractRotation(const Mat3& f, const Mat3& previous) {
  // Müller et al. 2016 maximise tr(R^T F) over R <- exp(omega) R. With M = F R^T, the gradient of that trace is
  // g = sum_c R_c x F_c (the axial vector of M - M^T) and its Hessian is -(tr(M) I - sym(M)). Müller's step
  // omega = g / |tr M| stands in tr(M) I for that matrix, so near the maximum it contracts the error only by
  // about s_max/tr(S) (1/3 for F near a rotation): with a warm start 1e-4 rad off, the 10 iterations ran out
  // before |omega| < 1e-9 in most calls. The Newton step H^-1 g has the same fixed point and converges
  // quadratically; it is taken wherever H is positive definite (near every maximum) and the step is short.
  Eigen::Quaterniond q{Eigen::Matrix3d(previous)};
  q.normalize();
  for (int k = 0; k < kMaxIterations; ++k) {
    const Mat3 m = f * q.toRotationMatrix().transpose();
    const Vec3 g(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
    const double trace = m.trace();
    Vec3 omega = g / (std::abs(trace) + kDenominatorOffset);
    if (omega.norm() < kStop) break;
    const Mat3 hessian = trace * Mat3::Identity() - 0.5 * (m + m.transpose());
    const Eigen::LLT<Mat3> llt(hessian);
    if (llt.info() == Eigen::Success) {
      const Vec3 newton = llt.solve(g);
      if (newton.allFinite() && newton.norm() < kLargestNewtonAngle) omega = newton;
    }
    const double angle = omega.norm();
    q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega / angle)) * q;
    q.normalize();
  }
  return Mat3(q.toRotationMatrix());
}

} // namespace poro
