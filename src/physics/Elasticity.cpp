#include "physics/Elasticity.hpp"

#include "core/Parallel.hpp"
#include "physics/FieldNames.hpp"
#include "physics/RotationExtraction.hpp"

#include <algorithm>
#include <stdexcept>

namespace poro {

namespace {
constexpr double kLameFloor = 1e-3; // METHOD.md §8: softening factors stay positive
/// Where the neighbours' elastic blocks weigh at most this times a particle's mass (soft bodies: 0.03-0.33 on the
/// published sets), the preconditioner forms them from the rest moment; where they outweigh it (the fusilli:
/// 300-1,200), their rotations steer the CG, and they are summed pair by pair, as they are where the material
/// softens with saturation (the neighbours' moduli then differ).
constexpr double kNeighbourShareFromRest = 1.0;

bool isElastic(const PorousMaterial* material) { return material && material->youngsModulus > 0.0; }

Mat3 symmetric(const Mat3& a) { return 0.5 * (a + a.transpose()); }

/// P = 2 shear eps + volumetric tr(eps) I.
Mat3 stressOf(const Mat3& eps, double shear, double volumetric) {
  return 2.0 * shear * eps + (volumetric * eps.trace()) * Mat3::Identity();
}

/// F = [sum_t V0_t (x_t - x_s) gradW0^T] L^T of particle s, before its rotation is extracted.
Mat3 deformationGradient(const ElasticRestState& rest, const std::vector<Vec3>& x, std::size_t s) {
  Mat3 deformed = Mat3::Zero();
  for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
    const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
    addOuter(deformed, x[t] - x[s], rest.weightedGradient(pair));
  }
  return deformed * rest.correction(s).transpose();
}

/// The position part's strain of particle s for the deformation gradient f and the rotation r extracted from it.
/// F^ = I + displaced RL^T, eps = sym(F^) - I, with displaced = sum V0_t ((x_t - x_s) - R(X_t - X_s)) gradW0^T.
/// That is deformed - R M^T for the rest moment M = L^-1, so where L inverts M, F^ = F R^T: no second pass.
Mat3 positionStrain(const ElasticRestState& rest, const std::vector<Vec3>& x, const std::vector<Vec3>& restX,
                    std::size_t s, const Mat3& f, const Mat3& r) {
  if (rest.inverts(s)) return symmetric(f * r.transpose()) - Mat3::Identity();
  Mat3 displaced = Mat3::Zero();
  for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
    const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
    addOuter(displaced, (x[t] - x[s]) - r * (restX[t] - restX[s]), rest.weightedGradient(pair));
  }
  return symmetric(displaced * (r * rest.correction(s)).transpose());
}

/// B(g) = shear (|g|^2 I + g g^T) + volumetric g g^T: the block a stress couples back onto one velocity.
Mat3 stiffnessBlock(const Vec3& g, double shear, double volumetric) {
  Mat3 block = (shear * g.squaredNorm()) * Mat3::Identity();
  addOuter(block, (shear + volumetric) * g, g);
  return block;
}
} // namespace

void Elasticity::registerFields(ParticleSet& set) {
  auto& rotation = set.addMat3(field::rotation, Restart);
  // A new set starts unrotated; a restarted one keeps what it read (never all zeros).
  for (Mat3& r : rotation)
    if (r.isZero()) r.setIdentity();
}

template <class F> void Elasticity::Body::forEachStressed(std::size_t n, const F& f) const {
  if (stressed.empty())
    parallel::forEach(n, f);
  else
    parallel::forEach(stressed.size(), [&](std::size_t k) { f(static_cast<std::size_t>(stressed[k])); });
}

bool Elasticity::enabled(const StepContext& ctx) const {
  return std::any_of(ctx.dynamicSets.begin(), ctx.dynamicSets.end(),
                     [&](std::size_t s) { return isElastic(ctx.materials[s]); });
}

void Elasticity::prepare(const StepContext& ctx) {
  ctx_ = &ctx;
  rest_.resize(ctx.particles.size());
  std::size_t used = 0; // bodies are kept from step to step, their arrays refilled in place
  for (std::size_t p = 0; p < ctx.dynamicSets.size(); ++p) {
    const std::size_t s = ctx.dynamicSets[p];
    if (!isElastic(ctx.materials[s])) continue;
    if (used == bodies_.size()) bodies_.emplace_back();
    Body& body = bodies_[used++];
    body.set = s;
    body.part = p;
    const bool rebuilt = rest_[s].update(ctx.particles[s], ctx.kernel);
    prepareBody(ctx, body, rebuilt);
  }
  bodies_.resize(used);
}

void Elasticity::prepareBody(const StepContext& ctx, Body& body, bool restRebuilt) {
  ParticleSet& set = ctx.particles[body.set];
  const PorousMaterial& material = *ctx.materials[body.set];
  const ElasticRestState& rest = rest_[body.set];
  const std::size_t n = set.size();
  const auto& x = set.x();
  const auto& restX = set.vec3(field::restPosition);
  const auto& saturation = set.real(field::saturation);
  auto& rotation = set.mat3(field::rotation);
  const double mu = material.shearModulus();
  const double lambda = material.lameLambda();
  const double volumetricModulus = ctx.compatibility.unitLambdaVolumetricStress ? 1.0 : lambda;
  const double bloating = material.bloating * (ctx.compatibility.lambdaScaledBloating ? lambda : 1.0);
  body.uniformModuli = material.shearSoftening == 0.0 && material.volumeSoftening == 0.0;
  body.mu = mu;
  body.volumetricModulus = volumetricModulus;
  body.shearSoftening = material.shearSoftening;
  body.volumeSoftening = material.volumeSoftening;
  body.saturation = saturation.data();

  body.stress.resize(n);
  body.stressOfPositions = true;
  body.stressed.clear();
  const std::size_t owned = ctx.owned(body.set);
  if (owned < n) { // ghosts: rest neighbour lists are symmetric, so a ghost is read if an own particle is in its list
    for (std::size_t s = 0; s < owned; ++s) body.stressed.push_back(static_cast<Index>(s));
    for (std::size_t s = owned; s < n; ++s)
      for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair)
        if (static_cast<std::size_t>(rest.neighbour(pair)) < owned) {
          body.stressed.push_back(static_cast<Index>(s));
          break;
        }
  }
  body.hourglass.prepare(rest, restX, material.hourglassControl * mu, n, body.stressed, restRebuilt);
  body.forEachStressed(n, [&](std::size_t s) {
    // Rotation first (METHOD.md §6.5.2).
    const Mat3 f = deformationGradient(rest, x, s);
    if (body.hourglass.enabled()) body.hourglass.setGradient(s, f);
    rotation[s] = extractRotation(f, rotation[s]);
    const Mat3 rl = rotation[s] * rest.correction(s);
    const Mat3 strain = positionStrain(rest, x, restX, s, f, rotation[s]);
    const Mat3 stress =
        stressOf(strain, body.shear(s), body.volumetric(s)) - (bloating * saturation[s]) * Mat3::Identity();
    body.stress[s] = rest.volume(s) * (stress * rl);
  });
}

double Elasticity::Body::shear(std::size_t s) const {
  return std::max(1.0 + shearSoftening * saturation[s], kLameFloor) * mu;
}

double Elasticity::Body::volumetric(std::size_t s) const {
  return std::max(1.0 + volumeSoftening * saturation[s], kLameFloor) * volumetricModulus;
}

Mat3 Elasticity::strain(std::size_t s, std::size_t i) const {
  // Formed again rather than kept for every particle: prepare() has left the rotation it was formed with.
  for (const Body& body : bodies_) {
    if (body.set != s) continue;
    const ParticleSet& set = ctx_->particles[s];
    const ElasticRestState& rest = rest_[s];
    const auto& x = set.x();
    return positionStrain(rest, x, set.vec3(field::restPosition), i, deformationGradient(rest, x, i),
                          set.mat3(field::rotation)[i]);
  }
  return Mat3::Zero();
}

Vec3 Elasticity::force(const Body& body, const std::vector<Mat3>& weighted, std::size_t s) const {
  // The M_s part of every pair sums to V0_s M_s G0_s.
  const ElasticRestState& rest = rest_[body.set];
  Vec3 sum = Vec3::Zero();
  for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair)
    sum += weighted[static_cast<std::size_t>(rest.neighbour(pair))] * rest.gradient(pair);
  return weighted[s] * rest.gradientSum(s) + rest.volume(s) * sum;
}

void Elasticity::addApply(const linalg::BlockVector& u, const linalg::BlockVector& au) const {
  const double dt = ctx_->dt;
  for (const Body& body : bodies_) {
    const ElasticRestState& rest = rest_[body.set];
    const Vec3* v = u[body.part].data;
    Vec3* out = au[body.part].data;
    const std::size_t n = u[body.part].size;
    const auto& rotation = ctx_->particles[body.set].mat3(field::rotation);
    body.stressOfPositions = false;
    // All stresses first, then the forces (METHOD.md §6.5.4). The forces of own particles read the stresses of their
    // rest neighbours, ghosts among them in a parallel run: those are formed here too, from the ghosts' velocities
    // that follow the own ones in the storage (GhostExchange.hpp; the set's size counts both).
    body.forEachStressed(ctx_->particles[body.set].size(), [&](std::size_t s) {
      Mat3 gradient = Mat3::Zero();
      for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
        const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
        addOuter(gradient, v[t] - v[s], rest.weightedGradient(pair));
      }
      const Mat3 rl = rotation[s] * rest.correction(s);
      const Mat3 eps = symmetric(dt * gradient * rl.transpose());
      if (body.hourglass.enabled()) body.hourglass.setGradient(s, gradient * rest.correction(s).transpose());
      body.stress[s] = rest.volume(s) * (stressOf(eps, body.shear(s), body.volumetric(s)) * rl);
    });
    parallel::forEach(n, [&](std::size_t s) { out[s] -= dt * force(body, body.stress, s); });
    if (body.hourglass.enabled()) body.hourglass.addForces(v, n, -dt * dt, out); // -dt f(dt u) = dt^2 K u
  }
}

void Elasticity::addDiagonal(const linalg::BlockDiagonal& d) const {
  const double dt2 = ctx_->dt * ctx_->dt;
  for (const Body& body : bodies_) {
    const ElasticRestState& rest = rest_[body.set];
    const auto& rotation = ctx_->particles[body.set].mat3(field::rotation);
    const double mass = ctx_->particles[body.set].mass;
    Mat3* out = d[body.part].data;
    const std::size_t first = d[body.part].first;
    parallel::forEach(d[body.part].size, [&](std::size_t k) {
      const std::size_t s = first + k;
      // D_s = dt^2 [V0_s B_s(G_s) + V0_s^2 sum_t V0_t B_t(g_ts)], G_s = sum_t V0_t g_st (METHOD.md §6.5.8).
      const double v0 = rest.volume(s);
      const Mat3 moment = rest.neighbourMoment(s);
      // The neighbours' sum is at most dt^2 V0_s^2 (2 k_mu mu + k_lambda lambda) tr(S_s) in norm.
      const double share = dt2 * v0 * v0 * (2.0 * body.shear(s) + body.volumetric(s)) * moment.trace() / mass;
      Mat3 neighbours;
      if (body.uniformModuli && share <= kNeighbourShareFromRest) {
        // With the neighbours' rotations taken as s's own (their moduli are s's: the material does not soften): B is
        // rotation-covariant, B(R g) = R B(g) R^T, so the sum is mu tr(S_s) I + (mu + lambda) R_s S_s R_s^T, S_s fixed
        // at rest. Exact for a body that turns as a whole; elsewhere off by 4 sin(delta / 2) share m at most for
        // neighbours turned by delta against s, which the mass outweighs: the CG reaches the same tolerance.
        const Mat3& r = rotation[s];
        neighbours = (body.shear(s) + body.volumetric(s)) * (r * moment * r.transpose());
        neighbours.diagonal().array() += body.shear(s) * moment.trace();
      } else {
        // B is quadratic in g, so V0_t B_t(g_ts) = B_t(V0_t g_ts) / V0_t with the stored weighted gradients; the
        // identity parts of the blocks are summed as one scalar.
        neighbours.setZero();
        double identityPart = 0.0;
        for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
          const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
          const Vec3 gts = (rotation[t] * rest.correction(t)) * rest.weightedGradient(pair);
          const double inverseVolume = rest.inverseVolume(t);
          identityPart += body.shear(t) * inverseVolume * gts.squaredNorm();
          addOuter(neighbours, ((body.shear(t) + body.volumetric(t)) * inverseVolume) * gts, gts);
        }
        neighbours.diagonal().array() += identityPart;
      }
      const Vec3 g = (rotation[s] * rest.correction(s)) * rest.gradientSum(s);
      out[k] += dt2 * (v0 * stiffnessBlock(g, body.shear(s), body.volumetric(s)) + v0 * v0 * neighbours);
      if (body.hourglass.enabled()) out[k].diagonal().array() += dt2 * body.hourglass.diagonal(s);
    });
  }
}

void Elasticity::addRhs(const linalg::BlockVector& b) const {
  const double dt = ctx_->dt;
  for (const Body& body : bodies_) {
    if (!body.stressOfPositions) throw std::logic_error("Elasticity::addRhs after addApply: prepare() again first");
    Vec3* out = b[body.part].data;
    parallel::forEach(b[body.part].size, [&](std::size_t s) { out[s] += dt * force(body, body.stress, s); });
    if (body.hourglass.enabled())
      body.hourglass.addForces(ctx_->particles[body.set].x().data(), b[body.part].size, dt, out);
  }
}

} // namespace poro
