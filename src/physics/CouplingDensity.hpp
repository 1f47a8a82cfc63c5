#pragma once
/// The densities shared by the fluid-solid coupling terms, drag (Eq. 16) and capillary adhesion (Eq. 11),
/// so both see one consistent pair of densities (METHOD.md §11):
///   rho^mix_it = rho^_i max(phi^loc_i, phi^min_t),   phi^min_t = max(0.05 phi_t, 0.01)   (METHOD.md §6.4),
///   rho_t      = the current density of t (couplingSolidDensity: current, the paper's rho_t^n), or the
///                material's bulk density rho_b (couplingSolidDensity: rest)               (METHOD.md §10).
/// Keys: system/solverDict compatibility.couplingSolidDensity (current | rest, default current).

#include "physics/StepContext.hpp"

#include <algorithm>

namespace poro {

/// phi^min_t: keeps the coupling coefficients within 20x of their in-pore value and positive (METHOD.md §6.4).
double couplingPorosityFloor(double porosity);

/// The whole-volume fluid density rho^mix_it [kg/m^3] of fluid particles next to one porous material.
class MixtureDensity {
public:
  /// @param fluid the fluid set (fields `density` = rho^, `localPorosity` = phi^loc).
  MixtureDensity(const ParticleSet& fluid, const PorousMaterial& material);
  /// rho^mix_it for fluid particle i.
  double operator()(std::size_t i) const { return density_[i] * std::max(localPorosity_[i], floor_); }

private:
  const double* density_;
  const double* localPorosity_;
  double floor_;
};

/// The solid density rho_t [kg/m^3] the coupling terms use for the particles of one porous set.
class CouplingSolidDensity {
public:
  /// @param solidSet a porous set of ctx with a material.
  CouplingSolidDensity(const StepContext& ctx, std::size_t solidSet);
  /// rho_t for porous particle t.
  double operator()(std::size_t t) const { return current_ ? current_[t] : rest_; }

private:
  const double* current_ = nullptr; ///< the `density` field, or null for `rest`
  double rest_ = 0.0;               ///< rho_b
};

} // namespace poro
