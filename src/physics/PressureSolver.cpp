#include "physics/PressureSolver.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "sph/BoundaryVolume.hpp"

#include <algorithm>

namespace poro {

namespace {
const char* const kResidual = "pressureResidual"; ///< max(rho~ after the sweep's pressure - 1, 0)

/// Boundary neighbour data of one dynamic set, gathered once per call.
struct WallView {
  const NeighbourList* list;
  const std::vector<Vec3>* x;
  const std::vector<Vec3>* v;
  const std::vector<double>* volume;
  const std::vector<double>* factors;
};

std::vector<WallView> wallsOf(const StepContext& ctx, std::size_t a) {
  std::vector<WallView> walls;
  for (std::size_t k : ctx.boundarySets) {
    const ParticleSet& b = ctx.particles[k];
    walls.push_back({&ctx.search.list(a, k), &b.x(), &b.v(), &b.real(kBoundaryVolumeField), &ctx.gradients.of(a, k)});
  }
  return walls;
}
} // namespace

void PressureSolver::registerFields(ParticleSet& set) {
  set.addReal(field::pi, Restart);
  set.addReal(field::pressure, Output);
  set.addReal(field::rhoStar);
  set.addVec3(field::accelP);
  set.addReal(kResidual);
}

void PressureSolver::predictDensities(const StepContext& ctx) const {
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    const auto& x = set.x();
    const auto& v = set.v();
    const auto& rhoTilde = set.real(field::rhoTilde);
    const auto& gradSum = set.vec3(field::gradSum);
    auto& rhoStar = set.real(field::rhoStar);
    const NeighbourList& same = ctx.search.list(a, a);
    const auto& factors = ctx.gradients.of(a, a);
    const double volume = set.particleVolume;
    const auto walls = wallsOf(ctx, a);
    const double dt = ctx.dt;
    parallel::forEach(set.size(), [&](std::size_t i) {
      // sum_b V (v_a - v_b).gradW = v_a.G_a - V sum_b s_ab v_b.x_ab  (G holds the v_a part of every term)
      double others = 0.0;
      std::size_t p = same.offset(i);
      for (Index j : same.of(i)) {
        const std::size_t jj = static_cast<std::size_t>(j);
        others += factors[p++] * v[jj].dot(x[i] - x[jj]);
      }
      double change = v[i].dot(gradSum[i]) - volume * others;
      for (const WallView& w : walls) {
        std::size_t q = w.list->offset(i);
        for (Index k : w.list->of(i)) {
          const std::size_t kk = static_cast<std::size_t>(k);
          change -= (*w.volume)[kk] * (*w.factors)[q++] * (*w.v)[kk].dot(x[i] - (*w.x)[kk]);
        }
      }
      rhoStar[i] = rhoTilde[i] + dt * change;
    });
  }
}

void PressureSolver::computeAccelerations(const StepContext& ctx) const {
  // a^p_a = -pi_a G_a - V sum_b pi_b s_ab x_ab: the pi_a part of every pair and wall term is pi_a G_a
  // (fluid-fluid h_ab = 1 for equal masses, Eq. 7 line 1; walls are one-sided).
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    const auto& x = set.x();
    const auto& pi = set.real(field::pi);
    const auto& gradSum = set.vec3(field::gradSum);
    auto& accel = set.vec3(field::accelP);
    const NeighbourList& same = ctx.search.list(a, a);
    const auto& factors = ctx.gradients.of(a, a);
    const double volume = set.particleVolume;
    parallel::forEach(set.size(), [&](std::size_t i) {
      Vec3 sum = Vec3::Zero();
      std::size_t p = same.offset(i);
      for (Index j : same.of(i)) {
        const std::size_t jj = static_cast<std::size_t>(j);
        sum += (pi[jj] * factors[p++]) * (x[i] - x[jj]);
      }
      accel[i] = -pi[i] * gradSum[i] - volume * sum;
    });
  }
}

PressureStats PressureSolver::solve(const StepContext& ctx) const {
  const double dt = ctx.dt;
  const double dt2 = dt * dt;
  const double omega = settings_.relaxation;
  const double tolerance = settings_.maxDensityError / 100.0;

  for (std::size_t a : ctx.dynamicSets) { // warm start (METHOD.md §6.7)
    ParticleSet& set = ctx.particles[a];
    auto& pi = set.real(field::pi);
    const auto& rhoStar = set.real(field::rhoStar);
    const double factor = settings_.warmStart;
    parallel::forEach(set.size(), [&](std::size_t i) { pi[i] = rhoStar[i] > 1.0 ? factor * pi[i] : 0.0; });
  }

  PressureStats stats;
  for (int it = 1; it <= settings_.maxIterations; ++it) {
    computeAccelerations(ctx);
    double worstMean = 0.0, worstMax = 0.0;
    for (std::size_t a : ctx.dynamicSets) {
      ParticleSet& set = ctx.particles[a];
      const auto& x = set.x();
      auto& pi = set.real(field::pi);
      const auto& alpha = set.real(field::alpha);
      const auto& rhoStar = set.real(field::rhoStar);
      const auto& gradSum = set.vec3(field::gradSum);
      const auto& accel = set.vec3(field::accelP);
      auto& residual = set.real(kResidual);
      const NeighbourList& same = ctx.search.list(a, a);
      const auto& factors = ctx.gradients.of(a, a);
      const double volume = set.particleVolume;
      const std::size_t n = set.size();
      // (A pi)_a = dt^2 [a_a.G_a - V sum_b s_ab a_b.x_ab]; r = (1 - rho~*) - (A pi); error max(-r, 0).
      const double errorSum = parallel::sum<double>(n, [&](std::size_t i) {
        double others = 0.0;
        std::size_t p = same.offset(i);
        for (Index j : same.of(i)) {
          const std::size_t jj = static_cast<std::size_t>(j);
          others += factors[p++] * accel[jj].dot(x[i] - x[jj]);
        }
        const double api = dt2 * (accel[i].dot(gradSum[i]) - volume * others);
        const double r = (1.0 - rhoStar[i]) - api;
        residual[i] = std::max(-r, 0.0);
        pi[i] = std::max(pi[i] - omega * r * alpha[i] / dt2, 0.0);
        return residual[i];
      });
      const double mean = n > 0 ? errorSum / static_cast<double>(n) : 0.0;
      worstMean = std::max(worstMean, mean);
      worstMax = std::max(worstMax, parallel::max(n, 0.0, [&](std::size_t i) { return residual[i]; }));
    }
    stats.iterations = it;
    stats.meanError = 100.0 * worstMean;
    stats.maxError = 100.0 * worstMax;
    if (it >= settings_.minIterations && worstMean <= tolerance) {
      stats.converged = true;
      break;
    }
  }

  computeAccelerations(ctx);
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    auto& v = set.v();
    const auto& accel = set.vec3(field::accelP);
    const auto& pi = set.real(field::pi);
    const auto& density = set.real(field::density);
    auto& pressure = set.real(field::pressure);
    const double rhoMax = set.restDensity;
    parallel::forEach(set.size(), [&](std::size_t i) {
      v[i] += dt * accel[i];
      pressure[i] = pi[i] * density[i] * density[i] / rhoMax;
    });
  }
  return stats;
}

} // namespace poro
