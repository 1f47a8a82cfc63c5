#include "physics/PressureSolver.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/VolumeFactors.hpp"
#include "physics/WallContact.hpp"
#include "sph/BoundaryVolume.hpp"

#include <algorithm>
#include <functional>
#include <limits>

namespace poro {

namespace {
/// The first sweep Chebyshev extrapolates. The sweeps before it are plain relaxed Jacobi, so a step that converges
/// within them (most steps of a moving flow) is solved exactly as without acceleration, with Jacobi's smaller
/// single-particle errors; the slowly converging steps (water at rest, deep pools, impacts) are accelerated.
constexpr int kFirstChebyshevSweep = 4;

/// Chebyshev weight of sweep k (Golub and Varga 1961) for the convergence factor estimate rho: 1 before the
/// first accelerated sweep, 2/(2 - rho^2) at it, then 4/(4 - rho^2 w_{k-1}); it tends to 2/(1 + sqrt(1 - rho^2)).
double chebyshevWeight(int sweep, double rho, double previous) {
  if (sweep < kFirstChebyshevSweep) return 1.0;
  if (sweep == kFirstChebyshevSweep) return 2.0 / (2.0 - rho * rho);
  return 4.0 / (4.0 - rho * rho * previous);
}

/// A dynamic neighbour set of set a with its coupling and per-pair gradient factors.
struct PartnerView {
  const NeighbourList* list;
  const std::vector<Vec3>* x;
  const std::vector<PairFactor>* factors;
  const std::int64_t* objectB;
  SetCoupling coupling;
  const std::vector<Vec3>* v;
  const std::vector<Vec3>* accel;
  const std::vector<double>* pi;
};

std::vector<PartnerView> partnersOf(const StepContext& ctx, std::size_t a) {
  std::vector<PartnerView> result;
  for (const SetCoupling& c : couplingsOf(ctx, a)) {
    const ParticleSet& b = ctx.particles[c.other];
    result.push_back({&ctx.search.list(a, c.other), &b.x(), &ctx.gradients.of(a, c.other),
                      b.integer(field::objectId).data(), c, &b.v(), &b.vec3(field::accelP), &b.real(field::pi)});
  }
  return result;
}

/// Boundary neighbour data of one dynamic set, gathered once per call.
struct WallView {
  const NeighbourList* list;
  const std::vector<Vec3>* x;
  const std::vector<Vec3>* v;
  const std::vector<double>* volume;
  const std::vector<PairFactor>* factors;
};

std::vector<WallView> wallsOf(const StepContext& ctx, std::size_t a) {
  std::vector<WallView> walls;
  for (std::size_t k : ctx.boundarySets) {
    const ParticleSet& b = ctx.particles[k];
    walls.push_back({&ctx.search.list(a, k), &b.x(), &b.v(), &b.real(kBoundaryVolumeField), &ctx.gradients.of(a, k)});
  }
  return walls;
}

/// Pairs of particles [0, i) with their dynamic partners, plus i: the work before particle i in a sweep's loops.
std::size_t pairsBefore(const std::vector<PartnerView>& partners, std::size_t i) {
  std::size_t work = i;
  for (const PartnerView& p : partners)
    if (p.list->particles() > 0) work += p.list->offset(i);
  return work;
}

/// sum_b f(a<-b) V s_ab (q_b . x_ab) over the dynamic partners of particle i, for a per-particle vector
/// field q (velocities for Eq. 6, pressure accelerations for the operator).
double partnerProjection(const std::vector<PartnerView>& partners, const Vec3& xi, std::int64_t objectI, std::size_t i,
                         bool velocities) {
  double sum = 0.0;
  for (const PartnerView& p : partners) {
    if (p.coupling.factor == 0.0 && p.coupling.ownFactor == 0.0) continue;
    const std::vector<Vec3>& q = velocities ? *p.v : *p.accel;
    const auto& xb = *p.x;
    const auto& s = *p.factors;
    std::size_t pair = p.list->offset(i);
    double part = 0.0;
    if (p.coupling.byObject) {
      for (Index jIndex : p.list->of(i)) {
        const std::size_t j = static_cast<std::size_t>(jIndex);
        part += p.coupling.factorOf(objectI == p.objectB[j]) * s[pair++] * q[j].dot(xi - xb[j]);
      }
    } else {
      for (Index jIndex : p.list->of(i)) {
        const std::size_t j = static_cast<std::size_t>(jIndex);
        part += s[pair++] * q[j].dot(xi - xb[j]);
      }
      part *= p.coupling.factor;
    }
    sum += part;
  }
  return sum;
}

/// The sum and the largest of a set's residuals in one pass over them (parallel::sum's blocking: the same sum).
struct ResidualSummary {
  double sum = 0.0;
  double max = 0.0; // residuals are compressions, >= 0
  ResidualSummary& operator+=(const ResidualSummary& other) {
    sum += other.sum;
    max = std::max(max, other.max);
    return *this;
  }
};

/// Particles of set a a sweep updates, over all ranks: the fixed ones keep pi = 0 and count for nothing.
double activeParticles(const StepContext& ctx, std::size_t a) {
  const std::int64_t* fixed = fixedFlags(ctx.particles[a]);
  const std::size_t n = ctx.owned(a);
  const std::size_t active =
      fixed ? parallel::sum<std::size_t>(n, [&](std::size_t i) -> std::size_t { return fixed[i] ? 0 : 1; }) : n;
  return ctx.sumOverRanks(static_cast<double>(active));
}

/// p = pi rho^2 / rho^max (METHOD.md §6.7), in one place: formPressures() must give solve()'s values to the bit.
double pressureOf(double pi, double density, double rhoMax) { return pi * density * density / rhoMax; }
} // namespace

void PressureSolver::registerFields(ParticleSet& set, const CompatibilitySettings& compatibility) {
  set.addReal(field::pi, Restart);
  set.addReal(field::pressure, Output);
  set.addVec3(field::accelP, compatibility.setSequentialPressure ? Restart : Scratch);
  set.addVec3(sweepStateField);
}

void PressureSolver::predictDensities(const StepContext& ctx) const {
  for (std::size_t a : ctx.dynamicSets) {
    ParticleSet& set = ctx.particles[a];
    const auto& x = set.x();
    const auto& v = set.v();
    const auto& object = set.integer(field::objectId);
    const auto& rhoTilde = set.real(field::rhoTilde);
    const auto& gradSum = set.vec3(field::gradSum);
    auto& state = set.vec3(sweepStateField);
    const double volume = set.particleVolume;
    const auto partners = partnersOf(ctx, a);
    const auto walls = wallsOf(ctx, a);
    const double dt = ctx.dt;
    parallel::forEach(set.size(), [&](std::size_t i) {
      // sum_b f V (v_a - v_b).gradW = v_a.G_a - V sum_b f s_ab v_b.x_ab  (G holds the v_a part of every term)
      const double others = partnerProjection(partners, x[i], object[i], i, true);
      double change = v[i].dot(gradSum[i]) - volume * others;
      for (const WallView& w : walls) {
        std::size_t q = w.list->offset(i);
        for (Index k : w.list->of(i)) {
          const std::size_t kk = static_cast<std::size_t>(k);
          change -= (*w.volume)[kk] * (*w.factors)[q++] * (*w.v)[kk].dot(x[i] - (*w.x)[kk]);
        }
      }
      state[i][kPredictedDensity] = rhoTilde[i] + dt * change;
    });
  }
  predictWallShares(ctx);
}

void PressureSolver::computeAccelerations(const StepContext& ctx, const std::vector<std::size_t>& sets) const {
  // a^p_a = -pi_a G_a - V sum_b h_ab pi_b s_ab x_ab: the pi_a part of every pair and wall term is pi_a G_a;
  // h_ab is 0 across phases (Eq. 7 line 2, walls are one-sided), f(b<-a) m_b/m_a within one (Eq. 7, 8).
  for (std::size_t a : sets) {
    ParticleSet& set = ctx.particles[a];
    const auto& x = set.x();
    const auto& pi = set.real(field::pi);
    const auto& object = set.integer(field::objectId);
    const auto& gradSum = set.vec3(field::gradSum);
    auto& accel = set.vec3(field::accelP);
    const std::int64_t* fixed = fixedFlags(set);
    const double volume = set.particleVolume;
    const bool contact = hasWallContact(set);
    const double* kappa = contact ? set.real(field::contactPressure).data() : nullptr;
    const Vec3* wallGradient = contact ? set.vec3(field::wallGradient).data() : nullptr;
    auto partners = partnersOf(ctx, a);
    partners.erase(std::remove_if(partners.begin(), partners.end(),
                                  [](const PartnerView& p) {
                                    return p.coupling.coupling == 0.0 && p.coupling.ownCoupling == 0.0;
                                  }),
                   partners.end());
    const auto work = [&](std::size_t i) { return pairsBefore(partners, i); };
    parallel::forEachBalanced(ctx.owned(a), work, [&](std::size_t i) {
      if (fixed && fixed[i]) {
        accel[i].setZero();
        return;
      }
      Vec3 sum = Vec3::Zero();
      for (const PartnerView& p : partners) {
        const auto& piB = *p.pi;
        const auto& xb = *p.x;
        const auto& s = *p.factors;
        std::size_t pair = p.list->offset(i);
        if (p.coupling.byObject) {
          for (Index jIndex : p.list->of(i)) {
            const std::size_t j = static_cast<std::size_t>(jIndex);
            const double h = p.coupling.couplingOf(object[i] == p.objectB[j]);
            sum += (h * piB[j] * s[pair++]) * (x[i] - xb[j]);
          }
        } else { // one h for every pair: no object ids to load
          const double h = p.coupling.coupling;
          for (Index jIndex : p.list->of(i)) {
            const std::size_t j = static_cast<std::size_t>(jIndex);
            sum += (h * piB[j] * s[pair++]) * (x[i] - xb[j]);
          }
        }
      }
      accel[i] = -pi[i] * gradSum[i] - volume * sum;
      if (contact) accel[i] -= kappa[i] * wallGradient[i]; // WallContact.hpp
    });
  }
  ctx.refreshGhosts({field::accelP}); // the sweeps read the neighbours' a^p
}

std::vector<std::vector<double>> PressureSolver::applyOperator(const StepContext& ctx) const {
  computeAccelerations(ctx, ctx.dynamicSets);
  return operatorOfStoredAccelerations(ctx);
}

std::vector<std::vector<double>> PressureSolver::operatorOfStoredAccelerations(const StepContext& ctx) const {
  std::vector<std::vector<double>> result;
  for (std::size_t a : ctx.dynamicSets) {
    const ParticleSet& set = ctx.particles[a];
    const auto& x = set.x();
    const auto& object = set.integer(field::objectId);
    const auto& gradSum = set.vec3(field::gradSum);
    const auto& accel = set.vec3(field::accelP);
    const auto partners = partnersOf(ctx, a);
    std::vector<double> api(set.size());
    const auto work = [&](std::size_t i) { return pairsBefore(partners, i); };
    parallel::forEachBalanced(set.size(), work, [&](std::size_t i) {
      const double others = partnerProjection(partners, x[i], object[i], i, false);
      api[i] = ctx.dt * ctx.dt * (accel[i].dot(gradSum[i]) - set.particleVolume * others);
    });
    result.push_back(std::move(api));
  }
  return result;
}

void PressureSolver::warmStart(const StepContext& ctx) const {
  // The reference cap bounds pi dt^2 (its stored pressure) by 2.5e-4 m^2 before rescaling to this step's dt.
  constexpr double kReferenceCap = 2.5e-4; // [m^2]
  const bool capped = ctx.compatibility.cappedPressureWarmStart;
  const double dt = ctx.dt;
  const double previousDt = ctx.previousDt > 0.0 ? ctx.previousDt : dt;
  const double factor = settings_.warmStart;
  for (std::size_t a : ctx.dynamicSets) { // Fixed particles keep pi = 0
    ParticleSet& set = ctx.particles[a];
    auto& pi = set.real(field::pi);
    const auto& state = set.vec3(sweepStateField);
    const std::int64_t* fixed = fixedFlags(set);
    parallel::forEach(set.size(), [&](std::size_t i) {
      if (!(state[i][kPredictedDensity] > 1.0) || (fixed && fixed[i]))
        pi[i] = 0.0;
      else if (capped)
        pi[i] = factor * std::min(pi[i] * previousDt * previousDt, kReferenceCap) / (dt * dt);
      else
        pi[i] *= factor;
    });
  }
  warmStartContactPressure(ctx, factor);
  ctx.refreshGhosts({field::pi, field::contactPressure}); // rho* of a ghost near the halo's edge is not its owner's
}

PressureStats PressureSolver::iterate(const StepContext& ctx, const std::vector<std::size_t>& sets) const {
  const double dt2 = ctx.dt * ctx.dt;
  const double omega = settings_.relaxation;
  const double tolerance = settings_.maxDensityError / 100.0;
  const auto bound = [](double percent) {
    return percent > 0.0 ? percent / 100.0 : std::numeric_limits<double>::infinity();
  };
  const double particleBound = bound(settings_.maxParticleDensityError);
  const double skeletonBound = bound(settings_.maxSkeletonParticleDensityError);
  PressureStats stats;
  std::vector<double> active; // by position in `sets`: fixed flags do not change within a solve
  for (std::size_t a : sets) active.push_back(activeParticles(ctx, a));
  double weight = 1.0;
  for (int it = 1; it <= settings_.maxIterations; ++it) {
    if (settings_.chebyshev) weight = chebyshevWeight(it, settings_.spectralRadius, weight);
    computeAccelerations(ctx, sets);
    // Residuals use a^p of the sweep's start only, so updating pi set by set is pure Jacobi across sets.
    double worstMean = 0.0, worstMax = 0.0, worstSkeleton = 0.0;
    for (std::size_t k = 0; k < sets.size(); ++k) {
      const std::size_t a = sets[k];
      ParticleSet& set = ctx.particles[a];
      const auto& x = set.x();
      const auto& object = set.integer(field::objectId);
      const auto& gradSum = set.vec3(field::gradSum);
      const auto& accel = set.vec3(field::accelP);
      auto& state = set.vec3(sweepStateField);
      auto& pi = set.real(field::pi);
      const auto& alpha = set.real(field::alpha);
      const std::int64_t* fixed = fixedFlags(set);
      const double volume = set.particleVolume;
      const auto partners = partnersOf(ctx, a);
      const std::size_t n = ctx.owned(a); // a parallel run's ghosts get their pi from their owners below
      const bool contact = hasWallContact(set);
      double* kappa = contact ? set.real(field::contactPressure).data() : nullptr;
      const Vec3* wallGradient = contact ? set.vec3(field::wallGradient).data() : nullptr;
      const double* wallStar = contact ? set.real(field::wallShareStar).data() : nullptr;
      const double* wallLimit = contact ? set.real(field::wallContactLimit).data() : nullptr;
      // (A pi)_a = dt^2 [a_a.G_a - V sum_b f s_ab a_b.x_ab]; r = (1 - rho~*) - (A pi); error max(-r, 0).
      // The sweep in a loop of its own: inside parallel::sum, whose blocks of 4096 are handed out whole, a set of
      // 12,696 particles gave one thread 8,192 and the other 4,504 (the sum below is the same, bit for bit).
      const auto work = [&](std::size_t i) { return pairsBefore(partners, i); };
      parallel::forEachBalanced(n, work, [&](std::size_t i) {
        double& residual = state[i][kResidual];
        if (fixed && fixed[i]) {
          residual = 0.0;
          return;
        }
        const double others = partnerProjection(partners, x[i], object[i], i, false);
        const double api = dt2 * (accel[i].dot(gradSum[i]) - volume * others);
        const double r = (1.0 - state[i][kPredictedDensity]) - api;
        residual = std::max(-r, 0.0);
        const double jacobi = std::max(pi[i] - omega * r * alpha[i] / dt2, 0.0);
        // Chebyshev: pi^{k+1} = max(w (jacobi - pi^{k-1}) + pi^{k-1}, 0); the same fixed point as Jacobi's. Only
        // where pi was and stays positive: extrapolating a particle that just left or entered the clamped set
        // overshoots it (measured at r = 1 cm: larger single-particle errors, no fewer sweeps).
        double& previousPi = state[i][kPreviousPi];
        const double older = previousPi;
        previousPi = pi[i];
        const bool extrapolate = weight != 1.0 && older > 0.0 && jacobi > 0.0;
        pi[i] = extrapolate ? std::max(weight * (jacobi - older) + older, 0.0) : jacobi;
        if (contact) { // the wall-share constraint D* <= D^max with the same a^p (WallContact.hpp)
          const double g2 = wallGradient[i].squaredNorm();
          const double rc = (wallLimit[i] - wallStar[i]) - dt2 * accel[i].dot(wallGradient[i]);
          residual = std::max(residual, -rc);
          kappa[i] = g2 > 0.0 ? std::max(kappa[i] - omega * rc / (dt2 * g2), 0.0) : 0.0;
        }
      });
      const ResidualSummary residuals = parallel::sum<ResidualSummary>(n, [&](std::size_t i) {
        const double r = state[i][kResidual];
        return ResidualSummary{r, r};
      });
      const double mean = active[k] > 0 ? ctx.sumOverRanks(residuals.sum) / active[k] : 0.0;
      worstMean = std::max(worstMean, mean);
      const double largest = ctx.maxOverRanks(residuals.max);
      worstMax = std::max(worstMax, largest);
      if (ctx.materials[a]) worstSkeleton = std::max(worstSkeleton, largest);
    }
    ctx.refreshGhosts({field::pi, field::contactPressure});
    stats.iterations = it;
    stats.meanError = 100.0 * worstMean;
    stats.maxError = 100.0 * worstMax;
    stats.maxSkeletonError = 100.0 * worstSkeleton;
    if (it >= settings_.minIterations && worstMean <= tolerance && worstMax <= particleBound &&
        worstSkeleton <= skeletonBound) {
      stats.converged = true;
      break;
    }
  }
  computeAccelerations(ctx, sets);
  return stats;
}

PressureStats PressureSolver::solve(const StepContext& ctx) const {
  warmStart(ctx);
  PressureStats stats;
  if (ctx.compatibility.setSequentialPressure) {
    // Fluid first, then the porous sets by material; materials point into one vector in file order.
    std::vector<std::size_t> order = ctx.dynamicSets;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const PorousMaterial* ma = ctx.materials[a];
      const PorousMaterial* mb = ctx.materials[b];
      if (!ma || !mb) return !ma && mb;
      return std::less<const PorousMaterial*>()(ma, mb);
    });
    stats.converged = true;
    for (std::size_t a : order) {
      const PressureStats one = iterate(ctx, {a});
      stats.iterations = std::max(stats.iterations, one.iterations);
      stats.meanError = std::max(stats.meanError, one.meanError);
      stats.maxError = std::max(stats.maxError, one.maxError);
      stats.maxSkeletonError = std::max(stats.maxSkeletonError, one.maxSkeletonError);
      stats.converged = stats.converged && one.converged;
    }
    // The finish of METHOD.md §6.7: a^p from the final pi of every set (solid-solid forces across materials
    // stay reciprocal), used for the velocities and kept as the next step's lagged a^p.
    computeAccelerations(ctx, ctx.dynamicSets);
  } else {
    stats = iterate(ctx, ctx.dynamicSets);
  }

  const double dt = ctx.dt;
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
      pressure[i] = pressureOf(pi[i], density[i], rhoMax);
    });
  }
  return stats;
}

void PressureSolver::formPressures(ParticleSystem& particles, const std::vector<std::size_t>& sets) {
  for (std::size_t a : sets) {
    ParticleSet& set = particles[a];
    const auto& pi = set.real(field::pi);
    const auto& density = set.real(field::density);
    auto& pressure = set.real(field::pressure);
    const double rhoMax = set.restDensity;
    parallel::forEach(set.size(), [&](std::size_t i) { pressure[i] = pressureOf(pi[i], density[i], rhoMax); });
  }
}

std::pair<std::size_t, std::size_t> PressureSolver::mostCompressed(const ParticleSystem& particles,
                                                                   const std::vector<std::size_t>& sets) {
  std::pair<std::size_t, std::size_t> worst{sets.empty() ? 0 : sets.front(), 0};
  double largest = -1.0;
  for (std::size_t s : sets) {
    const auto& state = particles[s].vec3(sweepStateField);
    for (std::size_t i = 0; i < state.size(); ++i)
      if (state[i][kResidual] > largest) {
        largest = state[i][kResidual];
        worst = {s, i};
      }
  }
  return worst;
}

} // namespace poro
