#pragma once
/// Implicit capillary adhesion between fluid and porous solids — Böttcher et al. 2025, Eq. (11)-(15)
/// (METHOD.md §6.5.6):
///   c_it = C^cap,0_t (1 - eta_cap,t S_t) (m_i + m_t)/(rho^mix_it + rho_t) W_it   (Eq. 13; mbar/rhobar of Eq. 11),
///   F_i = -c_it x_it^{n+1},   F_t = +c_it x_it^{n+1}   (Eq. 11, 14),   x^{n+1} = x^n + dt u   (Eq. 15):
///   matrix part F_i -= dt c_it u_it, F_t += dt c_it u_it; right-hand side F^x_i -= c_it x_it^n, F^x_t += the same.
/// rho^mix_it and rho_t as in physics/CouplingDensity.hpp (METHOD.md §6.4, §10), S_t the saturation (Eq. 12).
/// One coefficient per pair, evaluated by the same expression from both sides, so the pair forces are equal
/// and opposite to the last bit; c_it >= 0, so the matrix part is symmetric positive semi-definite.
/// Implicit in both velocities; no wall adhesion.
/// Keys: constant/porosityProperties <material>.capillaryStrength (C^cap,0) [N/m], >= 0, default 0;
///       <material>.capillaryFalloff (eta_cap) [-], in [0, 1], default 0.

#include "physics/ImplicitTerm.hpp"

namespace poro {

class CapillaryAdhesion final : public ImplicitTerm {
public:
  const char* name() const override { return "capillaryAdhesion"; }
  bool enabled(const StepContext& ctx) const override;
  void prepare(const StepContext& ctx) override;
  void addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const override;
  void addDiagonal(const linalg::BlockDiagonal& d) const override;
  void addRhs(const linalg::BlockVector& b) const override;

  /// The adhesion coefficient c_it of one pair [N/m] (exposed for tests).
  /// @param strength C^cap,0 [N/m]; falloff eta_cap; saturation S_t; w = W_it [1/m^3].
  static double coefficient(double strength, double falloff, double saturation, double massI, double rhoMix,
                            double massT, double rhoT, double w);

private:
  /// One side of the fluid-solid coupling: the list from set `self` (block part `part`) to set `other`.
  struct Side {
    std::size_t self, part, other, otherPart;
    std::vector<PairFactor> pairCoefficient; ///< c_ab per pair, in list order
  };
  const StepContext* ctx_ = nullptr;
  std::vector<Side> sides_;
};

} // namespace poro
