#include "physics/ImplicitSolver.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/VolumeFactors.hpp"

#include <Eigen/LU>

#include <algorithm>

namespace poro {

namespace {
// Three Krylov vectors besides the unknown: the right-hand side turns into the residual r in place, and the
// preconditioned residual z and the product q = A p take turns in one field (linalg::CgWork). The unknown u is
// solved for in the velocity field itself, v^n kept meanwhile in dv's (solve()).
const char* const kRhs = ImplicitSolver::rightHandSideField; ///< b, then r
const char* const kUnknown = field::v;
const char* const kP = "cgP";
const char* const kQ = ImplicitSolver::productField; ///< z and q

/// Rows of Fixed particles hold their known velocity: (A u)_a = m u_a, b_a = m v^n_a, D_a = m I. Their
/// residual and search directions then stay zero, which equals moving them to the right-hand side
/// (METHOD.md §6.5.8); the terms' couplings of Active rows to them remain.
/// row(k, m) for the Fixed particles first + k, k < size, of a part.
template <class Row>
void overwriteFixedRows(const StepContext& ctx, std::size_t part, std::size_t first, std::size_t size, const Row& row) {
  const ParticleSet& set = ctx.particles[ctx.dynamicSets[part]];
  const std::int64_t* fixed = fixedFlags(set);
  if (!fixed) return;
  parallel::forEach(size, [&](std::size_t k) {
    if (fixed[first + k]) row(k, set.mass);
  });
}

/// Particles per window of the preconditioner's assembly: 0.6 MB of Mat3 blocks per dynamic set.
constexpr std::size_t kDiagonalWindow = 8192;
} // namespace

class ImplicitSolver::Operator final : public linalg::BlockOperator {
public:
  explicit Operator(const ImplicitSolver& solver) : solver_(solver) {}
  void apply(const linalg::BlockVector& x, const linalg::BlockVector& y) const override {
    solver_.ctx_->refreshGhosts({kUnknown, kP}); // CG applies the operator to these two only; the terms read neighbours
    solver_.apply(x, y);
  }

private:
  const ImplicitSolver& solver_;
};

ImplicitSolver::ImplicitSolver(const ImplicitSettings& settings, std::vector<std::unique_ptr<ImplicitTerm>> terms)
    : settings_(settings), terms_(std::move(terms)) {}

void ImplicitSolver::registerFields(ParticleSet& set) {
  set.addVec3(field::deltaV, Restart);
  for (const char* name : {kRhs, kP, kQ}) set.addVec3(name);
}

linalg::BlockVector ImplicitSolver::view(const StepContext& ctx, const char* fieldName) {
  linalg::BlockVector v;
  for (std::size_t a : ctx.dynamicSets) { // this rank's rows; the ghosts' entries follow in the storage
    auto& f = ctx.particles[a].vec3(fieldName);
    v.push_back({f.data(), ctx.owned(a)});
  }
  return v;
}

void ImplicitSolver::prepare(const StepContext& ctx) {
  ctx_ = &ctx;
  enabled_.clear();
  for (auto& term : terms_)
    if (term->enabled(ctx)) {
      term->prepare(ctx);
      enabled_.push_back(term.get());
    }
}

void ImplicitSolver::apply(const linalg::BlockVector& u, const linalg::BlockVector& au) const {
  for (std::size_t p = 0; p < u.size(); ++p) {
    const double m = ctx_->particles[ctx_->dynamicSets[p]].mass;
    const Vec3* in = u[p].data;
    Vec3* out = au[p].data;
    parallel::forEach(u[p].size, [&](std::size_t i) { out[i] = m * in[i]; });
  }
  for (const ImplicitTerm* term : enabled_) term->addApply(u, au);
  for (std::size_t p = 0; p < u.size(); ++p)
    overwriteFixedRows(*ctx_, p, 0, u[p].size, [&](std::size_t i, double m) { au[p].data[i] = m * u[p].data[i]; });
}

void ImplicitSolver::diagonal(const linalg::BlockDiagonal& d) const {
  for (std::size_t p = 0; p < d.size(); ++p) {
    const double m = ctx_->particles[ctx_->dynamicSets[p]].mass;
    Mat3* out = d[p].data;
    parallel::forEach(d[p].size, [&](std::size_t i) { out[i] = m * Mat3::Identity(); });
  }
  for (const ImplicitTerm* term : enabled_) term->addDiagonal(d);
  for (std::size_t p = 0; p < d.size(); ++p)
    overwriteFixedRows(*ctx_, p, d[p].first, d[p].size,
                       [&](std::size_t k, double m) { d[p].data[k] = m * Mat3::Identity(); });
}

void ImplicitSolver::rhs(const linalg::BlockVector& b) const {
  for (std::size_t p = 0; p < b.size(); ++p) {
    const ParticleSet& set = ctx_->particles[ctx_->dynamicSets[p]];
    const double m = set.mass;
    const auto& v = set.v();
    Vec3* out = b[p].data;
    parallel::forEach(b[p].size, [&](std::size_t i) { out[i] = m * v[i]; });
  }
  for (const ImplicitTerm* term : enabled_) term->addRhs(b);
  for (std::size_t p = 0; p < b.size(); ++p) {
    const auto& v = ctx_->particles[ctx_->dynamicSets[p]].v();
    overwriteFixedRows(*ctx_, p, 0, b[p].size, [&](std::size_t i, double m) { b[p].data[i] = m * v[i]; });
  }
}

void ImplicitSolver::formPreconditioner(const StepContext& ctx) {
  // The diagonal blocks a window of particles at a time: a Mat3 for every particle would be the largest array of the
  // solve. Each block is inverted in double and kept in single precision, symmetric.
  const std::size_t parts = ctx.dynamicSets.size();
  inverseDiagonal_.resize(parts);
  std::size_t largest = 0;
  for (std::size_t p = 0; p < parts; ++p) {
    inverseDiagonal_[p].resize(ctx.owned(ctx.dynamicSets[p]));
    largest = std::max(largest, inverseDiagonal_[p].size());
  }
  const std::size_t width = std::min(kDiagonalWindow, largest);
  diagonalWindow_.resize(parts * width);
  Mat3* blocks = diagonalWindow_.data();
  for (std::size_t first = 0; first < largest; first += width) {
    linalg::BlockDiagonal window;
    for (std::size_t p = 0; p < parts; ++p) {
      const std::size_t size = inverseDiagonal_[p].size();
      window.push_back({blocks + p * width, first < size ? std::min(width, size - first) : 0, first});
    }
    diagonal(window);
    for (std::size_t p = 0; p < parts; ++p) {
      const linalg::Mat3Span& part = window[p];
      if (part.size == 0) continue; // past this set's end
      linalg::SymmetricBlock* inverse = inverseDiagonal_[p].data() + first;
      parallel::forEach(part.size,
                        [&](std::size_t k) { inverse[k] = linalg::SymmetricBlock(Mat3(part.data[k].inverse())); });
    }
  }
}

linalg::CgResult ImplicitSolver::solve(const StepContext& ctx) {
  prepare(ctx);
  wallReactions_.clear();
  const Vec3 gdt = ctx.dt * ctx.fluid.gravity;
  linalg::CgResult result;
  result.converged = true;
  if (enabled_.empty()) {
    for (std::size_t a : ctx.dynamicSets) {
      ParticleSet& set = ctx.particles[a];
      auto& v = set.v();
      auto& dv = set.vec3(field::deltaV);
      const std::int64_t* fixed = fixedFlags(set);
      parallel::forEach(set.size(), [&](std::size_t i) {
        dv[i].setZero();
        if (!(fixed && fixed[i])) v[i] += gdt;
      });
    }
    return result;
  }

  const linalg::BlockVector b = view(ctx, kRhs), u = view(ctx, kUnknown);
  rhs(b);
  // Initial guess v^n + dv (METHOD.md §6.5.8); compatibility implicitInitialGuess deltaTDeltaV: v^n + dt dv. The
  // guess goes into v, v^n into dv until the solve is done: no array of its own for u (24 bytes per particle).
  const double guessScale = ctx.compatibility.deltaTScaledInitialGuess ? ctx.dt : 1.0;
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    auto& v = set.v();
    auto& dv = set.vec3(field::deltaV);
    parallel::forEach(set.size(), [&](std::size_t i) {
      const Vec3 guess = v[i] + guessScale * dv[i];
      dv[i] = v[i];
      v[i] = guess;
    });
  }
  linalg::BlockPreconditioner inverse;
  if (settings_.preconditioner) {
    formPreconditioner(ctx);
    for (const auto& blocks : inverseDiagonal_) inverse.push_back({blocks.data(), blocks.size()});
  }
  const linalg::CgWork work{b, view(ctx, kQ), view(ctx, kP), view(ctx, kQ)};
  linalg::CgSettings cg{settings_.tolerance, settings_.maxIterations, {}};
  if (ctx.ghosts) cg.sumOverRanks = [&ctx](double local) { return ctx.sumOverRanks(local); };
  result = linalg::solveCg(Operator(*this), inverse, b, u, work, cg);
  if (collectWallReactions_) {
    for (std::size_t k : ctx.boundarySets) wallReactions_.emplace_back(ctx.particles[k].size(), Vec3::Zero());
    for (const ImplicitTerm* term : enabled_) term->addWallReactions(u, wallReactions_);
  }

  for (std::size_t a : ctx.dynamicSets) { // v* = u + dt g, dv = u - v^n; Fixed: v* = v^n (METHOD.md §6.5.9)
    ParticleSet& set = ctx.particles[a];
    auto& v = set.v(); // u
    auto& dv = set.vec3(field::deltaV); // v^n
    const std::int64_t* fixed = fixedFlags(set);
    parallel::forEach(set.size(), [&](std::size_t i) {
      if (fixed && fixed[i]) {
        v[i] = dv[i];
        dv[i].setZero();
        return;
      }
      const Vec3 solution = v[i];
      v[i] = solution + gdt;
      dv[i] = solution - dv[i];
    });
  }
  return result;
}

} // namespace poro
