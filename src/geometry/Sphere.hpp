#pragma once
/// A sphere for the lattice samplers (particleDict `shape: sphere`), answered analytically: crossings of a row
/// from the quadratic |p - centre| = radius, distances as | |p - centre| - radius |.

#include "geometry/ClosedShape.hpp"

namespace poro {

class Sphere final : public ClosedShape {
public:
  /// `radius` [m] > 0.
  Sphere(const Vec3& centre, double radius);

  const Vec3& centre() const { return centre_; }
  double radius() const { return radius_; }

  Vec3 boxMin() const override;
  Vec3 boxMax() const override;
  double volume() const override;
  double area() const override;
  void crossRow(double y, double z, double tolerance, RowCrossings& row) const override;
  double distance(const Vec3& p) const override;

private:
  Vec3 centre_;
  double radius_;
};

} // namespace poro
