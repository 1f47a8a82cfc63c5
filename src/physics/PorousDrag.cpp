#include "physics/PorousDrag.hpp"

#include "core/Parallel.hpp"

namespace poro {

namespace {
constexpr double kDragFactor = 10.0; // 2(d + 2) for d = 3

/// The work before particle a of a loop over `list` (its pairs, plus a), for parallel::forEachBalanced.
auto pairsBefore(const NeighbourList& list) {
  return [&list](std::size_t a) { return a + list.offset(a); };
}
} // namespace

double PorousDrag::coefficient(double mu, double massI, double rhoMix, double massT, double rhoT, double distance2,
                               double regulariser) {
  return pairFactor(kDragFactor * mu * massI * massT, rhoMix * rhoT, distance2, regulariser, 1.0);
}

template <bool FluidSide, class T, class Term>
T PorousDrag::sumOverPairsAs(const Side& side, const NeighbourList& list, const std::vector<PairFactor>& factors,
                             const std::vector<Vec3>& xa, const std::vector<Vec3>& xb, std::size_t a, T sum,
                             const Term& term) {
  // x_ab and its square flip exactly with the side, and the densities' product commutes: both sides of a pair
  // form the same K s.
  const double selfDensity = FluidSide ? side.rhoMix(a) : side.rhoSolid(a);
  std::size_t q = list.offset(a);
  for (Index bIndex : list.of(a)) {
    const std::size_t b = static_cast<std::size_t>(bIndex);
    const Vec3 xab = xa[a] - xb[b];
    const double otherDensity = FluidSide ? side.rhoSolid(b) : side.rhoMix(b);
    term(sum, b, xab,
         pairFactor(side.numerator, selfDensity * otherDensity, xab.squaredNorm(), side.regulariser, factors[q++]));
  }
  return sum;
}

template <class T, class Term>
T PorousDrag::sumOverPairs(const Side& side, const NeighbourList& list, const std::vector<PairFactor>& factors,
                           const std::vector<Vec3>& xa, const std::vector<Vec3>& xb, std::size_t a, T sum,
                           const Term& term) {
  return side.fluidSide ? sumOverPairsAs<true>(side, list, factors, xa, xb, a, sum, term)
                        : sumOverPairsAs<false>(side, list, factors, xa, xb, a, sum, term);
}

bool PorousDrag::enabled(const StepContext& ctx) const {
  bool fluid = false, drag = false;
  for (std::size_t a : ctx.dynamicSets) {
    fluid = fluid || ctx.particles[a].kind() == SetKind::Fluid;
    drag = drag || (ctx.materials[a] && ctx.materials[a]->dragViscosity > 0.0);
  }
  return fluid && drag;
}

void PorousDrag::prepare(const StepContext& ctx) {
  ctx_ = &ctx;
  sides_.clear();
  std::size_t fluidPart = 0;
  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p)
    if (ctx.particles[ctx.dynamicSets[p]].kind() == SetKind::Fluid) fluidPart = p;
  const std::size_t fluidSet = ctx.dynamicSets[fluidPart];
  const ParticleSet& fluid = ctx.particles[fluidSet];
  const double h = ctx.kernel.supportRadius();
  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p) {
    const std::size_t t = ctx.dynamicSets[p];
    const PorousMaterial* material = ctx.materials[t];
    if (!material || material->dragViscosity == 0.0) continue;
    // K_it with i always the fluid particle, whichever side evaluates it; rho_t^n, or rho_b with
    // couplingSolidDensity: rest (METHOD.md §10).
    const double numerator = kDragFactor * material->dragViscosity * fluid.mass * ctx.particles[t].mass;
    const MixtureDensity rhoMix(fluid, *material);
    const CouplingSolidDensity rhoSolid(ctx, t);
    sides_.push_back({fluidSet, fluidPart, t, p, true, rhoMix, rhoSolid, numerator, 0.01 * h * h});
    sides_.push_back({t, p, fluidSet, fluidPart, false, rhoMix, rhoSolid, numerator, 0.01 * h * h});
  }
}

void PorousDrag::addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const {
  // (A u)_a -= dt F_a with F_a = sum_b K s (u_ab . x_ab) x_ab from either side (x_ab and u_ab flip together).
  const double dt = ctx_->dt;
  for (const Side& side : sides_) {
    const NeighbourList& list = ctx_->search.list(side.self, side.other);
    const auto& xa = ctx_->particles[side.self].x();
    const auto& xb = ctx_->particles[side.other].x();
    const Vec3* ua = u[side.part].data;
    const Vec3* ub = u[side.otherPart].data;
    Vec3* out = au[side.part].data;
    const auto& factors = ctx_->gradients.of(side.self, side.other);
    parallel::forEachBalanced(u[side.part].size, pairsBefore(list), [&](std::size_t a) {
      const Vec3 force = sumOverPairs(
          side, list, factors, xa, xb, a, Vec3(Vec3::Zero()),
          [&](Vec3& sum, std::size_t b, const Vec3& xab, double ks) { sum += (ks * (ua[a] - ub[b]).dot(xab)) * xab; });
      out[a] -= dt * force;
    });
  }
}

void PorousDrag::addDiagonal(const linalg::BlockDiagonal& d) const {
  const double dt = ctx_->dt;
  for (const Side& side : sides_) {
    const NeighbourList& list = ctx_->search.list(side.self, side.other);
    const auto& xa = ctx_->particles[side.self].x();
    const auto& xb = ctx_->particles[side.other].x();
    if (d[side.part].size == 0) continue; // a window past this set's end: `first` may be past its lists too
    Mat3* out = d[side.part].data;
    const std::size_t first = d[side.part].first;
    const auto work = [&](std::size_t k) { return pairsBefore(list)(first + k) - pairsBefore(list)(first); };
    const auto& factors = ctx_->gradients.of(side.self, side.other);
    parallel::forEachBalanced(d[side.part].size, work, [&](std::size_t k) {
      const Mat3 block =
          sumOverPairs(side, list, factors, xa, xb, first + k, Mat3(Mat3::Zero()),
                       [](Mat3& sum, std::size_t, const Vec3& xab, double ks) { addOuter(sum, ks * xab, xab); });
      out[k] -= dt * block;
    });
  }
}

} // namespace poro
