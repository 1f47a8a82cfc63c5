#pragma once
/// Corotated linear elasticity of porous solids with bloating and saturation softening — Peer et al. 2017 and
/// Böttcher et al. 2025, Eq. (19)-(21) (METHOD.md §6.5.2, §6.5.4), for materials with youngsModulus > 0:
///   rotation R_s of F_s = sum_{t in N0(s)} V0_t (x_t - x_s) (x) L_s gradW(X_s - X_t) (Müller et al. 2016),
///   g_st = R_s L_s gradW(X_s - X_t),
///   velocity part (matrix): grad u_s = dt sum V0_t (u_t - u_s) (x) g_st, eps = sym(grad u),
///   position part (rhs):    F^_s = I + sum V0_t ((x_t - x_s) - R_s (X_t - X_s)) (x) g_st, eps = sym(F^) - I,
///   P_s = 2 k_mu mu eps + k_lambda lambda tr(eps) I [- eta_bloat S I on the rhs only],
///   k_mu = max(1 + eta_m S, 1e-3), k_lambda = max(1 + eta_l S, 1e-3),
///   F_s = sum_t V0_s V0_t (P_s R_s L_s + P_t R_t L_t) gradW(X_s - X_t).
/// The velocity part is the Hessian of sum_s V0_s eps_s:C_s:eps_s / 2, so it is symmetric positive
/// semi-definite; elastic links never span two objects. Compatibility switches (METHOD.md §10):
/// volumetricStress unitLambda drops lambda from the volumetric term, bloatingStress lambdaScaled multiplies
/// eta_bloat by lambda. Optional zero-energy-mode control (not in the paper): HourglassControl.hpp.
/// Keys: constant/porosityProperties <material>.{youngsModulus, poissonsRatio, bloating, shearSoftening,
/// volumeSoftening, hourglassControl}.

#include "physics/ElasticRestState.hpp"
#include "physics/HourglassControl.hpp"
#include "physics/ImplicitTerm.hpp"

#include <vector>

namespace poro {

class Elasticity final : public ImplicitTerm {
public:
  const char* name() const override { return "elasticity"; }
  bool enabled(const StepContext& ctx) const override;
  void prepare(const StepContext& ctx) override;
  void addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const override;
  void addDiagonal(const linalg::BlockDiagonal& d) const override;
  void addRhs(const linalg::BlockVector& b) const override;

  /// Registers the rotation field (restart state: the warm start of the rotation extraction).
  static void registerFields(ParticleSet& set);
  /// The rest state of set `s` (valid after prepare), for tests.
  const ElasticRestState& restState(std::size_t s) const { return rest_[s]; }
  /// The strain of the position part at x^n of particle i of set s (valid after prepare), for tests.
  Mat3 strain(std::size_t s, std::size_t i) const;

private:
  /// One elastic porous set and its per-step coefficients.
  struct Body {
    std::size_t set = 0, part = 0;
    /// k_mu mu and k_lambda lambda (or k_lambda with unitLambda) [Pa] of particle s, formed from its saturation
    /// where they are read: the saturation does not change within a step, and two arrays fewer are kept.
    double mu = 0.0, volumetricModulus = 0.0, shearSoftening = 0.0, volumeSoftening = 0.0;
    const double* saturation = nullptr;
    double shear(std::size_t s) const;
    double volumetric(std::size_t s) const;
    bool uniformModuli = true; ///< no saturation softening: every particle has the material's moduli
    /// V0_s P_s R_s L_s: of the position part (with bloating) after prepare(), read by addRhs(); then of the
    /// velocity part, formed by every addApply(). One array for both: the right-hand side is formed before the CG
    /// applies the operator, and each holds 72 bytes per particle. (R_s L_s itself is formed where it is used, 27
    /// products per particle, not kept.)
    mutable std::vector<Mat3> stress;
    mutable bool stressOfPositions = false; ///< `stress` still holds the position part's
    /// The particles whose stresses the own particles' forces read: in a parallel run the own ones and the ghosts
    /// among their rest neighbours, not the ghosts lent only to complete those ghosts' sums; empty: all.
    std::vector<Index> stressed;
    template <class F> void forEachStressed(std::size_t n, const F& f) const;
    HourglassControl hourglass; ///< off unless the material sets hourglassControl
  };
  /// restRebuilt: the rest state was built anew for this step (a reorder, a removal, the first step).
  void prepareBody(const StepContext& ctx, Body& body, bool restRebuilt);
  /// F_s = V0_s sum_t V0_t (M_s + M_t) gradW(X_s - X_t) for a per-particle field M = P R L, given the volume-weighted
  /// field V0 M: the neighbours' volumes ride with their stresses instead of being read per pair.
  Vec3 force(const Body& body, const std::vector<Mat3>& weighted, std::size_t s) const;

  const StepContext* ctx_ = nullptr;
  std::vector<ElasticRestState> rest_; ///< by set index; kept across steps, rebuilt when a set is reordered
  std::vector<Body> bodies_;
};

} // namespace poro
