#include "geometry/SurfaceTransform.hpp"

#include <Eigen/Geometry>

namespace poro {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

void SurfaceTransform::applyTo(TriangleMesh& mesh) const {
  const Mat3 rotation = Eigen::AngleAxisd(rotationDegrees * kPi / 180.0, rotationAxis.normalized()).toRotationMatrix();
  for (Vec3& x : mesh.vertices) x = rotation * scale.cwiseProduct(x) + translation;
}

} // namespace poro
