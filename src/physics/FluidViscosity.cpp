#include "physics/FluidViscosity.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "sph/BoundaryVolume.hpp"

namespace poro {

namespace {
constexpr double kViscosityFactor = 10.0; // 2(d + 2) for d = 3
} // namespace

bool FluidViscosity::enabled(const StepContext& ctx) const {
  bool hasFluid = false;
  for (std::size_t a : ctx.dynamicSets) hasFluid = hasFluid || ctx.particles[a].kind() == SetKind::Fluid;
  return hasFluid && (ctx.fluid.viscosity > 0.0 || ctx.fluid.boundaryViscosity > 0.0);
}

void FluidViscosity::prepare(const StepContext& ctx) {
  ctx_ = &ctx;
  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p)
    if (ctx.particles[ctx.dynamicSets[p]].kind() == SetKind::Fluid) {
      fluidSet_ = ctx.dynamicSets[p];
      fluidPart_ = p;
    }
  const ParticleSet& fluid = ctx.particles[fluidSet_];
  const auto& x = fluid.x();
  const auto& rho = fluid.real(field::density);
  const double m = fluid.mass;
  const double h = ctx.kernel.supportRadius();
  const double regulariser = 0.01 * h * h;
  const double mu = ctx.fluid.viscosity;
  const double muWall = ctx.fluid.boundaryViscosity;

  const NeighbourList& same = ctx.search.list(fluidSet_, fluidSet_);
  const auto& sameFactors = ctx.gradients.of(fluidSet_, fluidSet_);
  pairCoefficient_.resize(same.totalPairs());
  parallel::forEach(fluid.size(), [&](std::size_t i) {
    std::size_t p = same.offset(i);
    for (Index j : same.of(i)) {
      const std::size_t jj = static_cast<std::size_t>(j);
      const double vbar = (m / rho[i]) * (m / rho[jj]);
      const double kappa = kViscosityFactor * mu * vbar / ((x[i] - x[jj]).squaredNorm() + regulariser);
      pairCoefficient_[p] = kappa * sameFactors[p];
      ++p;
    }
  });

  wallCoefficient_.assign(ctx.boundarySets.size(), {});
  for (std::size_t w = 0; w < ctx.boundarySets.size(); ++w) {
    const std::size_t k = ctx.boundarySets[w];
    const NeighbourList& list = ctx.search.list(fluidSet_, k);
    const auto& factors = ctx.gradients.of(fluidSet_, k);
    const auto& xk = ctx.particles[k].x();
    const auto& vk = ctx.particles[k].real(kBoundaryVolumeField);
    auto& coeff = wallCoefficient_[w];
    coeff.resize(list.totalPairs());
    const double volume = fluid.particleVolume;
    parallel::forEach(fluid.size(), [&](std::size_t i) {
      std::size_t p = list.offset(i);
      const double vi = m / rho[i];
      for (Index kk : list.of(i)) {
        const std::size_t c = static_cast<std::size_t>(kk);
        const double vbar = vi * vi * vk[c] / volume;
        coeff[p] = kViscosityFactor * muWall * vbar / ((x[i] - xk[c]).squaredNorm() + regulariser) * factors[p];
        ++p;
      }
    });
  }
}

void FluidViscosity::addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const {
  const StepContext& ctx = *ctx_;
  const auto& x = ctx.particles[fluidSet_].x();
  const Vec3* uf = u[fluidPart_].data;
  Vec3* out = au[fluidPart_].data;
  const NeighbourList& same = ctx.search.list(fluidSet_, fluidSet_);
  const double dt = ctx.dt;
  std::vector<const NeighbourList*> walls;
  for (std::size_t k : ctx.boundarySets) walls.push_back(&ctx.search.list(fluidSet_, k));
  parallel::forEach(u[fluidPart_].size, [&](std::size_t i) {
    Vec3 force = Vec3::Zero();
    std::size_t p = same.offset(i);
    for (Index j : same.of(i)) {
      const std::size_t jj = static_cast<std::size_t>(j);
      const Vec3 xij = x[i] - x[jj];
      force += (pairCoefficient_[p++] * (uf[i] - uf[jj]).dot(xij)) * xij;
    }
    for (std::size_t w = 0; w < walls.size(); ++w) {
      const auto& xk = ctx.particles[ctx.boundarySets[w]].x();
      std::size_t q = walls[w]->offset(i);
      for (Index k : walls[w]->of(i)) {
        const Vec3 xik = x[i] - xk[static_cast<std::size_t>(k)];
        force += (wallCoefficient_[w][q++] * uf[i].dot(xik)) * xik;
      }
    }
    out[i] -= dt * force;
  });
}

void FluidViscosity::addDiagonal(const linalg::BlockDiagonal& d) const {
  const StepContext& ctx = *ctx_;
  const auto& x = ctx.particles[fluidSet_].x();
  Mat3* out = d[fluidPart_].data;
  const NeighbourList& same = ctx.search.list(fluidSet_, fluidSet_);
  const double dt = ctx.dt;
  parallel::forEach(d[fluidPart_].size, [&](std::size_t i) {
    Mat3 block = Mat3::Zero();
    std::size_t p = same.offset(i);
    for (Index j : same.of(i)) {
      const Vec3 xij = x[i] - x[static_cast<std::size_t>(j)];
      block += pairCoefficient_[p++] * (xij * xij.transpose());
    }
    for (std::size_t w = 0; w < ctx.boundarySets.size(); ++w) {
      const NeighbourList& list = ctx.search.list(fluidSet_, ctx.boundarySets[w]);
      const auto& xk = ctx.particles[ctx.boundarySets[w]].x();
      std::size_t q = list.offset(i);
      for (Index k : list.of(i)) {
        const Vec3 xik = x[i] - xk[static_cast<std::size_t>(k)];
        block += wallCoefficient_[w][q++] * (xik * xik.transpose());
      }
    }
    out[i] -= dt * block;
  });
}

void FluidViscosity::addRhs(const linalg::BlockVector& b) const {
  const StepContext& ctx = *ctx_;
  const auto& x = ctx.particles[fluidSet_].x();
  Vec3* out = b[fluidPart_].data;
  const double dt = ctx.dt;
  for (std::size_t w = 0; w < ctx.boundarySets.size(); ++w) {
    const std::size_t k = ctx.boundarySets[w];
    const NeighbourList& list = ctx.search.list(fluidSet_, k);
    const auto& xk = ctx.particles[k].x();
    const auto& vk = ctx.particles[k].v();
    parallel::forEach(b[fluidPart_].size, [&](std::size_t i) {
      // The wall partner's known velocity: F^x_a = sum_k kappa_ak ((-v_k) . x_ak) gradW_ak.
      Vec3 force = Vec3::Zero();
      std::size_t q = list.offset(i);
      for (Index kk : list.of(i)) {
        const std::size_t c = static_cast<std::size_t>(kk);
        const Vec3 xik = x[i] - xk[c];
        force -= (wallCoefficient_[w][q++] * vk[c].dot(xik)) * xik;
      }
      out[i] += dt * force;
    });
  }
}

} // namespace poro
