#include "physics/CapillaryAdhesion.hpp"

#include "core/Memory.hpp"
#include "core/Parallel.hpp"
#include "physics/CouplingDensity.hpp"
#include "physics/FieldNames.hpp"

namespace poro {

double CapillaryAdhesion::coefficient(double strength, double falloff, double saturation, double massI, double rhoMix,
                                      double massT, double rhoT, double w) {
  return strength * (1.0 - falloff * saturation) * (massI + massT) / (rhoMix + rhoT) * w; // Eq. (13), (11)
}

bool CapillaryAdhesion::enabled(const StepContext& ctx) const {
  bool fluid = false, adhesion = false;
  for (std::size_t a : ctx.dynamicSets) {
    fluid = fluid || ctx.particles[a].kind() == SetKind::Fluid;
    adhesion = adhesion || (ctx.materials[a] && ctx.materials[a]->capillaryStrength > 0.0);
  }
  return fluid && adhesion;
}

void CapillaryAdhesion::prepare(const StepContext& ctx) {
  ctx_ = &ctx;
  std::size_t used = 0; // sides are kept from step to step, their pair arrays refilled in place
  std::size_t fluidPart = 0;
  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p)
    if (ctx.particles[ctx.dynamicSets[p]].kind() == SetKind::Fluid) fluidPart = p;
  const std::size_t fluidSet = ctx.dynamicSets[fluidPart];
  const ParticleSet& fluid = ctx.particles[fluidSet];

  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p) {
    const std::size_t t = ctx.dynamicSets[p];
    const PorousMaterial* material = ctx.materials[t];
    if (!material || material->capillaryStrength == 0.0) continue;
    const ParticleSet& solid = ctx.particles[t];
    const auto& saturation = solid.real(field::saturation);
    const bool fades = ctx.poreFill != nullptr;
    const double* fill = fades ? solid.real(field::poreFill).data() : nullptr;
    const double strength = material->capillaryStrength, falloff = material->capillaryFalloff;
    const MixtureDensity rhoMix(fluid, *material);
    const CouplingSolidDensity rhoSolid(ctx, t);
    // c_it with i always the fluid particle, whichever side evaluates it.
    auto pairC = [&](std::size_t i, std::size_t s, double distance) {
      const double c = coefficient(strength, falloff, saturation[s], fluid.mass, rhoMix(i), solid.mass, rhoSolid(s),
                                   ctx.kernel.w(distance));
      return fades ? PoreFill::fade(fill[s]) * c : c;
    };
    for (const bool fluidSide : {true, false}) {
      if (used == sides_.size()) sides_.emplace_back();
      Side& side = sides_[used++];
      side.self = fluidSide ? fluidSet : t;
      side.part = fluidSide ? fluidPart : p;
      side.other = fluidSide ? t : fluidSet;
      side.otherPart = fluidSide ? p : fluidPart;
      const NeighbourList& list = ctx.search.list(side.self, side.other);
      const auto& xSelf = ctx.particles[side.self].x();
      const auto& xOther = ctx.particles[side.other].x();
      memory::resizeForRefill(side.pairCoefficient, list.totalPairs());
      parallel::forEach(xSelf.size(), [&](std::size_t a) {
        std::size_t q = list.offset(a);
        for (Index bIndex : list.of(a)) {
          const std::size_t b = static_cast<std::size_t>(bIndex);
          const double distance = (xSelf[a] - xOther[b]).norm(); // |x_it| = |x_ti| to the bit
          side.pairCoefficient[q++] = fluidSide ? pairC(a, b, distance) : pairC(b, a, distance);
        }
      });
    }
  }
  sides_.resize(used);
}

void CapillaryAdhesion::addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const {
  // (A u)_a -= dt F_a with F_a = -dt sum_b c_ab u_ab from either side (Eq. 15 in Eq. 11, 14).
  const double dt2 = ctx_->dt * ctx_->dt;
  for (const Side& side : sides_) {
    const NeighbourList& list = ctx_->search.list(side.self, side.other);
    const Vec3* ua = u[side.part].data;
    const Vec3* ub = u[side.otherPart].data;
    Vec3* out = au[side.part].data;
    parallel::forEach(u[side.part].size, [&](std::size_t a) {
      Vec3 sum = Vec3::Zero();
      std::size_t q = list.offset(a);
      for (Index bIndex : list.of(a)) sum += side.pairCoefficient[q++] * (ua[a] - ub[static_cast<std::size_t>(bIndex)]);
      out[a] += dt2 * sum;
    });
  }
}

void CapillaryAdhesion::addDiagonal(const linalg::BlockDiagonal& d) const {
  const double dt2 = ctx_->dt * ctx_->dt;
  for (const Side& side : sides_) {
    const NeighbourList& list = ctx_->search.list(side.self, side.other);
    Mat3* out = d[side.part].data;
    const std::size_t firstParticle = d[side.part].first;
    parallel::forEach(d[side.part].size, [&](std::size_t k) {
      const std::size_t a = firstParticle + k;
      double sum = 0.0;
      const std::size_t first = list.offset(a), last = first + list.of(a).size();
      for (std::size_t q = first; q < last; ++q) sum += side.pairCoefficient[q];
      out[k] += (dt2 * sum) * Mat3::Identity();
    });
  }
}

void CapillaryAdhesion::addRhs(const linalg::BlockVector& b) const {
  // b_a += dt F^x_a with F^x_a = -sum_b c_ab x_ab at the current positions x^n (Eq. 11, 14).
  const double dt = ctx_->dt;
  for (const Side& side : sides_) {
    const NeighbourList& list = ctx_->search.list(side.self, side.other);
    const auto& xa = ctx_->particles[side.self].x();
    const auto& xb = ctx_->particles[side.other].x();
    Vec3* out = b[side.part].data;
    parallel::forEach(b[side.part].size, [&](std::size_t a) {
      Vec3 sum = Vec3::Zero();
      std::size_t q = list.offset(a);
      for (Index bIndex : list.of(a)) sum += side.pairCoefficient[q++] * (xa[a] - xb[static_cast<std::size_t>(bIndex)]);
      out[a] -= dt * sum;
    });
  }
}

} // namespace poro
