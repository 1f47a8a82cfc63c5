#include "physics/Densities.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "sph/BoundaryVolume.hpp"

namespace poro {

namespace {
/// alpha is 0 below this value of |G|^2 + Q [1/m^2]: only particles without neighbours (METHOD.md §6.3).
constexpr double kAlphaThreshold = 1e-5;
} // namespace

void registerDensityFields(ParticleSet& set) {
  set.addReal(field::density, Output);
  set.addReal(field::rhoTilde);
  set.addReal(field::alpha);
  set.addVec3(field::gradSum);
}

void computeDensities(const StepContext& ctx, PairGradients& gradients) {
  const ParticleSystem& ps = ctx.particles;
  const CubicKernel& kernel = ctx.kernel;
  gradients.resize(ps.size());
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    const std::vector<Vec3>& x = set.x();
    const double volume = set.particleVolume;
    const double rhoMax = set.restDensity;
    auto& rhoTilde = set.real(field::rhoTilde);
    auto& density = set.real(field::density);
    auto& alpha = set.real(field::alpha);
    auto& gradSum = set.vec3(field::gradSum);
    const NeighbourList& same = ctx.search.list(a, a);
    std::vector<double>& sameFactors = gradients.of(a, a);
    sameFactors.resize(same.totalPairs());

    // Wall lists and their factor arrays, gathered once so the particle loop stays flat.
    struct Wall {
      const NeighbourList* list;
      const std::vector<Vec3>* x;
      const std::vector<double>* volume;
      std::vector<double>* factors;
    };
    std::vector<Wall> walls;
    for (std::size_t k : ctx.boundarySets) {
      auto& factors = gradients.of(a, k);
      factors.resize(ctx.search.list(a, k).totalPairs());
      walls.push_back({&ctx.search.list(a, k), &ps[k].x(), &ps[k].real(kBoundaryVolumeField), &factors});
    }

    parallel::forEach(set.size(), [&](std::size_t i) {
      const Vec3 xi = x[i];
      double sumW = kernel.w0();
      Vec3 g = Vec3::Zero();
      double q = 0.0;
      std::size_t pair = same.offset(i);
      for (Index j : same.of(i)) {
        const Vec3 xij = xi - x[static_cast<std::size_t>(j)];
        const double dist = xij.norm();
        const double s = kernel.gradFactor(dist);
        sameFactors[pair++] = s;
        sumW += kernel.w(dist);
        g += s * xij;
        q += s * s * xij.squaredNorm();
      }
      double rt = volume * sumW;
      g *= volume;
      q *= volume * volume;
      for (const Wall& wall : walls) {
        std::size_t wp = wall.list->offset(i);
        for (Index k : wall.list->of(i)) {
          const std::size_t kk = static_cast<std::size_t>(k);
          const Vec3 xik = xi - (*wall.x)[kk];
          const double dist = xik.norm();
          const double s = kernel.gradFactor(dist);
          (*wall.factors)[wp++] = s;
          const double vk = (*wall.volume)[kk];
          rt += vk * kernel.w(dist);
          g += (vk * s) * xik;
        }
      }
      rhoTilde[i] = rt;
      density[i] = rhoMax * rt;
      gradSum[i] = g;
      const double denom = g.squaredNorm() + q;
      alpha[i] = denom > kAlphaThreshold ? 1.0 / denom : 0.0;
    });
  }
}

} // namespace poro
