#pragma once
/// Zero-energy-mode (hourglass) control of an elastic porous body, in the form of Ganzenmüller 2015 and
/// Kugelstadt et al. 2021: the corrected deformation gradient F_s of METHOD.md §6.5.2 does not see displacements
/// that alternate from particle to particle, so Eq. 19 lets them grow unresisted (measured in the published Seep at
/// r = 1 cm: neighbouring columns of the block 8 mm apart in height at 8 s). The control adds the energy
///   E = 1/2 sum_s sum_{t in N0(s)} w_st |F_s X_st - x_st|^2,   w_st = c V0_s V0_t k_st,
/// X_st = X_t - X_s, x_st = x_t - x_s, c = hourglassControl * mu [Pa], k_st = -W'(|X_st|)/|X_st| (the weight of
/// SPH's Laplacian, formed from the stored rest gradient: gradW(X_s - X_t) . X_st / |X_st|^2). The error vector is
/// what s's own affine estimate misses at t: zero for every affine x (rigid motions included), because the
/// corrected gradients reproduce linear fields exactly. F_s is linear in x, so E is quadratic and its force is
/// exactly linear, f = -K x with K symmetric positive semi-definite: the velocity part dt^2 K u goes into the
/// implicit system's matrix, the position part -dt K x^n onto its right-hand side, and no rotation is involved.
/// Key: constant/porosityProperties <material>.hourglassControl (>= 0, default 0: off, Eq. 19 as published).

#include "core/Types.hpp"
#include "physics/ElasticRestState.hpp"

#include <vector>

namespace poro {

class HourglassControl {
public:
  /// Takes the body's rest state for this step. `size` counts its particles with any ghosts; `stressed` lists the
  /// particles whose sums the own particles read (Elasticity's; empty: all). stiffness = c [Pa]; 0 switches off.
  /// K depends on the rest state alone, so its diagonal is formed again only when that was rebuilt.
  void prepare(const ElasticRestState& rest, const std::vector<Vec3>& restX, double stiffness, std::size_t size,
               const std::vector<Index>& stressed, bool restRebuilt);
  bool enabled() const { return stiffness_ > 0.0; }
  /// F_s of a field y for every stressed particle, for addForces(y). Elasticity forms the same sums for its own
  /// gradients and hands them over with setGradient instead (sum_t (y_t - y_s) (x) V0_t gradW0_st, times L_s^T).
  void formGradients(const Vec3* y) const;
  void setGradient(std::size_t s, const Mat3& f) const { gradient_[s] = f; }
  /// out[k] += scale f_k(y) for the own particles k < owned, f = -dE/dy for the field y (positions or velocities),
  /// with the gradients of y formed or set before.
  void addForces(const Vec3* y, std::size_t owned, double scale, Vec3* out) const;
  /// K_kk: the control's diagonal block of K is K_kk I (the coordinates do not couple).
  double diagonal(std::size_t k) const { return diagonal_[k]; }

private:
  /// w_st = c V0_s V0_t k_st for the rest pair `pair` of s (and t).
  double weight(std::size_t s, std::size_t t, std::size_t pair) const {
    return stiffness_ * rest_->volume(s) * rest_->volume(t) * laplacianWeight_[rest_->gradientIndex(pair)];
  }
  template <class F> void forEachStressed(const F& f) const;
  void formDiagonal();

  const ElasticRestState* rest_ = nullptr;
  const std::vector<Vec3>* restX_ = nullptr;
  double stiffness_ = 0.0;
  std::size_t size_ = 0;
  std::vector<Index> stressed_; ///< a copy: empty (all) in a serial run
  /// Per particle, for the field of the last addForces: F_s, P_s = H_s L_s with H_s = sum_t w_st eps_st (x) X_st,
  /// and own_s = sum_t w_st eps_st - P_s sum_t V0_t gradW0_st, which the force gathers.
  mutable std::vector<Mat3> gradient_, moment_;
  mutable std::vector<Vec3> own_;
  std::vector<double> diagonal_;
  /// k_st by stored rest gradient (ElasticRestState::gradientIndex): a lattice body's pairs share a few dozen, so
  /// the passes read them instead of dividing by |X_st|^2 per pair (the division led a profile of the passes).
  std::vector<double> laplacianWeight_;
};

} // namespace poro
