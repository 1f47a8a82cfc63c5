#pragma once
/// The strongly coupled implicit non-pressure solve in momentum form (METHOD.md §6.5; Eq. 9, 10, 22):
/// A = M - dt dF/du assembled from the registered terms, never as a matrix; block-Jacobi preconditioned
/// CG warm-started from v^n + dv; then gravity v* = u + dt g (§6.5.9).
/// Keys: system/solverDict implicit.{tolerance, maxIterations, preconditioner}.

#include "linalg/ConjugateGradient.hpp"
#include "physics/ImplicitTerm.hpp"
#include "physics/SolverSettings.hpp"

#include <memory>
#include <vector>

namespace poro {

class ImplicitSolver {
public:
  /// Terms in the explicit registration order of the Solver.
  ImplicitSolver(const ImplicitSettings& settings, std::vector<std::unique_ptr<ImplicitTerm>> terms);

  /// Registers dv (restart) and the Krylov scratch fields.
  static void registerFields(ParticleSet& set);
  /// The scratch field that holds the right-hand side, then the residual, during a solve only.
  static constexpr const char* rightHandSideField = "cgRhs";
  /// The scratch field that holds the preconditioned residual and the product A p, during a solve only.
  static constexpr const char* productField = "cgQ";

  /// Replaces v^n by v* for every dynamic set. Returns the CG statistics (0 iterations if no term is on).
  /// With collectWallReactions, also keeps the forces the terms exert on wall particles (wallReactions()).
  linalg::CgResult solve(const StepContext& ctx);
  void collectWallReactions(bool on) { collectWallReactions_ = on; }
  /// By boundary set (in ctx.boundarySets order), by particle: the force the last solve's terms exert on it [N];
  /// empty when not collected or no term was on.
  const std::vector<std::vector<Vec3>>& wallReactions() const { return wallReactions_; }

  /// The operator u -> A u of the current step (after solve or prepare), for tests.
  void prepare(const StepContext& ctx);
  void apply(const linalg::BlockVector& u, const linalg::BlockVector& au) const;
  void diagonal(const linalg::BlockDiagonal& d) const;
  void rhs(const linalg::BlockVector& b) const;
  /// A block vector view over the named Vec3 field of every dynamic set.
  static linalg::BlockVector view(const StepContext& ctx, const char* fieldName);

private:
  class Operator;
  /// Fills inverseDiagonal_ with the inverses of diagonal()'s blocks.
  void formPreconditioner(const StepContext& ctx);
  ImplicitSettings settings_;
  std::vector<std::unique_ptr<ImplicitTerm>> terms_;
  std::vector<ImplicitTerm*> enabled_;
  const StepContext* ctx_ = nullptr;
  bool collectWallReactions_ = false;
  std::vector<std::vector<Vec3>> wallReactions_;
  /// The preconditioner's blocks by dynamic set: scratch of solve(), formed anew every step, so not a particle field
  /// (nothing to sort or send with the particles).
  std::vector<std::vector<linalg::SymmetricBlock>> inverseDiagonal_;
  /// The window of diagonal blocks formPreconditioner() fills, kept between steps: allocated in each step, its
  /// 0.6 MB per dynamic set were mapped, page-faulted in and unmapped again every step.
  std::vector<Mat3> diagonalWindow_;
};

} // namespace poro
