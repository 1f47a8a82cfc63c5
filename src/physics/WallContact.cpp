#include "physics/WallContact.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/VolumeFactors.hpp"
#include "sph/BoundaryVolume.hpp"

#include <algorithm>
#include <cmath>

namespace poro {

void registerWallContactFields(ParticleSet& set) {
  set.addReal(field::wallContactLimit, Restart); // zero (unset) where new: initialiseWallContactLimits sets it
  set.addReal(field::contactPressure, Restart);
  set.addReal(field::wallShare);
  set.addReal(field::wallShareStar);
  set.addVec3(field::wallGradient);
}

void dropWallContactFields(ParticleSet& set) {
  for (const char* name :
       {field::wallContactLimit, field::contactPressure, field::wallShare, field::wallShareStar, field::wallGradient})
    set.drop(name);
}

bool hasWallContact(const ParticleSet& set) { return set.has(field::contactPressure); }

double flatWallShare(const CubicKernel& kernel, double spacing) {
  const int reach = static_cast<int>(std::ceil(kernel.supportRadius() / spacing));
  // V_k of a first-layer particle: its own layer and the one behind it (METHOD.md §6.2).
  double sum = kernel.w0();
  for (int layer = 0; layer >= -1; --layer)
    for (int i = -reach; i <= reach; ++i)
      for (int k = -reach; k <= reach; ++k)
        if (layer != 0 || i != 0 || k != 0) sum += kernel.w(spacing * Vec3(i, layer, k));
  const double volume = 1.0 / sum;
  double share = 0.0;
  for (int i = -reach; i <= reach; ++i)
    for (int k = -reach; k <= reach; ++k) share += volume * kernel.w(spacing * Vec3(i, 1.0, k));
  return share;
}

void initialiseWallContactLimits(const StepContext& ctx, double flatShare) {
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    if (!hasWallContact(set)) continue;
    auto& limit = set.real(field::wallContactLimit);
    const auto& share = set.real(field::wallShare);
    parallel::forEach(set.size(), [&](std::size_t i) {
      if (!(limit[i] > 0.0)) limit[i] = std::max(flatShare, share[i]); // unset: zero, or -1 in older files
    });
  }
}

void predictWallShares(const StepContext& ctx) {
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    if (!hasWallContact(set)) continue;
    const auto& x = set.x();
    const auto& v = set.v();
    const auto& share = set.real(field::wallShare);
    const auto& gradient = set.vec3(field::wallGradient);
    auto& predicted = set.real(field::wallShareStar);
    parallel::forEach(set.size(), [&](std::size_t i) {
      // sum_k V_k (v_a - v_k).gradW_ak = v_a.G^w_a - sum_k V_k s_ak v_k.x_ak
      double change = v[i].dot(gradient[i]);
      for (std::size_t k : ctx.boundarySets) {
        const ParticleSet& wall = ctx.particles[k];
        const auto& xk = wall.x();
        const auto& vk = wall.v();
        const auto& volume = wall.real(kBoundaryVolumeField);
        const auto& factors = ctx.gradients.of(a, k);
        const NeighbourList& list = ctx.search.list(a, k);
        std::size_t q = list.offset(i);
        for (Index kIndex : list.of(i)) {
          const std::size_t kk = static_cast<std::size_t>(kIndex);
          change -= volume[kk] * factors[q++] * vk[kk].dot(x[i] - xk[kk]);
        }
      }
      predicted[i] = share[i] + ctx.dt * change;
    });
  }
}

void warmStartContactPressure(const StepContext& ctx, double factor) {
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    if (!hasWallContact(set)) continue;
    auto& kappa = set.real(field::contactPressure);
    const auto& predicted = set.real(field::wallShareStar);
    const auto& limit = set.real(field::wallContactLimit);
    const std::int64_t* fixed = fixedFlags(set);
    parallel::forEach(set.size(), [&](std::size_t i) {
      kappa[i] = predicted[i] > limit[i] && !(fixed && fixed[i]) ? factor * kappa[i] : 0.0;
    });
  }
}

} // namespace poro
