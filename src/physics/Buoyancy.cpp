#include "physics/Buoyancy.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/VolumeFactors.hpp"

namespace poro {

bool Buoyancy::enabled(const StepContext& ctx) const {
  bool porous = false;
  for (std::size_t a : ctx.dynamicSets) porous = porous || ctx.materials[a];
  return porous && fluidSetOf(ctx) >= 0;
}

void Buoyancy::forces(const StepContext& ctx, std::size_t t, std::vector<Vec3>& force) {
  force.assign(ctx.particles[t].size(), Vec3::Zero());
  addForces(ctx, t, 1.0, force.data());
}

void Buoyancy::addForces(const StepContext& ctx, std::size_t t, double factor, Vec3* out) {
  const std::size_t fluidSet = static_cast<std::size_t>(fluidSetOf(ctx));
  const ParticleSet& fluid = ctx.particles[fluidSet];
  const ParticleSet& solid = ctx.particles[t];
  const auto& pi = fluid.real(field::pi);
  const auto& xf = fluid.x();
  const auto& xs = solid.x();
  const NeighbourList& list = ctx.search.list(t, fluidSet);
  const auto& gradients = ctx.gradients.of(t, fluidSet);
  const double scale = -(1.0 - ctx.materials[t]->porosity) * solid.particleVolume * fluid.mass;
  parallel::forEach(solid.size(), [&](std::size_t s) {
    Vec3 sum = Vec3::Zero();
    std::size_t q = list.offset(s);
    for (Index jIndex : list.of(s)) {
      const std::size_t j = static_cast<std::size_t>(jIndex);
      sum += (pi[j] * gradients[q++]) * (xs[s] - xf[j]);
    }
    const Vec3 force = scale * sum;
    out[s] += factor * force;
  });
}

void Buoyancy::addRhs(const linalg::BlockVector& b) const {
  for (std::size_t p = 0; p < ctx_->dynamicSets.size(); ++p) {
    const std::size_t t = ctx_->dynamicSets[p];
    if (ctx_->materials[t]) addForces(*ctx_, t, ctx_->dt, b[p].data);
  }
}

} // namespace poro
