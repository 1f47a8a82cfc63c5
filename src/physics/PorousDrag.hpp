#pragma once
/// Implicit porous drag between fluid and porous solids — Böttcher et al. 2025, Eq. (16) (METHOD.md §6.5.5):
///   K_it = 10 mu_por,t (m_i / rho^mix_it)(m_t / rho_t) / (|x_it|^2 + 0.01 H^2),
///   F_i += K_it (u_it . x_it) gradW_it,   F_t -= the same,
///   rho^mix_it = rho^_i max(phi^loc_i, max(0.05 phi_t, 0.01))  (METHOD.md §6.4); rho_t the current density of
///   t, or rho_b with the compatibility switch couplingSolidDensity: rest (METHOD.md §10).
/// One coefficient per pair, evaluated by the same expression from both sides, so the pair forces are
/// equal and opposite to the last bit. Implicit in both velocities; no wall drag.
/// K_it s_it is formed where it is used, from the stored kernel gradient factor s_it and the particles' densities,
/// not kept per pair: the fluid-solid lists grow as the fluid soaks in, and the two sides' coefficients took 8 bytes
/// per pair (40 bytes per particle of the published Seep once its block is full); a division per pair is the cost.
/// Keys: constant/porosityProperties <material>.dragViscosity [Pa s], >= 0, default 0.

#include "physics/CouplingDensity.hpp"
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
  /// K_it s_it from the numerator 10 mu_por m_i m_t, the densities' product rho^mix_it rho_t, |x_it|^2 and the
  /// gradient factor s_it: the one expression both sides of a pair evaluate.
  static double pairFactor(double numerator, double densities, double distance2, double regulariser, double s) {
    return numerator * s / (densities * (distance2 + regulariser));
  }

private:
  /// One side of the fluid-solid coupling: the list from set `self` (block part `part`) to set `other`.
  struct Side {
    std::size_t self, part, other, otherPart;
    bool fluidSide;                ///< `self` is the fluid
    MixtureDensity rhoMix;         ///< rho^mix of the fluid particle
    CouplingSolidDensity rhoSolid; ///< rho_t of the solid particle
    double numerator;              ///< 10 mu_por,t m_i m_t
    double regulariser;            ///< 0.01 H^2
  };
  /// Accumulates term(sum, b, x_ab, K s) over the pairs (a, b) of one side into `sum`, in list order.
  template <class T, class Term>
  static T sumOverPairs(const Side& side, const NeighbourList& list, const std::vector<PairFactor>& factors,
                        const std::vector<Vec3>& xa, const std::vector<Vec3>& xb, std::size_t a, T sum,
                        const Term& term);
  /// The same with the side's kind known at compile time: no branch in the pair loop.
  template <bool FluidSide, class T, class Term>
  static T sumOverPairsAs(const Side& side, const NeighbourList& list, const std::vector<PairFactor>& factors,
                          const std::vector<Vec3>& xa, const std::vector<Vec3>& xb, std::size_t a, T sum,
                          const Term& term);
  const StepContext* ctx_ = nullptr;
  std::vector<Side> sides_;
};

} // namespace poro
