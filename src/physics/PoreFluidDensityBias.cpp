#include "physics/PoreFluidDensityBias.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

namespace {
/// Table points; b is piecewise smooth in the share, linear interpolation errs below 1e-5 between them.
constexpr std::size_t kTableSize = 2048;
} // namespace

double PoreFluidDensityBias::latticeSum(const CubicKernel& kernel, double volume, double spacing) {
  const int n = static_cast<int>(kernel.supportRadius() / spacing) + 1;
  double sum = 0.0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int l = -n; l <= n; ++l) sum += kernel.w(spacing * std::sqrt(static_cast<double>(i * i + j * j + l * l)));
  return volume * sum;
}

PoreFluidDensityBias::PoreFluidDensityBias(const CubicKernel& kernel, double volume) : table_(kTableSize) {
  // b(phi) = S(2r phi^(-1/3)) - phi S(2r): relative to the dense lattice's own sum, so b(1) = 0 exactly.
  const double dense = latticeSum(kernel, volume, std::cbrt(volume));
  for (std::size_t k = 0; k < kTableSize; ++k) {
    const double share = kMinShare + (1.0 - kMinShare) * static_cast<double>(k) / (kTableSize - 1);
    table_[k] = latticeSum(kernel, volume, std::cbrt(volume / share)) - share * dense;
  }
  table_.back() = 0.0;
}

double PoreFluidDensityBias::operator()(double poreShare) const {
  if (poreShare >= 1.0) return 0.0;
  const double at = (std::max(poreShare, kMinShare) - kMinShare) / (1.0 - kMinShare) * (kTableSize - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(at), kTableSize - 2);
  const double t = at - static_cast<double>(k);
  return (1.0 - t) * table_[k] + t * table_[k + 1];
}

double PoreFluidDensityBias::uncorrectedFill(double porosity) const {
  if (porosity >= 1.0) return 1.0;
  // s + b(s) rises with s (the lattice sum rises with the density), so bisect; b may be negative (phi > 0.7).
  const auto excess = [&](double share) { return share + (*this)(share) - porosity; };
  if (porosity <= kMinShare || excess(kMinShare) >= 0.0) return 0.0;
  double lo = kMinShare, hi = 1.0;
  for (int it = 0; it < 50; ++it) (excess(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  return lo / porosity;
}

} // namespace poro
