#include "physics/Densities.hpp"

#include "core/Memory.hpp"
#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/PoreFluidDensityBias.hpp"
#include "physics/VolumeFactors.hpp"
#include "physics/WallContact.hpp"
#include "sph/BoundaryVolume.hpp"

#include <algorithm>

namespace poro {

namespace {
/// alpha is 0 below this value of |G|^2 + Q [1/m^2]: only particles without neighbours (METHOD.md §6.3).
constexpr double kAlphaThreshold = 1e-5;
/// Porous: sum_j V W_sj over fluid neighbours, the numerator of the saturation (Eq. 12).
const char* const kFluidVolume = "fluidVolume";

/// One neighbour set of the particle loop with everything the sums need.
struct Partner {
  const NeighbourList* list;
  const std::vector<Vec3>* x;
  std::vector<PairFactor>* gradients;
  SetCoupling coupling;
  bool counts; ///< f(a<-b) != 0 for some pair
  const std::int64_t* objectB;
  const std::int64_t* fixedB; ///< null: all Active
  double massRatio;           ///< m_a / m_b
  bool fluidB;
  double solidShare; ///< (1 - phi_b) for a fluid a and porous b: the local-porosity sum
};

struct Wall {
  const NeighbourList* list;
  const std::vector<Vec3>* x;
  const std::vector<double>* volume;
  std::vector<PairFactor>* gradients;
};

/// One particle's offsets to its neighbours in one set, and their kernel values (CubicKernel::values): a
/// buffer per thread, grown to the longest list seen.
struct PairScratch {
  std::vector<double> dx, dy, dz, dist, w;

  /// Fills the offsets x_i - x_j over `range` and their distances and W; returns the count.
  std::size_t values(const CubicKernel& kernel, const Vec3& xi, const std::vector<Vec3>& xb,
                     NeighbourList::Range range) {
    const std::size_t n = range.size();
    if (dx.size() < n)
      for (auto* buffer : {&dx, &dy, &dz, &dist, &w}) buffer->resize(n);
    std::size_t k = 0;
    for (Index j : range) {
      const Vec3 d = xi - xb[static_cast<std::size_t>(j)];
      dx[k] = d.x();
      dy[k] = d.y();
      dz[k] = d.z();
      ++k;
    }
    kernel.values(n, dx.data(), dy.data(), dz.data(), dist.data(), w.data());
    return n;
  }
  /// values(), and s into `factors`.
  std::size_t evaluate(const CubicKernel& kernel, const Vec3& xi, const std::vector<Vec3>& xb,
                       NeighbourList::Range range, PairFactor* factors) {
    const std::size_t n = values(kernel, xi, xb, range);
    kernel.gradientFactors(n, dist.data(), factors);
    return n;
  }
  Vec3 offset(std::size_t k) const { return Vec3(dx[k], dy[k], dz[k]); }
};

PairScratch& pairScratch() {
  thread_local PairScratch scratch;
  return scratch;
}

void computeSetDensities(const StepContext& ctx, std::size_t a, PairGradients& gradients) {
  const ParticleSystem& ps = ctx.particles;
  const CubicKernel& kernel = ctx.kernel;
  ParticleSet& set = ctx.particles[a];
  const bool porous = set.kind() == SetKind::Porous;
  const auto& x = set.x();
  const double volume = set.particleVolume;
  const double rhoMax = set.restDensity;
  const double self = selfFactor(ctx, a);
  auto& rhoTilde = set.real(field::rhoTilde);
  auto& density = set.real(field::density);
  auto& alpha = set.real(field::alpha);
  auto& gradSum = set.vec3(field::gradSum);
  double* fluidVolume = porous ? set.real(kFluidVolume).data() : nullptr;
  double* localPorosity = porous ? nullptr : set.real(field::localPorosity).data();
  const std::int64_t* objectA = set.integer(field::objectId).data();
  const PoreFluidDensityBias* poreBias = porous ? nullptr : ctx.poreFluidBias;
  const bool contact = hasWallContact(set);
  double* wallShare = contact ? set.real(field::wallShare).data() : nullptr;
  Vec3* wallGradient = contact ? set.vec3(field::wallGradient).data() : nullptr;

  std::vector<Partner> partners;
  const auto couplings = couplingsOf(ctx, a);
  for (std::size_t b : ctx.dynamicSets) {
    const ParticleSet& other = ps[b];
    Partner p{};
    p.list = &ctx.search.list(a, b);
    p.x = &other.x();
    p.gradients = &gradients.of(a, b);
    memory::resizeForRefill(*p.gradients, p.list->totalPairs());
    for (const SetCoupling& c : couplings)
      if (c.other == b) {
        p.coupling = c;
        p.counts = true;
      }
    p.objectB = other.integer(field::objectId).data();
    p.fixedB = fixedFlags(other);
    p.massRatio = set.mass / other.mass;
    p.fluidB = other.kind() == SetKind::Fluid;
    p.solidShare = !porous && ctx.materials[b] ? 1.0 - ctx.materials[b]->porosity : 0.0;
    partners.push_back(p);
  }
  std::vector<Wall> walls;
  for (std::size_t k : ctx.boundarySets) {
    auto& g = gradients.of(a, k);
    memory::resizeForRefill(g, ctx.search.list(a, k).totalPairs());
    walls.push_back({&ctx.search.list(a, k), &ps[k].x(), &ps[k].real(kBoundaryVolumeField), &g});
  }

  parallel::forEach(ctx.owned(a), [&](std::size_t i) {
    const Vec3 xi = x[i];
    PairScratch& scratch = pairScratch();
    double sumW = self * kernel.w0(); // volume factors times W, times V below
    double solidW = 0.0;              // fluid: sum (1 - phi_t) W_it
    double fluidW = 0.0;              // porous: sum W_sj over fluid
    Vec3 g = Vec3::Zero();
    double q = 0.0;
    for (const Partner& p : partners) {
      const NeighbourList::Range range = p.list->of(i);
      // G sums the stored (rounded) s, the numbers the solvers will read.
      PairFactor* s = p.gradients->data() + p.list->offset(i);
      const std::size_t n = scratch.evaluate(kernel, xi, *p.x, range, s);
      const double* w = scratch.w.data();
      if (p.fluidB && porous)
        for (std::size_t k = 0; k < n; ++k) fluidW += w[k];
      if (!p.counts) continue;
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t j = static_cast<std::size_t>(range[k]);
        const Vec3 xij = scratch.offset(k);
        const double f = p.coupling.factorOf(objectA[i] == p.objectB[j]);
        sumW += f * w[k];
        solidW += p.solidShare * w[k];
        g += (f * s[k]) * xij;
        if (p.coupling.samePhase && !(p.fixedB && p.fixedB[j]))
          q += f * f * p.massRatio * s[k] * s[k] * xij.squaredNorm();
      }
    }
    double rt = volume * sumW;
    double wallW = 0.0;
    Vec3 wallG = Vec3::Zero();
    g *= volume;
    q *= volume * volume;
    for (const Wall& wall : walls) {
      const NeighbourList::Range range = wall.list->of(i);
      PairFactor* s = wall.gradients->data() + wall.list->offset(i);
      const std::size_t n = scratch.evaluate(kernel, xi, *wall.x, range, s);
      for (std::size_t k = 0; k < n; ++k) {
        const double vk = (*wall.volume)[static_cast<std::size_t>(range[k])];
        const Vec3 xik = scratch.offset(k);
        wallW += vk * scratch.w[k];
        g += (vk * s[k]) * xik;
        if (contact) wallG += (vk * s[k]) * xik;
      }
    }
    rt += wallW;
    if (contact) {
      wallShare[i] = wallW;
      wallGradient[i] = wallG;
    }
    if (poreBias && solidW > 0.0) rt -= (*poreBias)(1.0 - volume * solidW);
    rhoTilde[i] = rt;
    density[i] = rhoMax * rt;
    gradSum[i] = g;
    const double denom = g.squaredNorm() + q;
    alpha[i] = denom > kAlphaThreshold ? 1.0 / denom : 0.0;
    if (fluidVolume) fluidVolume[i] = volume * fluidW;
    if (localPorosity) localPorosity[i] = 1.0 - volume * solidW - wallW;
  });
}

/// S_s of Eq. 12 with the current densities of the material's particles.
void computeSaturation(const StepContext& ctx, std::size_t a) {
  ParticleSet& set = ctx.particles[a];
  const double phi = ctx.materials[a]->porosity;
  const auto& x = set.x();
  const auto& rho = set.real(field::density);
  const auto& fluidVolume = set.real(kFluidVolume);
  auto& saturation = set.real(field::saturation);
  // The pore fill only where the adhesion reads it.
  const PoreFill* poreFill = ctx.materials[a]->capillaryStrength > 0.0 ? ctx.poreFill : nullptr;
  double* fill = poreFill ? set.real(field::poreFill).data() : nullptr;
  const bool compressible = ctx.materials[a]->compressible;
  double* restCoverage = poreFill && set.has(field::restCoverage) ? set.real(field::restCoverage).data() : nullptr;
  const NeighbourList& same = ctx.search.list(a, a);
  const CubicKernel& kernel = ctx.kernel;
  const double m = set.mass;
  parallel::forEach(ctx.owned(a), [&](std::size_t i) {
    if (phi == 0.0) {
      saturation[i] = fluidVolume[i] > 0.0 ? 1.0 : 0.0;
      if (fill) fill[i] = saturation[i];
      return;
    }
    double n = (m / rho[i]) * kernel.w0();
    double coverage = poreFill ? poreFill->volumeWeight(0.0) : 0.0; // sum_t V Wbar_st
    PairScratch& scratch = pairScratch();
    const NeighbourList::Range range = same.of(i);
    const std::size_t count = scratch.values(kernel, x[i], x, range);
    for (std::size_t k = 0; k < count; ++k) n += (m / rho[static_cast<std::size_t>(range[k])]) * scratch.w[k];
    if (poreFill)
      for (std::size_t k = 0; k < count; ++k) coverage += poreFill->volumeWeight(scratch.dist[k]);
    saturation[i] = std::clamp(fluidVolume[i] / (phi * n), 0.0, 1.0);
    if (!poreFill) return;
    if (restCoverage && !(restCoverage[i] > 0.0)) restCoverage[i] = coverage; // unset: the first step, at rest
    const double pores = PoreFill::poreVolume(phi, compressible, coverage, restCoverage ? restCoverage[i] : -1.0);
    fill[i] = pores > 0.0 ? fluidVolume[i] / pores : (fluidVolume[i] > 0.0 ? 1e9 : 0.0); // squeezed shut
  });
}

} // namespace

void registerDensityFields(ParticleSet& set) {
  set.addReal(field::density, Output);
  set.addReal(field::rhoTilde);
  set.addReal(field::alpha);
  set.addVec3(field::gradSum);
  if (set.kind() == SetKind::Porous) {
    set.addReal(field::saturation, Output);
    set.addReal(kFluidVolume);
  } else {
    set.addReal(field::localPorosity, Output);
  }
}

void computeDensities(const StepContext& ctx, PairGradients& gradients) {
  gradients.resize(ctx.particles.size());
  for (std::size_t a : ctx.dynamicSets) computeSetDensities(ctx, a, gradients);
  const bool anyMaterial = std::any_of(ctx.dynamicSets.begin(), ctx.dynamicSets.end(),
                                       [&](std::size_t a) { return ctx.materials[a] != nullptr; });
  if (!anyMaterial) return;
  ctx.refreshGhosts({field::density}); // N_s sums the neighbours' densities, ghosts among them
  for (std::size_t a : ctx.dynamicSets)
    if (ctx.materials[a]) computeSaturation(ctx, a);
}

std::vector<std::string> densityFields() {
  return {field::density, field::rhoTilde, field::alpha,         field::gradSum,   field::saturation,
          kFluidVolume,   field::poreFill, field::localPorosity, field::wallShare, field::wallGradient};
}

} // namespace poro
