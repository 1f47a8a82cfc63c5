#pragma once
/// Buoyancy on porous solids — Böttcher et al. 2025, Eq. (17) (METHOD.md §6.5.7):
///   F^x_s = -(1 - phi_s) V sum_j m_j pi_j^{n-1} gradW_sj
/// from the fluid pressures of the previous pressure solve (zero in the first step). It is the reaction of
/// the fluid-side solid term of Eq. 7, lagged one step; the fluid gets no buoyancy term. Right-hand side only.

#include "physics/ImplicitTerm.hpp"

namespace poro {

class Buoyancy final : public ImplicitTerm {
public:
  const char* name() const override { return "buoyancy"; }
  bool enabled(const StepContext& ctx) const override;
  void prepare(const StepContext& ctx) override { ctx_ = &ctx; }
  void addApply(const linalg::BlockVector&, const linalg::BlockVector&) const override {}
  void addDiagonal(const linalg::BlockDiagonal&) const override {}
  void addRhs(const linalg::BlockVector& b) const override;

  /// F^x of every particle of porous set `t` into `force` (exposed for tests).
  static void forces(const StepContext& ctx, std::size_t t, std::vector<Vec3>& force);

private:
  /// out[s] += factor F^x_s for every particle s of porous set `t`: the right-hand side takes the forces as they are
  /// formed, with no array of them beside it (2.7 MB of the published Seep at r = 1 cm, held at a step's peak).
  static void addForces(const StepContext& ctx, std::size_t t, double factor, Vec3* out);
  const StepContext* ctx_ = nullptr;
};

} // namespace poro
