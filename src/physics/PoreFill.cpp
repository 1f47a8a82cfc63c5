#include "physics/PoreFill.hpp"

#include "physics/FieldNames.hpp"
#include "sph/ParticleSet.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

namespace {

/// Table points over [0, H]; Wbar is smooth (W convolved with a ball), linear interpolation errs below 1e-6.
constexpr std::size_t kTableSize = 1024;
/// Radial quadrature points per table entry (Simpson's rule, even).
constexpr int kRadialPoints = 2000;

/// Area of the sphere of radius rho about the origin that lies inside the ball of radius a about a point at
/// distance d from the origin.
double areaInsideBall(double rho, double d, double a) {
  if (rho + d <= a) return 4.0 * M_PI * rho * rho;
  if (rho >= d + a || rho <= d - a) return 0.0;
  return M_PI * rho * (a * a - (rho - d) * (rho - d)) / d; // a spherical cap
}

/// W averaged over the ball of radius a about a point at distance d: the integral of W over the shells of
/// radius rho that cross the ball, divided by the ball's volume.
double ballAverage(const CubicKernel& kernel, double d, double a) {
  const double lo = std::max(0.0, d - a), hi = std::min(kernel.supportRadius(), d + a);
  if (hi <= lo) return 0.0;
  const double h = (hi - lo) / kRadialPoints;
  double sum = 0.0;
  for (int k = 0; k <= kRadialPoints; ++k) {
    const double rho = lo + h * k;
    const double weight = (k == 0 || k == kRadialPoints) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += weight * kernel.w(rho) * areaInsideBall(rho, d, a);
  }
  return sum * h / 3.0 / (4.0 / 3.0 * M_PI * a * a * a);
}

} // namespace

PoreFill::PoreFill(const CubicKernel& kernel, double volume)
    : step_(kernel.supportRadius() / (kTableSize - 1)), table_(kTableSize) {
  const double a = std::cbrt(3.0 * volume / (4.0 * M_PI)); // the ball of volume V
  for (std::size_t k = 0; k < kTableSize; ++k) table_[k] = volume * ballAverage(kernel, step_ * k, a);
  table_.back() = 0.0;

  // Scale so that the dense lattice, spacing 2r = V^(1/3), sums to exactly 1 within H.
  const double spacing = std::cbrt(volume);
  const int n = static_cast<int>(kernel.supportRadius() / spacing) + 1;
  double lattice = 0.0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int l = -n; l <= n; ++l)
        lattice += volumeWeight(spacing * std::sqrt(static_cast<double>(i * i + j * j + l * l)));
  for (double& v : table_) v /= lattice;
}

double PoreFill::volumeWeight(double dist) const {
  const double at = dist / step_;
  if (at >= static_cast<double>(kTableSize - 1)) return 0.0;
  const std::size_t k = static_cast<std::size_t>(at);
  const double t = at - static_cast<double>(k);
  return (1.0 - t) * table_[k] + t * table_[k + 1];
}

double PoreFill::poreVolume(double porosity, bool compressible, double coverage, double restCoverage) {
  if (!compressible || restCoverage < 0.0) return porosity * coverage;
  return std::max(restCoverage - (1.0 - porosity) * coverage, 0.0);
}

void PoreFill::registerFields(ParticleSet& set, const PorousMaterial& material) {
  set.addReal(field::poreFill);
  if (material.compressible)
    set.addReal(field::restCoverage, Restart); // zero (unset) where new: set at the particle's first step
  else
    set.drop(field::restCoverage); // read with porous.vtp, which holds every material's fields
}

double PoreFill::fade(double fill) { return std::clamp((kFadeStart + kFadeWidth - fill) / kFadeWidth, 0.0, 1.0); }

} // namespace poro
