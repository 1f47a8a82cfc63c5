#pragma once
/// Implicit fluid viscosity and optional wall viscosity — Böttcher et al. 2025, Eq. (18) (METHOD.md §6.5.3):
///   F_a(u) = sum_b kappa_ab (u_ab . x_ab) gradW_ab,  kappa_ab = 10 mu Vbar_ab / (|x_ab|^2 + 0.01 H^2),
///   Vbar_ab = (m_a/rho_a)(m_b/rho_b) over fluid neighbours; a wall particle k is a partner of known velocity
///   v_k with Vbar_ak = (m_a/rho_a)^2 V_k/V and mu = mu_b (its v_k part goes to the right-hand side).
/// Implicit in v^{n+1}; pair forces are equal and opposite (momentum-conserving).
/// Keys: constant/fluidProperties viscosity, boundaryViscosity [Pa s], >= 0, default 0.

#include "physics/ImplicitTerm.hpp"

namespace poro {

class FluidViscosity final : public ImplicitTerm {
public:
  const char* name() const override { return "fluidViscosity"; }
  bool enabled(const StepContext& ctx) const override;
  void prepare(const StepContext& ctx) override;
  void addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const override;
  void addDiagonal(const linalg::BlockDiagonal& d) const override;
  void addRhs(const linalg::BlockVector& b) const override;

private:
  const StepContext* ctx_ = nullptr;
  std::size_t fluidSet_ = 0;                         ///< index of the fluid set in the particle system
  std::size_t fluidPart_ = 0;                        ///< its part in the block vectors
  std::vector<double> pairCoefficient_;              ///< kappa_ab s_ab per fluid pair (gradW = s x)
  std::vector<std::vector<double>> wallCoefficient_; ///< kappa_ak s_ak per wall pair, per boundary set
};

} // namespace poro
