#pragma once
/// The cubic spline's over-estimate of sparse fluid (option `pressure.poreFluidDensity: latticeCorrected` of
/// system/solverDict; not in the paper). Fluid that shares space with a porous solid of pore share phi rests
/// at phi/V particles per volume, spacing 2r phi^(-1/3). At that spacing the kernel sum sum_j V W_ij (self
/// included) on a simple cubic lattice exceeds phi: by 0.046 at phi = 0.4 (11 %), 0.008 at 0.6, and by
/// 1/pi - phi once the spacing exceeds H, because the self term V W(0) = 1/pi does not thin out with the
/// fluid. Eq. 4 with the constraint rho~ <= 1 therefore holds pore fluid ~10 % too sparse at phi = 0.4.
/// The correction subtracts that excess b(phi) from the fluid's rho~, phi being the share of the volume the
/// solids leave open: 1 - sum_t (1 - phi_t) V W_it (walls excluded, so fluid away from porous solids is
/// unchanged: b(1) = 0 exactly).

#include "sph/Kernel.hpp"

#include <vector>

namespace poro {

class PoreFluidDensityBias {
public:
  /// Tabulates b over pore shares [kMinShare, 1] for the kernel and the particle volume V = (2r)^3.
  PoreFluidDensityBias(const CubicKernel& kernel, double volume);
  /// b(poreShare); shares outside [kMinShare, 1] are clamped into it.
  double operator()(double poreShare) const;
  /// The share of its pores that fluid fills at rest without the correction (Eq. 4 as it stands), on the lattice:
  /// s / phi with s + b(s) = phi, where the fluid's own kernel sum equals the pore share. 0 when even a lone
  /// particle's self term exceeds it (phi below about 1/pi); slightly above 1 for phi > 0.75, where b < 0.
  double uncorrectedFill(double porosity) const;
  /// sum_n V W(spacing n) over the simple cubic lattice points n (self included).
  static double latticeSum(const CubicKernel& kernel, double volume, double spacing);

  static constexpr double kMinShare = 0.01;

private:
  std::vector<double> table_; ///< b at kMinShare + k (1 - kMinShare) / (size - 1)
};

} // namespace poro
