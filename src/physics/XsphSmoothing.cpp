#include "physics/XsphSmoothing.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/VolumeFactors.hpp"

namespace poro {

namespace {
constexpr const char* kVelocityBefore = "xsphVelocityBefore"; // v^n, read while v is rewritten (gather form)
} // namespace

void smoothFluidVelocities(const StepContext& ctx, double eps) {
  const long fluidSet = fluidSetOf(ctx);
  if (eps == 0.0 || fluidSet < 0) return;
  const std::size_t f = static_cast<std::size_t>(fluidSet);
  ParticleSet& fluid = ctx.particles[f];
  auto& v = fluid.v();
  auto& before = fluid.addVec3(kVelocityBefore);
  before = v;
  const auto& x = fluid.x();
  const auto& rho = fluid.real(field::density);
  const double twiceMass = 2.0 * fluid.mass;
  const NeighbourList& list = ctx.search.list(f, f);
  parallel::forEach(fluid.size(), [&](std::size_t i) {
    Vec3 sum = Vec3::Zero();
    for (Index jIndex : list.of(i)) {
      const std::size_t j = static_cast<std::size_t>(jIndex);
      sum += (twiceMass / (rho[i] + rho[j]) * ctx.kernel.w(x[i] - x[j])) * (before[j] - before[i]);
    }
    v[i] = before[i] + eps * sum;
  });
}

} // namespace poro
