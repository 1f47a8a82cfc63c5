#pragma once
/// Implicit viscosity in the pair form of Böttcher et al. 2025, Eq. (18) (METHOD.md §6.5.3):
///   F_a(u) = sum_b kappa_ab (u_ab . x_ab) gradW_ab,  kappa_ab = 10 mu Vbar_ab / (|x_ab|^2 + 0.01 H^2),
///   Vbar_ab = (m_a/rho_a)(m_b/rho_b); a wall particle k is a partner of known velocity v_k with
///   Vbar_ak = (m_a/rho_a)^2 V_k/V (its v_k part goes to the right-hand side).
/// Applied to
///   - the fluid: mu = viscosity over all fluid neighbours, mu_b = boundaryViscosity at walls;
///   - each porous material (solid damping, not in the paper; needed by two published setups, §12.2):
///     mu = dampingViscosity between particles of one object, mu_b = boundaryDampingViscosity at walls.
/// Implicit in v^{n+1}; pair forces are equal and opposite (momentum-conserving), rigid motion is not damped.
/// Keys: constant/fluidProperties viscosity, boundaryViscosity; constant/porosityProperties
/// <material>.dampingViscosity, boundaryDampingViscosity [Pa s], >= 0, default 0.

#include "physics/ImplicitTerm.hpp"

namespace poro {

class Viscosity final : public ImplicitTerm {
public:
  const char* name() const override { return "viscosity"; }
  bool enabled(const StepContext& ctx) const override;
  void prepare(const StepContext& ctx) override;
  void addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const override;
  void addDiagonal(const linalg::BlockDiagonal& d) const override;
  void addRhs(const linalg::BlockVector& b) const override;
  /// The wall term's reaction: particle a pulls wall particle k with -kappa_ak s_ak ((u_a - v_k).x_ak) x_ak.
  void addWallReactions(const linalg::BlockVector& u, std::vector<std::vector<Vec3>>& forces) const override;

private:
  /// One viscous set: the fluid, or a porous material with damping.
  struct Member {
    std::size_t set = 0, part = 0;
    std::vector<PairFactor> pairCoefficient;              ///< kappa_ab s_ab per same-set pair (gradW = s x)
    std::vector<std::vector<PairFactor>> wallCoefficient; ///< kappa_ak s_ak per wall pair, per boundary set; none
                                                          ///< without wall viscosity (mu_b = 0)
  };
  /// Viscosity inside the set and at walls of `member` (pairs of different objects get 0 if `byObject`).
  void prepareMember(const StepContext& ctx, Member& member, double mu, double muWall, bool byObject);

  const StepContext* ctx_ = nullptr;
  std::vector<Member> members_;
};

} // namespace poro
