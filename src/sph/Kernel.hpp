#pragma once
/// Cubic spline kernel (Monaghan) with support radius H = 4r, evaluated analytically (METHOD.md §2.1).

#include "core/Types.hpp"

#include <cmath>

namespace poro {

class CubicKernel {
public:
  /// @param supportRadius H [m] (= 4 r).
  explicit CubicKernel(double supportRadius)
      : h_(supportRadius), invH_(1.0 / supportRadius), kW_(8.0 / (M_PI * h_ * h_ * h_)),
        kGrad_(48.0 / (M_PI * h_ * h_ * h_)) {}

  double supportRadius() const { return h_; }
  /// W(0) = 8/(pi H^3) = 1/(8 pi r^3).
  double w0() const { return kW_; }

  /// W at distance `dist` [1/m^3].
  double w(double dist) const {
    const double q = dist * invH_;
    if (q > 1.0) return 0.0;
    return q <= 0.5 ? innerW(kW_, q) : shellW(kW_, q);
  }
  double w(const Vec3& x) const { return w(x.norm()); }

  /// Gradient of W with respect to the first particle's position for x = x_a - x_b [1/m^4].
  Vec3 grad(const Vec3& x) const { return gradFactor(x.norm()) * x; }

  /// Scalar s(dist) with grad(x) = s(||x||) x, so pair loops can store one number per pair.
  double gradFactor(double dist) const {
    const double q = dist * invH_;
    if (dist <= 1e-9 || q > 1.0) return 0.0;
    return kGrad_ * gradPiece(q) * invH_ / dist;
  }

  /// The distances and W of n pairs given by their offsets x_a - x_b in components: the numbers w() gives, bit
  /// for bit, from a loop without branches (both pieces formed, one kept) that the compiler vectorises, since one
  /// square root per pair bounds the scalar loops. gradientFactors() then gives s from the distances, in a loop of
  /// its own: in one loop GCC 12 does not if-convert the selects.
  void values(std::size_t n, const double* dx, const double* dy, const double* dz, double* dist, double* w) const {
    const double invH = invH_, kW = kW_; // locals: the stores below cannot change them
    for (std::size_t k = 0; k < n; ++k) {
      const double d = std::sqrt(dx[k] * dx[k] + dy[k] * dy[k] + dz[k] * dz[k]);
      const double q = d * invH;
      const double inner = innerW(kW, q), shell = shellW(kW, q);
      const double kept = q <= 0.5 ? inner : shell;
      w[k] = q > 1.0 ? 0.0 : kept;
      dist[k] = d;
    }
  }

  /// s of n pairs from their distances: the numbers gradFactor() gives, bit for bit, vectorised (one division per
  /// pair).
  template <class Factor> void gradientFactors(std::size_t n, const double* dist, Factor* s) const {
    const double invH = invH_, kGrad = kGrad_;
    for (std::size_t k = 0; k < n; ++k) {
      const double d = dist[k];
      const double q = d * invH;
      const double factor = kGrad * gradPiece(q) * invH / d;
      s[k] = static_cast<Factor>(d <= 1e-9 || q > 1.0 ? 0.0 : factor);
    }
  }

private:
  // The spline's pieces for q = dist / H, shared by the scalar and the batch evaluations so they agree bit for bit.
  static double innerW(double kW, double q) { return kW * (6.0 * q * q * q - 6.0 * q * q + 1.0); } // q <= 1/2
  static double shellW(double kW, double q) {                                                      // 1/2 < q <= 1
    const double s = 1.0 - q;
    return 2.0 * kW * s * s * s;
  }
  /// dW/dq over the gradient's constant, on both pieces.
  static double gradPiece(double q) { return q <= 0.5 ? q * (3.0 * q - 2.0) : -(1.0 - q) * (1.0 - q); }

  double h_, invH_, kW_, kGrad_;
};

} // namespace poro
