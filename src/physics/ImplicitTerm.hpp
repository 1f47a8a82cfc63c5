#pragma once
/// One velocity-implicit force term of the momentum system (METHOD.md §6.5.1, Eq. 22):
///   (A u)_a = m_a u_a - dt F_a(u),   b_a = m_a v^n_a + dt F^x_a.
/// A term adds -dt F(u) to A u, its 3x3 diagonal blocks to the preconditioner, and dt F^x to b.
/// Block vector part p belongs to the particle set ctx.dynamicSets[p].

#include "linalg/BlockVector.hpp"
#include "physics/StepContext.hpp"

namespace poro {

class ImplicitTerm {
public:
  virtual ~ImplicitTerm() = default;
  /// Name for logs (the physics, e.g. "fluidViscosity").
  virtual const char* name() const = 0;
  /// False when the term's coefficients are all zero: it is then skipped entirely.
  virtual bool enabled(const StepContext& ctx) const = 0;
  /// Computes the per-step coefficients from x^n, rho, ... (called once per step, before the solve).
  virtual void prepare(const StepContext& ctx) = 0;
  /// au += -dt F(u).
  virtual void addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const = 0;
  /// d[p].data[k] += the term's diagonal block of A for particle d[p].first + k of part p, k < d[p].size (the solve
  /// forms the diagonal a window of particles at a time).
  virtual void addDiagonal(const linalg::BlockDiagonal& d) const = 0;
  /// b += dt F^x (position and known-velocity parts). Called after prepare() and before the step's first addApply():
  /// a term may reuse its arrays between the two (Elasticity's stresses).
  virtual void addRhs(const linalg::BlockVector& b) const = 0;
  /// forces[w][k] += the force the term's particles exert on particle k of the boundary set ctx.boundarySets[w]
  /// at the solution u: the reaction of the term's wall part (rigid bodies take it). Terms without walls add none.
  virtual void addWallReactions(const linalg::BlockVector& /*u*/, std::vector<std::vector<Vec3>>& /*forces*/) const {}
};

} // namespace poro
