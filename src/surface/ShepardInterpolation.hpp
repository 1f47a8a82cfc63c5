#pragma once
/// Particle fields read off at arbitrary points (a surface's vertices, a cut plane): the Shepard average
/// f(x) = sum_j V_j W(x - x_j) f_j / sum_j V_j W(x - x_j) over the particles within the kernel's support, which
/// reproduces a uniform field exactly and is bounded by the particles' values.

#include "surface/ColourField.hpp"

namespace poro {

/// Cell grids larger than this many cells (8 bytes each) are refused.
inline constexpr double kMaxShepardCells = 5.0e7;

class ShepardInterpolation {
public:
  /// Sorts `cloud`'s finite particles into cells of the support radius (the cloud must outlive this object). More
  /// than kMaxShepardCells cells over the particles' extent is an InputError starting with `where` (the surfaceDict
  /// the support radius comes from).
  ShepardInterpolation(const ParticleCloud& cloud, double supportRadius,
                       const std::string& where = "ShepardInterpolation");

  /// field(x) at every point, values[point components + c]; 0 where no particle reaches. Parallel, each point
  /// summing its particles in a fixed order. Fields of 1 to 3 components with one value set per particle;
  /// anything else is a programming error (std::invalid_argument), not silently truncated.
  std::vector<double> at(const std::vector<Vec3>& points, const ParticleField& field) const;

private:
  const ParticleCloud& cloud_;
  double h_;
  Vec3 origin_ = Vec3::Zero();
  std::array<std::int64_t, 3> dims_{0, 0, 0};
  std::vector<std::size_t> start_, order_; ///< particles by cell (counting sort), start_[cell] .. start_[cell + 1]
};

} // namespace poro
