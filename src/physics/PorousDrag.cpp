#include "physics/PorousDrag.hpp"

#include "core/Memory.hpp"
#include "core/Parallel.hpp"
#include "physics/CouplingDensity.hpp"

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
  return kDragFactor * mu * (massI / rhoMix) * (massT / rhoT) / (distance2 + regulariser);
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
  std::size_t used = 0; // sides are kept from step to step, their pair arrays refilled in place
  std::size_t fluidPart = 0;
  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p)
    if (ctx.particles[ctx.dynamicSets[p]].kind() == SetKind::Fluid) fluidPart = p;
  const std::size_t fluidSet = ctx.dynamicSets[fluidPart];
  const ParticleSet& fluid = ctx.particles[fluidSet];
  const double h = ctx.kernel.supportRadius();
  const double regulariser = 0.01 * h * h;

  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p) {
    const std::size_t t = ctx.dynamicSets[p];
    const PorousMaterial* material = ctx.materials[t];
    if (!material || material->dragViscosity == 0.0) continue;
    const ParticleSet& solid = ctx.particles[t];
    const double mu = material->dragViscosity;
    const MixtureDensity rhoMix(fluid, *material);
    const CouplingSolidDensity rhoSolid(ctx, t); // rho_t^n, or rho_b with couplingSolidDensity: rest (§10)
    // K_it with i always the fluid particle, whichever side evaluates it.
    auto pairK = [&](std::size_t i, std::size_t s, double distance2) {
      return coefficient(mu, fluid.mass, rhoMix(i), solid.mass, rhoSolid(s), distance2, regulariser);
    };
    for (const bool fluidSide : {true, false}) {
      if (used == sides_.size()) sides_.emplace_back();
      Side& side = sides_[used++];
      side.self = fluidSide ? fluidSet : t;
      side.part = fluidSide ? fluidPart : p;
      side.other = fluidSide ? t : fluidSet;
      side.otherPart = fluidSide ? p : fluidPart;
      const NeighbourList& list = ctx.search.list(side.self, side.other);
      const auto& gradients = ctx.gradients.of(side.self, side.other);
      const auto& xSelf = ctx.particles[side.self].x();
      const auto& xOther = ctx.particles[side.other].x();
      memory::resizeForRefill(side.pairCoefficient, list.totalPairs());
      parallel::forEachBalanced(xSelf.size(), pairsBefore(list), [&](std::size_t a) {
        std::size_t q = list.offset(a);
        for (Index bIndex : list.of(a)) {
          const std::size_t b = static_cast<std::size_t>(bIndex);
          const double d2 = (xSelf[a] - xOther[b]).squaredNorm();
          const double k = fluidSide ? pairK(a, b, d2) : pairK(b, a, d2);
          side.pairCoefficient[q] = k * gradients[q];
          ++q;
        }
      });
    }
  }
  sides_.resize(used);
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
    parallel::forEachBalanced(u[side.part].size, pairsBefore(list), [&](std::size_t a) {
      Vec3 force = Vec3::Zero();
      std::size_t q = list.offset(a);
      for (Index bIndex : list.of(a)) {
        const std::size_t b = static_cast<std::size_t>(bIndex);
        const Vec3 xab = xa[a] - xb[b];
        force += (side.pairCoefficient[q++] * (ua[a] - ub[b]).dot(xab)) * xab;
      }
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
    parallel::forEachBalanced(d[side.part].size, work, [&](std::size_t k) {
      const std::size_t a = first + k;
      Mat3 block = Mat3::Zero();
      std::size_t q = list.offset(a);
      for (Index bIndex : list.of(a)) {
        const Vec3 xab = xa[a] - xb[static_cast<std::size_t>(bIndex)];
        addOuter(block, side.pairCoefficient[q++] * xab, xab);
      }
      out[k] -= dt * block;
    });
  }
}

} // namespace poro
