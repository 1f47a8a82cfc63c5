#include "geometry/Sphere.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Sphere::Sphere(const Vec3& centre, double radius) : centre_(centre), radius_(radius) {}

Vec3 Sphere::boxMin() const { return centre_ - Vec3::Constant(radius_); }
Vec3 Sphere::boxMax() const { return centre_ + Vec3::Constant(radius_); }
double Sphere::volume() const { return 4.0 / 3.0 * kPi * radius_ * radius_ * radius_; }
double Sphere::area() const { return 4.0 * kPi * radius_ * radius_; }

void Sphere::crossRow(double y, double z, double tolerance, RowCrossings& row) const {
  const double dy = y - centre_.y(), dz = z - centre_.z();
  const double offAxis2 = dy * dy + dz * dz; // squared distance of the row from the centre
  const double x0 = centre_.x();
  if (offAxis2 < radius_ * radius_) {
    const double half = std::sqrt(radius_ * radius_ - offAxis2);
    row.crossings.push_back(x0 - half);
    row.crossings.push_back(x0 + half);
  }
  // Points whose distance from the centre lies in [radius - 2 tolerance, radius + 2 tolerance] (twice the
  // tolerance: a margin for the round-off of these square roots).
  const double outer = radius_ + 2.0 * tolerance, inner = std::max(0.0, radius_ - 2.0 * tolerance);
  if (offAxis2 > outer * outer) return;
  const double outerHalf = std::sqrt(outer * outer - offAxis2);
  const double innerHalf = offAxis2 < inner * inner ? std::sqrt(inner * inner - offAxis2) : 0.0;
  row.nearSurface.emplace_back(x0 - outerHalf, x0 - innerHalf);
  row.nearSurface.emplace_back(x0 + innerHalf, x0 + outerHalf);
}

double Sphere::distance(const Vec3& p) const { return std::abs((p - centre_).norm() - radius_); }

} // namespace poro
