#pragma once
/// Implicit porous drag between fluid and porous solids — Böttcher et al. 2025, Eq. (16) (METHOD.md §6.5.5):
///   K_it = 10 mu_por,t (m_i / rho^mix_it)(m_t / rho_t) / (|x_it|^2 + 0.01 H^2),
///   F_i += K_it (u_it . x_it) gradW_it,   F_t -= the same,
///   rho^mix_it = rho^_i max(phi^loc_i, max(0.05 phi_t, 0.01))  (METHOD.md §6.4); rho_t the current density of
///   t, or rho_b with the compatibility switch couplingSolidDensity: rest (METHOD.md §10).
/// One coefficient per pair, evaluated by the same expression from both sides, so the pair forces are
/// equal and opposite to the last bit. Implicit in both velocities; no wall drag.
/// Keys: constant/porosityProperties <material>.dragViscosity [Pa s], >= 0, default 0.

#include "physics/ImplicitTerm.hpp"

namespace poro {

class PorousDrag final : public ImplicitTerm {
public:
  const char* name() const override { return "porousDrag"; }
  bool enabled(const StepContext& ctx) const override;
  void prepare(const StepContext& ctx) override;
  void addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const override;
  void addDiagonal(const linalg::BlockDiagonal& d) const override;
  void addRhs(const linalg::BlockVector&) const override {}

  /// The drag coefficient K_it of one pair (exposed for tests).
  static double coefficient(double mu, double massI, double rhoMix, double massT, double rhoT, double distance2,
                            double regulariser);

private:
  /// One side of the fluid-solid coupling: the list from set `self` (block part `part`) to set `other`.
  struct Side {
    std::size_t self, part, other, otherPart;
    std::vector<PairFactor> pairCoefficient; ///< K s per pair (gradW = s x)
  };
  const StepContext* ctx_ = nullptr;
  std::vector<Side> sides_;
};

} // namespace poro
