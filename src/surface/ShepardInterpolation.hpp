#pragma once
/// Particle fields read off at arbitrary points (a surface's vertices, a cut plane): the Shepard average
/// f(x) = sum_j V_j W(x - x_j) f_j / sum_j V_j W(x - x_j) over the particles within the kernel's support, which
/// reproduces a uniform field exactly and is bounded by the particles' values.

#include "surface/ColourField.hpp"

namespace poro {

class ShepardInterpolation {
public:
  /// Sorts `cloud`'s finite particles into cells of the support radius (the cloud must outlive this object).
  ShepardInterpolation(const ParticleCloud& cloud, double supportRadius);

  /// field(x) at every point, values[point components + c]; 0 where no particle reaches. Parallel, each point
  /// summing its particles in a fixed order.
  std::vector<double> at(const std::vector<Vec3>& points, const ParticleField& field) const;

private:
  const ParticleCloud& cloud_;
  double h_;
  Vec3 origin_ = Vec3::Zero();
  std::array<std::int64_t, 3> dims_{0, 0, 0};
  std::vector<std::size_t> start_, order_; ///< particles by cell (counting sort), start_[cell] .. start_[cell + 1]
};

} // namespace poro
