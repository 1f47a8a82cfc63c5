#include "physics/Viscosity.hpp"

#include "core/Memory.hpp"
#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "sph/BoundaryVolume.hpp"

namespace poro {

namespace {
constexpr double kViscosityFactor = 10.0; // 2(d + 2) for d = 3

/// (mu, mu_b) of a dynamic set: the fluid's viscosities or a porous material's damping.
std::pair<double, double> viscositiesOf(const StepContext& ctx, std::size_t set) {
  if (const PorousMaterial* m = ctx.materials[set]) return {m->dampingViscosity, m->boundaryDampingViscosity};
  return {ctx.fluid.viscosity, ctx.fluid.boundaryViscosity};
}
} // namespace

bool Viscosity::enabled(const StepContext& ctx) const {
  for (std::size_t a : ctx.dynamicSets) {
    const auto [mu, muWall] = viscositiesOf(ctx, a);
    if (mu > 0.0 || muWall > 0.0) return true;
  }
  return false;
}

void Viscosity::prepare(const StepContext& ctx) {
  ctx_ = &ctx;
  // Members are kept from step to step: their pair arrays are refilled in place instead of freed and allocated
  // anew (the allocator would keep the freed blocks, and the process grows by the lists' growth each step).
  std::size_t used = 0;
  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p) {
    const std::size_t s = ctx.dynamicSets[p];
    const auto [mu, muWall] = viscositiesOf(ctx, s);
    if (mu == 0.0 && muWall == 0.0) continue;
    if (used == members_.size()) members_.emplace_back();
    Member& member = members_[used++];
    member.set = s;
    member.part = p;
    prepareMember(ctx, member, mu, muWall, ctx.materials[s] != nullptr);
  }
  members_.resize(used);
}

void Viscosity::prepareMember(const StepContext& ctx, Member& member, double mu, double muWall, bool byObject) {
  const ParticleSet& set = ctx.particles[member.set];
  const auto& x = set.x();
  const auto& rho = set.real(field::density);
  const auto& object = set.integer(field::objectId);
  const double m = set.mass;
  const double h = ctx.kernel.supportRadius();
  const double regulariser = 0.01 * h * h;

  const NeighbourList& same = ctx.search.list(member.set, member.set);
  const auto& sameFactors = ctx.gradients.of(member.set, member.set);
  memory::resizeForRefill(member.pairCoefficient, same.totalPairs());
  std::vector<double> volumeOf(set.size()); // m/rho once per particle, not once per pair
  parallel::forEach(set.size(), [&](std::size_t i) { volumeOf[i] = m / rho[i]; });
  parallel::forEach(set.size(), [&](std::size_t i) {
    std::size_t p = same.offset(i);
    for (Index j : same.of(i)) {
      const std::size_t jj = static_cast<std::size_t>(j);
      const double vbar = volumeOf[i] * volumeOf[jj];
      const double kappa = kViscosityFactor * mu * vbar / ((x[i] - x[jj]).squaredNorm() + regulariser);
      member.pairCoefficient[p] = byObject && object[i] != object[jj] ? 0.0 : kappa * sameFactors[p];
      ++p;
    }
  });

  // Without a wall viscosity the wall pairs contribute nothing: no coefficients, and no wall loops below.
  member.wallCoefficient.assign(muWall > 0.0 ? ctx.boundarySets.size() : 0, {});
  for (std::size_t w = 0; w < member.wallCoefficient.size(); ++w) {
    const std::size_t k = ctx.boundarySets[w];
    const NeighbourList& list = ctx.search.list(member.set, k);
    const auto& factors = ctx.gradients.of(member.set, k);
    const auto& xk = ctx.particles[k].x();
    const auto& vk = ctx.particles[k].real(kBoundaryVolumeField);
    auto& coeff = member.wallCoefficient[w];
    memory::resizeForRefill(coeff, list.totalPairs());
    const double volume = set.particleVolume;
    parallel::forEach(set.size(), [&](std::size_t i) {
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

void Viscosity::addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const {
  const StepContext& ctx = *ctx_;
  const double dt = ctx.dt;
  for (const Member& member : members_) {
    const auto& x = ctx.particles[member.set].x();
    const Vec3* uf = u[member.part].data;
    Vec3* out = au[member.part].data;
    const NeighbourList& same = ctx.search.list(member.set, member.set);
    std::vector<const NeighbourList*> walls;
    for (std::size_t w = 0; w < member.wallCoefficient.size(); ++w)
      walls.push_back(&ctx.search.list(member.set, ctx.boundarySets[w]));
    const auto work = [&](std::size_t i) {
      std::size_t pairs = i + same.offset(i);
      for (const NeighbourList* wall : walls) pairs += wall->offset(i);
      return pairs;
    };
    parallel::forEachBalanced(u[member.part].size, work, [&](std::size_t i) {
      Vec3 force = Vec3::Zero();
      std::size_t p = same.offset(i);
      for (Index j : same.of(i)) {
        const std::size_t jj = static_cast<std::size_t>(j);
        const Vec3 xij = x[i] - x[jj];
        force += (member.pairCoefficient[p++] * (uf[i] - uf[jj]).dot(xij)) * xij;
      }
      for (std::size_t w = 0; w < walls.size(); ++w) {
        const auto& xk = ctx.particles[ctx.boundarySets[w]].x();
        std::size_t q = walls[w]->offset(i);
        for (Index k : walls[w]->of(i)) {
          const Vec3 xik = x[i] - xk[static_cast<std::size_t>(k)];
          force += (member.wallCoefficient[w][q++] * uf[i].dot(xik)) * xik;
        }
      }
      out[i] -= dt * force;
    });
  }
}

void Viscosity::addDiagonal(const linalg::BlockDiagonal& d) const {
  const StepContext& ctx = *ctx_;
  const double dt = ctx.dt;
  for (const Member& member : members_) {
    const auto& x = ctx.particles[member.set].x();
    Mat3* out = d[member.part].data;
    const std::size_t first = d[member.part].first;
    const NeighbourList& same = ctx.search.list(member.set, member.set);
    parallel::forEach(d[member.part].size, [&](std::size_t k) {
      const std::size_t i = first + k;
      Mat3 block = Mat3::Zero();
      std::size_t p = same.offset(i);
      for (Index j : same.of(i)) {
        const Vec3 xij = x[i] - x[static_cast<std::size_t>(j)];
        addOuter(block, member.pairCoefficient[p++] * xij, xij);
      }
      for (std::size_t w = 0; w < member.wallCoefficient.size(); ++w) {
        const NeighbourList& list = ctx.search.list(member.set, ctx.boundarySets[w]);
        const auto& xk = ctx.particles[ctx.boundarySets[w]].x();
        std::size_t q = list.offset(i);
        for (Index c : list.of(i)) {
          const Vec3 xik = x[i] - xk[static_cast<std::size_t>(c)];
          addOuter(block, member.wallCoefficient[w][q++] * xik, xik);
        }
      }
      out[k] -= dt * block;
    });
  }
}

void Viscosity::addWallReactions(const linalg::BlockVector& u, std::vector<std::vector<Vec3>>& forces) const {
  const StepContext& ctx = *ctx_;
  for (const Member& member : members_) {
    const auto& x = ctx.particles[member.set].x();
    const Vec3* uf = u[member.part].data;
    for (std::size_t w = 0; w < member.wallCoefficient.size(); ++w) {
      const std::size_t k = ctx.boundarySets[w];
      const NeighbourList& list = ctx.search.list(member.set, k);
      const auto& xk = ctx.particles[k].x();
      const auto& vk = ctx.particles[k].v();
      const auto& coefficient = member.wallCoefficient[w];
      auto& out = forces[w];
      // Serial and in a fixed order: several particles pull one wall particle, and restarts must sum alike.
      for (std::size_t i = 0; i < u[member.part].size; ++i) {
        std::size_t q = list.offset(i);
        for (Index kk : list.of(i)) {
          const std::size_t c = static_cast<std::size_t>(kk);
          const Vec3 xik = x[i] - xk[c];
          out[c] -= (coefficient[q++] * (uf[i] - vk[c]).dot(xik)) * xik;
        }
      }
    }
  }
}

void Viscosity::addRhs(const linalg::BlockVector& b) const {
  const StepContext& ctx = *ctx_;
  const double dt = ctx.dt;
  for (const Member& member : members_) {
    const auto& x = ctx.particles[member.set].x();
    Vec3* out = b[member.part].data;
    for (std::size_t w = 0; w < member.wallCoefficient.size(); ++w) {
      const std::size_t k = ctx.boundarySets[w];
      const NeighbourList& list = ctx.search.list(member.set, k);
      const auto& xk = ctx.particles[k].x();
      const auto& vk = ctx.particles[k].v();
      parallel::forEach(b[member.part].size, [&](std::size_t i) {
        // The wall partner's known velocity: F^x_a = sum_k kappa_ak ((-v_k) . x_ak) gradW_ak.
        Vec3 force = Vec3::Zero();
        std::size_t q = list.offset(i);
        for (Index kk : list.of(i)) {
          const std::size_t c = static_cast<std::size_t>(kk);
          const Vec3 xik = x[i] - xk[c];
          force -= (member.wallCoefficient[w][q++] * vk[c].dot(xik)) * xik;
        }
        out[i] += dt * force;
      });
    }
  }
}

} // namespace poro
