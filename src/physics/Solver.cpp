#include "physics/Solver.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "core/StopSignals.hpp"
#include "physics/Buoyancy.hpp"
#include "physics/CapillaryAdhesion.hpp"
#include "physics/Densities.hpp"
#include "physics/Elasticity.hpp"
#include "physics/FieldNames.hpp"
#include "physics/NumericalHealth.hpp"
#include "physics/PoreFluidDensityBias.hpp"
#include "physics/PorousDrag.hpp"
#include "physics/RigidBodyForces.hpp"
#include "physics/StartDensity.hpp"
#include "physics/TimeStepSize.hpp"
#include "physics/Viscosity.hpp"
#include "physics/VolumeFactors.hpp"
#include "physics/WallContact.hpp"
#include "physics/XsphSmoothing.hpp"
#include "sph/BoundaryVolume.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>

namespace poro {

namespace {

/// Implicit terms in the order they add to the operator (STYLE.md §5: registration is an explicit list).
std::vector<std::unique_ptr<ImplicitTerm>> makeImplicitTerms() {
  std::vector<std::unique_ptr<ImplicitTerm>> terms;
  terms.push_back(std::make_unique<Viscosity>());
  terms.push_back(std::make_unique<Elasticity>());
  terms.push_back(std::make_unique<PorousDrag>());
  terms.push_back(std::make_unique<CapillaryAdhesion>());
  terms.push_back(std::make_unique<Buoyancy>());
  return terms;
}

std::string formatDuration(double seconds) {
  // Beyond a year of wall time the figure says only that (and a huge quotient must not overflow the rounding).
  constexpr double kYear = 365.0 * 24 * 3600;
  if (!(seconds < kYear)) return "more than a year";
  const long long s = std::llround(std::max(seconds, 0.0));
  std::ostringstream out;
  out << s / 3600 << ':' << std::setw(2) << std::setfill('0') << (s / 60) % 60 << ':' << std::setw(2)
      << std::setfill('0') << s % 60;
  return out.str();
}

/// The ranks' share of a parallel run for its closing summary: load, the exchanges' share of the time loop and the
/// balance over the run (collective: every rank calls it).
std::string rankSummary(const GhostExchange& ranks, double loopSeconds) {
  const GhostExchange::Load load = ranks.load();
  const double n = static_cast<double>(ranks.ranks());
  const auto meanAndLargest = [&](double value, int decimals, const char* unit) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(decimals) << ranks.sum(value) / n << unit << " mean, " << ranks.max(value)
        << unit << " largest";
    return out.str();
  };
  const double share = loopSeconds > 0.0 ? 100.0 * load.seconds / loopSeconds : 0.0;
  const double migrating = loopSeconds > 0.0 ? 100.0 * load.migrationSeconds / loopSeconds : 0.0;
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << "Ranks: " << ranks.ranks() << "; particles per rank "
      << meanAndLargest(static_cast<double>(load.particles), 0, "") << "; ghosts per rank "
      << meanAndLargest(static_cast<double>(load.ghosts), 0, "")
      << "\n  halo exchanges and reductions: " << meanAndLargest(share, 1, " %")
      << " of a rank's time loop, of which migrations and new halos " << meanAndLargest(migrating, 1, " %")
      << "\n  imbalance (heaviest rank's weight over the mean): " << 100.0 * load.meanImbalance
      << " % mean over the migrations, " << 100.0 * load.largestImbalance << " % largest; re-partitioned "
      << load.repartitions << " times\n";
  return out.str();
}

} // namespace

Solver::Solver(ParticleSystem particles, const FluidProperties& fluid, std::vector<PorousMaterial> materials,
               const SolverSettings& settings, const TimeControl& control, const RunState& start,
               std::vector<ObjectMotion> wallMotions, std::vector<RigidBody::Spec> rigidBodies, GhostExchange* ghosts)
    : particles_(std::move(particles)), fluid_(fluid), materials_(std::move(materials)), settings_(settings),
      control_(control), state_(start), kernel_(particles_.supportRadius()),
      search_(particles_.supportRadius(), settings.searchSkin * particles_.supportRadius()),
      implicit_(settings.implicit, makeImplicitTerms()), pressure_(settings.pressure),
      wallMotions_(std::move(wallMotions)), flatWallShare_(flatWallShare(kernel_, particles_.spacing())) {
  ghosts_ = ghosts;
  hasRigidBodies_ = !rigidBodies.empty();
  if (settings_.threads > 0) parallel::setThreads(settings_.threads);
  const double volume = particles_.particleVolume();
  if (settings_.pressure.latticeCorrectedPoreFluid) poreFluidBias_.emplace(kernel_, volume);
  const bool adhesion = std::any_of(materials_.begin(), materials_.end(),
                                    [](const PorousMaterial& m) { return m.capillaryStrength > 0.0; });
  if (settings_.implicit.adhesionFadesInFullPores && adhesion) poreFill_.emplace(kernel_, volume);
  setMaterials_.assign(particles_.size(), nullptr);
  std::size_t fluidSets = 0;
  for (std::size_t s = 0; s < particles_.size(); ++s) {
    ParticleSet& set = particles_[s];
    set.particleVolume = volume;
    switch (set.kind()) {
    case SetKind::Fluid:
      set.restDensity = fluid_.density;
      set.mass = fluid_.density * volume;
      registerDensityFields(set);
      registerSolveFields(set);
      dynamicSets_.push_back(s);
      ++fluidSets;
      break;
    case SetKind::Boundary:
      setUpBoundarySet(set);
      boundarySets_.push_back(s);
      break;
    case SetKind::Porous: {
      auto material = std::find_if(materials_.begin(), materials_.end(),
                                   [&](const PorousMaterial& m) { return m.name == set.name(); });
      if (material == materials_.end())
        throw InputError("porous particle set '" + set.name() + "': no such material in constant/porosityProperties");
      set.particleVolume = volume;
      setUpPorousSet(set, *material);
      auto& id = set.integer(field::materialId);
      std::fill(id.begin(), id.end(), static_cast<std::int64_t>(material - materials_.begin()));
      setMaterials_[s] = &*material;
      dynamicSets_.push_back(s);
      break;
    }
    }
  }
  if (fluidSets > 1) throw InputError("more than one fluid particle set; PoroSPH simulates one fluid");
  // A run from step 0 starts with controlDict's deltaT: a rewritten 0/ records the step of the run before.
  if (state_.step == 0 || state_.nextDeltaT <= 0.0) state_.nextDeltaT = control_.deltaT;
  for (const ObjectMotion& m : wallMotions_) {
    std::size_t n = 0;
    double reach = 0.0; // the largest distance of the body's particles from its rotation axis
    for (std::size_t k : boundarySets_) {
      const auto& object = particles_[k].integer(field::objectId);
      const auto& rest = particles_[k].vec3(field::restPosition);
      for (std::size_t i = 0; i < object.size(); ++i) {
        if (object[i] != m.objectId) continue;
        ++n;
        reach = std::max(reach, m.motion.distanceFromAxis(rest[i]));
      }
    }
    if (ghosts_) { // the body's particles are spread over the ranks
      n = static_cast<std::size_t>(ghosts_->sum(static_cast<double>(n)));
      reach = ghosts_->max(reach);
    }
    wallReach_.push_back(reach);
    if (n == 0)
      throw InputError(m.where + ": region '" + m.region + "' has a motion, but the walls of the start time " +
                       "directory hold no particle of it (object id " + std::to_string(m.objectId) +
                       "); run sampleParticles again (it rewrites 0/) and start from 0");
  }
  setUpRigidBodies(std::move(rigidBodies));
  implicit_.collectWallReactions(!rigidBodies_.empty());
  placeWalls(state_.time, state_.nextDeltaT);
  if (ghosts_) { // a restart reads the origins back, so it keeps the skin (and migrates) where the run it continues did
    for (std::size_t s = 0; s < particles_.size(); ++s) {
      const bool restart = particles_[s].has(field::searchOrigin);
      auto& origin = particles_[s].addVec3(field::searchOrigin, Restart);
      if (!restart) std::fill(origin.begin(), origin.end(), Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
    }
    computeWallVolumesWithGhosts();
  }
  updateDomain();
  checkStartPositions();
}

void Solver::updateDomain() {
  if (settings_.health.domain) {
    domain_ = settings_.health.domain;
    return;
  }
  const auto overRanks = [this](Vec3& lo, Vec3& hi) { // one reduction: the largest of hi and of -lo
    const std::vector<double> all = ghosts_->gather({-lo.x(), -lo.y(), -lo.z(), hi.x(), hi.y(), hi.z()});
    for (std::size_t k = 0; k + 6 <= all.size(); k += 6)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], -all[k + a]);
        hi[a] = std::max(hi[a], all[k + 3 + a]);
      }
  };
  std::vector<long long> rigid; // rigid bodies are checked against the domain, so they do not make it
  for (const RigidBody& body : rigidBodies_) rigid.push_back(body.objectId());
  domain_ = wallDomain(particles_, boundarySets_, sweptByRotatingWalls(),
                       ghosts_ ? std::function<void(Vec3&, Vec3&)>(overRanks) : nullptr, rigid);
}

void Solver::checkStartPositions() {
  if (!domain_) return;
  const auto outside = findOutside(particles_, dynamicSets_, *domain_);
  if (outside.empty()) return;
  std::ostringstream msg;
  msg << std::setprecision(10);
  for (std::size_t k = 0; k < outside.size(); ++k) {
    const std::string& file = particles_[outside[k].set].source;
    msg << (k ? "; " : "") << (file.empty() ? "" : file + ": ")
        << describe(particles_, {outside[k]}, [&](std::size_t s, std::size_t i) { return particles_[s].x()[i]; });
  }
  msg << " outside the domain " << describeDomain() << ", at the start (time " << state_.time << " s, step "
      << state_.step << ")";
  if (settings_.health.leavingDomain == HealthAction::Warn) {
    outsideReported_ = count(outside);
    log::warning(msg.str() + " (health.leavingDomain warn: they stay in the run).");
    return;
  }
  msg << ". No run writes particles there unless health.leavingDomain is warn (they stay) or stop (it stops "
         "there), so the file is damaged or was edited, or the walls or health.domain changed since it was written "
         "(in 0/: a region sampled far outside the walls). Restore the file or start from an earlier time "
         "directory (startFrom startTime in system/controlDict); health.leavingDomain: warn in system/solverDict "
         "runs on with them where they are.";
  throw InputError(msg.str());
}

void Solver::checkStart() {
  if (state_.step == 0) checkStartDensity();
  if (ghosts_) ghosts_->drop(particles_); // the start is written next: this rank's own particles
  startChecked_ = true;
}

void Solver::checkStartDensity() {
  const StepContext ctx = beginStep(stepSizeFor(state_.nextDeltaT));
  const double limit = settings_.health.startDensity;
  const auto densest = densestAtStart(ctx, limit);
  if (densest.empty()) return;
  std::ostringstream line;
  line << std::setprecision(6) << "Densest particles at the start (rho / rho^max; health.startDensity " << limit
       << "): " << listDensest(particles_, densest);
  log::info(line.str());
  for (const DensestParticle& d : densest)
    if (d.above > 0) throw InputError(describeOverDense(ctx, densest, limit));
}

void Solver::setTimeControl(const TimeControl& control) {
  control_ = control;
  state_.nextDeltaT =
      control_.adjustTimeStep ? std::clamp(state_.nextDeltaT, control_.minDeltaT, control_.maxDeltaT) : control_.deltaT;
}

void Solver::setUpBoundarySet(ParticleSet& set) {
  if (!wallMotions_.empty() || hasRigidBodies_) { // moving walls: everything below is done at the rest position X
    const bool restart = set.has(field::restPosition);
    auto& rest = set.addVec3(field::restPosition, Restart);
    if (!restart) rest = set.x();
    set.x() = rest;
  }
  // One Morton sort makes the walls' order (and so every sum over them) a function of their rest positions
  // alone, identical after a restart. Their volumes stay right under the rigid motion of each body.
  set.permute(search_.mortonOrder(set.x()));
  computeBoundaryVolumes(set, kernel_);
}

void Solver::placeWalls(double t, double deltaT) {
  // Moves the particles of one wall body (objectId) to place(rest) with velocity(rest).
  const auto drive = [&](long long objectId, const auto& place, const auto& velocity) {
    for (std::size_t k : boundarySets_) {
      ParticleSet& set = particles_[k];
      const auto& object = set.integer(field::objectId);
      const auto& rest = set.vec3(field::restPosition);
      auto& x = set.x();
      auto& v = set.v();
      parallel::forEach(set.size(), [&](std::size_t i) {
        if (object[i] != objectId) return;
        x[i] = place(rest[i]);
        v[i] = velocity(rest[i]);
      });
    }
  };
  for (const ObjectMotion& m : wallMotions_) {
    const WallMotion::Pose now = m.motion.pose(t);
    const WallMotion::Pose next = m.motion.pose(t + deltaT);
    drive(
        m.objectId, [&](const Vec3& X) { return m.motion.place(now, X); },
        [&](const Vec3& X) { return m.motion.meanVelocity(now, next, X, deltaT); });
  }
  for (std::size_t b = 0; b < rigidBodies_.size(); ++b) { // a body's pose drives its particles as a wall's
    const RigidBody& body = rigidBodies_[b];
    const RigidBodyState& s = state_.rigidBodies[b];
    const bool held = body.heldAt(t);
    drive(
        body.objectId(), [&](const Vec3& X) { return body.place(s, X); },
        [&](const Vec3& X) { return held ? Vec3(Vec3::Zero()) : body.chordVelocity(s, X, deltaT); });
  }
}

void Solver::setUpRigidBodies(std::vector<RigidBody::Spec> specs) {
  const bool restart = !state_.rigidBodies.empty();
  if (restart && state_.rigidBodies.size() != specs.size())
    throw InputError("uniform/rigidBodies of the start time directory holds " +
                     std::to_string(state_.rigidBodies.size()) + " bodies, system/particleDict has " +
                     std::to_string(specs.size()) + " rigid regions; run sampleParticles again and start from 0");
  for (std::size_t b = 0; b < specs.size(); ++b) {
    // The body's particles (id, X), on every rank of a parallel run, in id order: its mass and inertia are then the
    // same sums whichever rank holds which particle, so a restart on other owners continues bit for bit.
    std::vector<double> flat;
    for (std::size_t k : boundarySets_) {
      const auto& object = particles_[k].integer(field::objectId);
      const auto& id = particles_[k].integer(field::id);
      const auto& X = particles_[k].vec3(field::restPosition);
      for (std::size_t i = 0; i < object.size(); ++i)
        if (object[i] == specs[b].objectId)
          flat.insert(flat.end(), {static_cast<double>(id[i]), X[i].x(), X[i].y(), X[i].z()});
    }
    if (ghosts_) flat = ghosts_->gather(flat);
    std::vector<std::size_t> order(flat.size() / 4);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return flat[4 * p] < flat[4 * q]; });
    std::vector<Vec3> rest;
    for (const std::size_t p : order) rest.emplace_back(flat[4 * p + 1], flat[4 * p + 2], flat[4 * p + 3]);
    if (rest.empty())
      throw InputError(specs[b].where + ": rigid region '" + specs[b].name + "' has no particle in the walls of the " +
                       "start time directory; run sampleParticles again (it rewrites 0/) and start from 0");
    rigidBodies_.emplace_back(specs[b], rest, particles_.particleRadius());
    if (restart && state_.rigidBodies[b].name != specs[b].name)
      throw InputError("uniform/rigidBodies of the start time directory names body '" + state_.rigidBodies[b].name +
                       "' where system/particleDict has rigid region '" + specs[b].name + "'");
    if (!restart) state_.rigidBodies.push_back(rigidBodies_.back().initialState());
  }
}

void Solver::moveRigidBodies(const StepContext& ctx, double deltaT) {
  if (rigidBodies_.empty()) return;
  std::vector<long long> objects;
  std::vector<Vec3> centres;
  for (std::size_t b = 0; b < rigidBodies_.size(); ++b) {
    objects.push_back(rigidBodies_[b].objectId());
    centres.push_back(state_.rigidBodies[b].centre);
  }
  std::vector<Wrench> wrenches = rigidBodyWrenches(ctx, objects, centres, implicit_.wallReactions());
  if (ghosts_) { // each rank summed the forces of its own particles: one reduction for every body's wrench
    std::vector<double> flat;
    for (const Wrench& w : wrenches)
      flat.insert(flat.end(), {w.force.x(), w.force.y(), w.force.z(), w.torque.x(), w.torque.y(), w.torque.z()});
    ghosts_->sum(flat);
    for (std::size_t b = 0; b < wrenches.size(); ++b) {
      wrenches[b].force = Vec3(flat[6 * b], flat[6 * b + 1], flat[6 * b + 2]);
      wrenches[b].torque = Vec3(flat[6 * b + 3], flat[6 * b + 4], flat[6 * b + 5]);
    }
  }
  for (std::size_t b = 0; b < rigidBodies_.size(); ++b)
    if (!rigidBodies_[b].heldAt(state_.time))
      rigidBodies_[b].integrate(state_.rigidBodies[b], wrenches[b].force + rigidBodies_[b].mass() * fluid_.gravity,
                                wrenches[b].torque, deltaT);
}

std::vector<Domain> Solver::sweptByRotatingWalls() const {
  // Each particle of a rotating body runs on a circle about the axis (through the origin carried by the current
  // displacement): the box of that circle is its centre +- radius sqrt(1 - a_i^2) along axis i. Whatever angles
  // the motion reaches, the domain holds every place the body can turn to (an arm that turns up out of its tank,
  // fluid it carries there), and it does not depend on the angle a run starts at.
  std::vector<Domain> swept;
  for (const ObjectMotion& m : wallMotions_) {
    if (!m.motion.rotates()) continue;
    const Vec3& a = m.motion.axis();
    const Vec3 centre = m.motion.origin() + m.motion.pose(state_.time).displacement;
    const Vec3 extent = (Vec3::Ones() - a.cwiseProduct(a)).cwiseMax(0.0).cwiseSqrt();
    for (std::size_t k : boundarySets_) {
      const ParticleSet& set = particles_[k];
      const auto& object = set.integer(field::objectId);
      for (std::size_t i = 0; i < set.size(); ++i) {
        if (object[i] != m.objectId) continue;
        const Vec3 r = set.x()[i] - centre;
        const Vec3 onAxis = centre + r.dot(a) * a;
        const double radius = (r - r.dot(a) * a).norm();
        swept.push_back({onAxis - radius * extent, onAxis + radius * extent});
      }
    }
  }
  return swept;
}

void Solver::registerSolveFields(ParticleSet& set) const {
  ImplicitSolver::registerFields(set);
  // The implicit solve's right-hand side and the pressure solve's a^p are used one after the other in a step: one
  // array holds both (5.4 MB of the published Seep at r = 1 cm); the pressure solve's rho~*, residuals and last pi
  // likewise take the CG's q (5.4 MB). A lagged a^p is kept from step to step, and arrays of these names a time
  // directory brought along (a user's own) stay fields of their own.
  if (!settings_.compatibility.setSequentialPressure && set.canShare(field::accelP, ImplicitSolver::rightHandSideField))
    set.share(field::accelP, ImplicitSolver::rightHandSideField);
  if (set.canShare(PressureSolver::sweepStateField, ImplicitSolver::productField))
    set.share(PressureSolver::sweepStateField, ImplicitSolver::productField);
  PressureSolver::registerFields(set, settings_.compatibility);
}

void Solver::setUpPorousSet(ParticleSet& set, const PorousMaterial& material) {
  set.restDensity = material.maxDensity();
  set.mass = material.bulkDensity * set.particleVolume;
  registerDensityFields(set);
  registerSolveFields(set);
  set.addInt(field::materialId, Restart);
  auto& fixed = set.addInt(field::fixed, Restart);
  auto& rest = set.addVec3(field::restPosition, Restart);
  // porous.vtp holds every field any material has (zeros where a material has none): what this material does not
  // use is dropped, or a presence test would run that model (a restart under another preset, a second material).
  if (material.youngsModulus > 0.0)
    Elasticity::registerFields(set);
  else
    set.drop(field::rotation);
  if (material.compressible || settings_.pressure.wallContactAllSkeletons)
    registerWallContactFields(set);
  else
    dropWallContactFields(set);
  if (poreFill_ && material.capillaryStrength > 0.0)
    PoreFill::registerFields(set, material);
  else
    set.drop(field::restCoverage); // read with porous.vtp, which holds every material's fields
  // The rest state is the sampled one: X = x at step 0, read back from the time directory afterwards.
  if (state_.step == 0) rest = set.x();
  if (state_.step == 0) { // 0/ is rewritten at step 0: fixedBox must not stick to it, an edited one applies anew
    const bool rewritten = set.has(field::sampledFixed);
    auto& sampled = set.addInt(field::sampledFixed, Restart);
    if (rewritten)
      fixed = sampled;
    else
      sampled = fixed;
  }
  if (material.fixedBox) { // strictly inside the material's fixedBox at X (METHOD.md §4.2)
    const auto& [lo, hi] = *material.fixedBox;
    for (std::size_t i = 0; i < set.size(); ++i)
      if ((rest[i].array() > lo.array()).all() && (rest[i].array() < hi.array()).all()) fixed[i] = 1;
  }
}

StepContext Solver::context(double deltaT) {
  return StepContext{particles_,
                     search_,
                     gradients_,
                     kernel_,
                     fluid_,
                     deltaT,
                     dynamicSets_,
                     boundarySets_,
                     setMaterials_,
                     settings_.compatibility,
                     state_.lastDeltaT,
                     poreFluidBias_ ? &*poreFluidBias_ : nullptr,
                     ghosts_,
                     poreFill_ ? &*poreFill_ : nullptr};
}

void Solver::computeWallVolumesWithGhosts() {
  GhostExchange& ghosts = *ghosts_;
  ghosts.reattach(particles_); // no migration: a restart keeps the owners of the run it continues (searchOrigin)
  // As setUpBoundarySet computes them: moving walls at their rest positions (a body's own neighbours are the same
  // there as where it stands now), now with the ghost walls a subdomain's edge needs.
  for (std::size_t k : boundarySets_) {
    ParticleSet& set = particles_[k];
    const bool moving = set.has(field::restPosition);
    if (moving) std::swap(set.x(), set.vec3(field::restPosition));
    computeBoundaryVolumes(set, kernel_);
    if (moving) std::swap(set.x(), set.vec3(field::restPosition));
  }
  ghosts.drop(particles_);
}

void Solver::searchNeighbours(double deltaT) {
  if (ghosts_) ghosts_->drop(particles_); // e.g. those of checkStart's densities
  const bool sortNow = sortsThisStep();
  if (sortNow) {
    sortIfDue();
    search_.invalidate();
  }
  // How far the bulk of the particles moves this step decides whether the Verlet skin pays. It is measured afresh
  // rather than taken from the last step's report: a restarted run has no last step, and must choose as the
  // uninterrupted one did.
  const double bulkStep = bulkSpeed(deltaT) * deltaT;
  if (ghosts_) {
    // Between migrations the ranks keep their own particles in their slots and take the same ghosts again, so the
    // skin's candidates stay valid; a fresh halo after a restart lists the same neighbours in the same order. The
    // halo reaches H plus the skin, so it holds every neighbour until some particle has moved half the skin, even
    // where the search itself runs at H (a fast flow): then every other step keeps it instead of none.
    if (!sortNow && skinHoldsOnEveryRank()) {
      if (!ghosts_->reattach(particles_)) search_.invalidate();
    } else {
      ghosts_->update(particles_);
      markSearchOrigins();
      search_.invalidate();
    }
  }
  std::vector<const std::vector<Vec3>*> positions;
  std::vector<std::vector<bool>> wanted(particles_.size(), std::vector<bool>(particles_.size(), false));
  for (std::size_t s = 0; s < particles_.size(); ++s) positions.push_back(&particles_[s].x());
  for (std::size_t a : dynamicSets_) {
    for (std::size_t b : dynamicSets_) wanted[a][b] = true;
    for (std::size_t k : boundarySets_) wanted[a][k] = true;
  }
  // Ghosts are only neighbours: their owners compute them, and the step refreshes what it reads of them.
  std::vector<std::size_t> listed;
  if (ghosts_)
    for (std::size_t s = 0; s < particles_.size(); ++s) listed.push_back(ghosts_->owned(s));
  search_.update(positions, wanted, bulkStep, listed);
}

bool Solver::sortsThisStep() const { return settings_.sortInterval > 0 && state_.step % settings_.sortInterval == 0; }

void Solver::sortIfDue() {
  if (!sortsThisStep() || sortedAtStep_ == state_.step) return;
  for (std::size_t a : dynamicSets_) particles_[a].permute(search_.mortonOrder(particles_[a].x()));
  sortedAtStep_ = state_.step;
}

bool Solver::skinHoldsOnEveryRank() const {
  const double skin = settings_.searchSkin * particles_.supportRadius();
  double moved = 0.0; // NaN-proof: an origin never set (a start or a serial time directory) is infinitely far
  for (std::size_t s = 0; s < particles_.size(); ++s) {
    const auto& x = particles_[s].x();
    const auto& origin = particles_[s].vec3(field::searchOrigin);
    moved = std::max(moved, parallel::max(x.size(), 0.0, [&](std::size_t i) {
                       const double d = (x[i] - origin[i]).norm();
                       return d < INFINITY ? d : INFINITY;
                     }));
  }
  // As NeighbourSearch: two particles that each moved less than skin / 2 since are still within reach.
  return 2.0 * ghosts_->max(moved) < skin;
}

void Solver::markSearchOrigins() {
  for (std::size_t s = 0; s < particles_.size(); ++s) {
    auto& origin = particles_[s].vec3(field::searchOrigin);
    const auto& x = particles_[s].x();
    std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(ghosts_->owned(s)), origin.begin());
  }
}

StepContext Solver::beginStep(double deltaT) {
  StepContext ctx = context(deltaT);
  placeWalls(state_.time, deltaT);
  {
    ScopedPhase phase(phases_, "search");
    searchNeighbours(deltaT);
  }
  {
    ScopedPhase phase(phases_, "densities");
    computeDensities(ctx, gradients_);
    initialiseWallContactLimits(ctx, flatWallShare_);
    // Ghosts came with their owners' state (update, reattach) and computed none of these: the owners' are the right
    // ones, and the later loops read them of neighbours.
    std::vector<std::string> changed = densityFields();
    changed.push_back(field::wallContactLimit);
    ctx.refreshGhosts(changed);
  }
  return ctx;
}

void Solver::step(double deltaT) {
  const StepContext ctx = beginStep(deltaT);
  measureFluidDensity();
  {
    ScopedPhase phase(phases_, "implicit"); // the non-pressure velocity updates: XSPH smoothing, then Eq. 22
    smoothFluidVelocities(ctx, settings_.xsph);
    ctx.refreshGhosts({field::v});
    report_.implicit = implicit_.solve(ctx);
    ctx.refreshGhosts({field::v, field::deltaV});
  }
  {
    ScopedPhase phase(phases_, "pressure");
    pressure_.predictDensities(ctx);
    report_.pressure = pressure_.solve(ctx);
    moveRigidBodies(ctx, deltaT);
    if (state_.step + 1 == injectNaNStep_ && !dynamicSets_.empty() && particles_[dynamicSets_.front()].size() > 0)
      particles_[dynamicSets_.front()].v()[0] = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  }
  {
    ScopedPhase phase(phases_, "integrate");
    for (std::size_t a : dynamicSets_) { // symplectic Euler (METHOD.md §6.8)
      ParticleSet& set = particles_[a];
      auto& x = set.x();
      const auto& v = set.v();
      const std::int64_t* fixed = fixedFlags(set);
      parallel::forEach(set.size(), [&](std::size_t i) {
        if (!(fixed && fixed[i])) x[i] += deltaT * v[i];
      });
    }
    if (ghosts_) ghosts_->drop(particles_); // what is written and checked is this rank's own
    state_.time += deltaT;
    ++state_.step;
    report_.deltaT = state_.lastDeltaT = deltaT;
    report_.maxSpeed = maxSpeed();
    state_.nextDeltaT =
        cflStepSize(control_, report_.maxSpeed, particles_.spacing(), deltaT, report_.pressure.iterations);
    placeWalls(state_.time, state_.nextDeltaT); // written time directories show the walls where they are
    if (!wallMotions_.empty()) updateDomain();  // the domain goes where the walls go (a container carried along)
  }
}

void Solver::measureFluidDensity() {
  report_.maxFluidDensity = report_.maxPoreFluidDensity = 0.0;
  for (std::size_t a : dynamicSets_) {
    if (particles_[a].kind() != SetKind::Fluid) continue;
    const auto& rho = particles_[a].real(field::rhoTilde);
    report_.maxFluidDensity = parallel::max(rho.size(), 0.0, [&](std::size_t i) { return rho[i]; });
    for (std::size_t t : dynamicSets_) { // fluid in pores: the check of the porous wall (VALIDATION.md)
      if (!setMaterials_[t]) continue;
      const NeighbourList& solids = search_.list(a, t);
      report_.maxPoreFluidDensity = std::max(
          report_.maxPoreFluidDensity,
          parallel::max(rho.size(), 0.0, [&](std::size_t i) { return solids.of(i).size() > 0 ? rho[i] : 0.0; }));
    }
  }
  if (ghosts_) { // the log's figures are the run's
    report_.maxFluidDensity = ghosts_->max(report_.maxFluidDensity);
    report_.maxPoreFluidDensity = ghosts_->max(report_.maxPoreFluidDensity);
  }
}

std::size_t Solver::movingParticles() const {
  double n = 0.0;
  for (std::size_t s : dynamicSets_) n += static_cast<double>(ghosts_ ? ghosts_->owned(s) : particles_[s].size());
  return static_cast<std::size_t>(ghosts_ ? ghosts_->sum(n) : n);
}

double Solver::maxSpeed() const {
  double result = 0.0;
  for (std::size_t s = 0; s < particles_.size(); ++s) {
    const auto& v = particles_[s].v();
    const std::size_t n = ghosts_ ? ghosts_->owned(s) : v.size();
    // One square root per set: the root of the largest squared speed is the largest speed, to the bit.
    result = std::max(result, std::sqrt(parallel::max(n, 0.0, [&](std::size_t i) { return v[i].squaredNorm(); })));
  }
  if (ghosts_) result = ghosts_->max(result); // every rank takes the same step
  // The walls' velocities above are those of the step just done; the next step must also respect how fast the
  // prescribed motions go within it (a wall that starts, or speeds up at a corner of its table): their largest
  // speed |d'| + |theta'| (largest distance from the axis) over the longest step that can come.
  const double ahead = control_.adjustTimeStep ? control_.maxDeltaT : control_.deltaT;
  for (std::size_t m = 0; m < wallMotions_.size(); ++m)
    result = std::max(result, wallMotions_[m].motion.maxSpeed(wallReach_[m], state_.time, state_.time + ahead));
  return result;
}

double Solver::bulkSpeed(double deltaT) const {
  const double fastest = maxSpeed();
  const double skin = settings_.searchSkin * particles_.supportRadius();
  const double crossing = skin / (NeighbourSearch::stepsPerSkin * deltaT); // a speed that outruns the skin
  if (skin <= 0.0 || fastest < crossing) return fastest;
  // A few fast particles (a jet, a splash) are the search's movers: the speed that matters is that of the others,
  // unless the fast ones are more than its share. Moving walls count with their fastest point, as in maxSpeed.
  double fast = 0.0, listed = 0.0, others = 0.0;
  for (std::size_t s = 0; s < particles_.size(); ++s) {
    const auto& v = particles_[s].v();
    const std::size_t n = ghosts_ ? ghosts_->owned(s) : v.size();
    fast += parallel::sum<double>(n, [&](std::size_t i) { return v[i].norm() >= crossing ? 1.0 : 0.0; });
    if (std::find(dynamicSets_.begin(), dynamicSets_.end(), s) != dynamicSets_.end()) listed += static_cast<double>(n);
    others = std::max(others, parallel::max(n, 0.0, [&](std::size_t i) {
                        const double speed = v[i].norm();
                        return speed < crossing ? speed : 0.0;
                      }));
  }
  if (ghosts_) {
    fast = ghosts_->sum(fast);
    listed = ghosts_->sum(listed);
    others = ghosts_->max(others);
  }
  const double ahead = control_.adjustTimeStep ? control_.maxDeltaT : control_.deltaT;
  for (std::size_t m = 0; m < wallMotions_.size(); ++m)
    others = std::max(others, wallMotions_[m].motion.maxSpeed(wallReach_[m], state_.time, state_.time + ahead));
  return fast * static_cast<double>(NeighbourSearch::particlesPerMover) > listed ? fastest : others;
}

double Solver::stepSizeFor(double deltaT) const {
  // Adjustable steps land exactly on write times and endTime (OpenFOAM's adjustTimeStep habit).
  if (!control_.adjustTimeStep) return deltaT;
  double target = control_.endTime;
  if (control_.writeControl == TimeControl::WriteControl::RunTime) {
    const double k = std::floor(state_.time / control_.writeInterval * (1.0 + 1e-12) + 1e-9);
    target = std::min(target, (k + 1.0) * control_.writeInterval);
  }
  return stepTowards(state_.time, target, deltaT);
}

bool Solver::isWriteStep(double previousTime) const {
  if (control_.writeControl == TimeControl::WriteControl::TimeStep)
    return state_.step % static_cast<long long>(control_.writeInterval) == 0;
  // A write time t_w = k * writeInterval was reached in this step (half a step of slack for fixed steps).
  const double slack = 0.5 * report_.deltaT;
  const double before = std::floor((previousTime + slack) / control_.writeInterval);
  const double after = std::floor((state_.time + slack) / control_.writeInterval);
  return after > before;
}

void Solver::logProgress(double elapsed, double startTime) const {
  const StepReport& r = report_;
  std::ostringstream out;
  out << std::setprecision(6) << "Time = " << state_.time << "  (step " << state_.step << ")\n"
      << "deltaT = " << r.deltaT << "  max|v| = " << r.maxSpeed << " m/s  max fluid density = " << r.maxFluidDensity
      << " rho0";
  if (r.maxPoreFluidDensity > 0.0) out << " (in pores " << r.maxPoreFluidDensity << " rho0)";
  out << "\n"
      << "pressure: " << r.pressure.iterations << " sweeps, density error " << r.pressure.meanError << " % (max "
      << r.pressure.maxError << " %)" << (r.pressure.converged ? "" : "  NOT CONVERGED") << '\n'
      << "implicit: " << r.implicit.iterations << " CG iterations, residual " << r.implicit.relativeResidual
      << (r.implicit.converged ? "" : "  NOT CONVERGED") << '\n';
  const double done = (state_.time - startTime) / (control_.endTime - startTime);
  out << "ExecutionTime = " << std::setprecision(4) << elapsed << " s  ClockTime = " << std::llround(elapsed)
      << " s  ETA = " << formatDuration(done > 0 ? elapsed * (1.0 - done) / done : 0.0) << '\n';
  log::info(out.str());
}

void Solver::writeState(const Writer& write) {
  ScopedPhase phase(phases_, "output");
  write(*this);
  lastWrittenStep_ = state_.step;
}

void Solver::stopAfterWriting(const Writer& write, const std::string& message) {
  std::ostringstream out;
  out << message << "\nThe state at time " << std::setprecision(10) << state_.time << " (step " << state_.step
      << ") is " << (lastWrittenStep_ == state_.step ? "already on disk" : "written") << " as a time directory.";
  if (lastWrittenStep_ != state_.step) writeState(write);
  if (ghosts_) ghosts_->sum(0.0); // every rank has written its part before any of them stops the run
  throw NumericalError(out.str());
}

std::string Solver::whatToChange() const {
  std::ostringstream out;
  out << std::setprecision(6);
  if (control_.adjustTimeStep)
    out << "reduce maxCourant (now " << control_.maxCourant << ") or maxDeltaT (now " << control_.maxDeltaT << " s)";
  else
    out << "reduce deltaT (now " << control_.deltaT << " s)";
  out << " in system/controlDict";
  return out.str();
}

std::string Solver::describeDomain() const {
  const Vec3& lo = domain_->min;
  const Vec3& hi = domain_->max;
  std::ostringstream out;
  out << std::setprecision(6) << '(' << lo.x() << ", " << lo.y() << ", " << lo.z() << ") - (" << hi.x() << ", "
      << hi.y() << ", " << hi.z() << ')'
      << (settings_.health.domain ? "" : ", the walls' bounding box grown by its longest side");
  return out.str();
}

void Solver::checkHealth(const Writer& write) {
  const HealthSettings& health = settings_.health;
  const auto notFinite = findNonFinite(particles_, dynamicSets_);
  // In a parallel run every rank takes the decision of the worst one, so that they stop (or go on) together.
  const auto anyRank = [&](bool here) { return ghosts_ ? ghosts_->max(here ? 1.0 : 0.0) > 0.0 : here; };
  if (anyRank(!notFinite.empty())) {
    std::ostringstream msg;
    msg << std::setprecision(10) << "step " << state_.step << " (time " << state_.time << " s, deltaT "
        << report_.deltaT << " s): NaN or infinite position or velocity in "
        << describe(particles_, notFinite,
                    [&](std::size_t s, std::size_t i) {
                      const auto p = snapshot_.positionOf(s, i, particles_[s].integer(field::id)[i]);
                      return p ? *p : particles_[s].x()[i];
                    })
        << " (positions at the start of the step)" << (notFinite.empty() ? " on another rank" : "");
    if (health.nonFinite == HealthAction::Remove) {
      const auto removed = static_cast<double>(count(notFinite));
      warnings_.record(RunWarnings::Kind::NonFiniteRemoved, state_.step, state_.time,
                       static_cast<std::size_t>(ghosts_ ? ghosts_->sum(removed) : removed));
      removeParticles(particles_, notFinite);
      log::warning(msg.str() + "; removed (health.nonFinite remove in system/solverDict). If this recurs, " +
                   whatToChange() + ".");
    } else {
      snapshot_.restore(particles_, state_);
      // Moving walls and rigid bodies back where the restored state has them.
      placeWalls(state_.time, state_.nextDeltaT);
      PressureSolver::formPressures(particles_, dynamicSets_);
      for (std::size_t s : dynamicSets_) { // a restart from the written state solves from a cold start
        auto& deltaV = particles_[s].vec3(field::deltaV);
        std::fill(deltaV.begin(), deltaV.end(), Vec3::Zero());
      }
      msg << ". The step is undone. To continue: " << whatToChange()
          << ", then run again with startFrom latestTime; or set health.nonFinite: remove in system/solverDict.";
      stopAfterWriting(write, msg.str());
    }
  }
  if (domain_) {
    const auto outside = findOutside(particles_, dynamicSets_, *domain_);
    const std::size_t n = count(outside);
    const auto nAll = static_cast<std::size_t>(ghosts_ ? ghosts_->sum(static_cast<double>(n)) : n);
    const bool stopAll = health.leavingDomain == HealthAction::Stop && nAll > 0;
    if (stopAll || (n > 0 && (health.leavingDomain != HealthAction::Warn || n > outsideReported_))) {
      std::ostringstream msg;
      msg << std::setprecision(6) << "step " << state_.step << " (time " << state_.time << " s): "
          << (n == 0
                  ? std::string("particles of another rank")
                  : describe(particles_, outside, [&](std::size_t s, std::size_t i) { return particles_[s].x()[i]; }))
          << " left the domain " << describeDomain()
          << ". Particles escape through gaps in the walls wider than a particle diameter or are thrown out by a "
             "pressure spike ("
          << whatToChange() << "); health.domain in system/solverDict sets the domain";
      switch (health.leavingDomain) {
      case HealthAction::Warn:
        outsideReported_ = n;
        log::warning(msg.str() + " (health.leavingDomain warn: they stay in the run).");
        break;
      case HealthAction::Remove:
        removeParticles(particles_, outside);
        log::warning(msg.str() + " (health.leavingDomain remove: they are deleted).");
        break;
      case HealthAction::Stop:
        stopAfterWriting(write, msg.str() + " (health.leavingDomain stop).");
        break;
      }
    }
    if (nAll > 0) // every rank, also where none of its own particles left
      warnings_.record(health.leavingDomain == HealthAction::Remove ? RunWarnings::Kind::LeftDomainRemoved
                                                                    : RunWarnings::Kind::OutsideDomainKept,
                       state_.step, state_.time, nAll);
    checkRigidBodiesInDomain(write);
  }
  checkIterations(write);
  checkCourant();
}

void Solver::checkCourant() {
  if (!control_.adjustTimeStep || report_.maxSpeed <= 0.0) return;
  const double cfl = control_.maxCourant * particles_.spacing() / report_.maxSpeed;
  if (cfl >= control_.minDeltaT) return;
  // Warned of once, then counted (the log's summary): a fast wall can keep the step at minDeltaT for a whole run.
  if (warnings_.steps(RunWarnings::Kind::StepAboveCourant) == 0 && (!ghosts_ || ghosts_->rank() == 0)) {
    std::ostringstream msg;
    msg << std::setprecision(6) << "step " << state_.step << " (time " << state_.time
        << " s): max|v| = " << report_.maxSpeed << " m/s (particles or prescribed walls) asks for a step of maxCourant "
        << "2r / max|v| = " << cfl << " s, below minDeltaT = " << control_.minDeltaT << " s; the steps take minDeltaT, "
        << "so the fastest move " << control_.minDeltaT * report_.maxSpeed / particles_.spacing()
        << " particle diameters per step instead of " << control_.maxCourant
        << ". Lower minDeltaT in system/controlDict (or slow the walls' motion). Further such steps are counted in the "
           "summary at the end of the run.";
    log::warning(msg.str());
  }
  warnings_.record(RunWarnings::Kind::StepAboveCourant, state_.step, state_.time);
}

void Solver::checkRigidBodiesInDomain(const Writer& write) {
  std::size_t outside = 0;
  for (std::size_t b = 0; b < rigidBodies_.size(); ++b) { // the bodies' states are every rank's
    const RigidBodyState& body = state_.rigidBodies[b];
    if (domain_->contains(body.centre)) continue;
    ++outside;
    if (settings_.health.leavingDomain == HealthAction::Warn && rigidBodiesOutside_.count(b)) continue;
    std::ostringstream msg;
    msg << std::setprecision(6) << "step " << state_.step << " (time " << state_.time << " s): rigid body '"
        << body.name << "' left the domain " << describeDomain() << ": its centre is at (" << body.centre.x() << ", "
        << body.centre.y() << ", " << body.centre.z() << "), moving at " << body.velocity.norm()
        << " m/s. Rigid bodies do not touch walls: a body meets a wall only through the fluid between them, so one "
           "much denser than the fluid can press it aside and pass through a floor";
    if (settings_.health.leavingDomain == HealthAction::Warn) {
      rigidBodiesOutside_.insert(b);
      log::warning(msg.str() + " (health.leavingDomain warn: it stays in the run).");
      continue;
    }
    stopAfterWriting(write, msg.str() + ". A body is not deleted: the run stops (health.leavingDomain warn in "
                                        "system/solverDict keeps it in the run).");
  }
  if (outside > 0) warnings_.record(RunWarnings::Kind::RigidBodiesOutsideKept, state_.step, state_.time, outside);
}

void Solver::checkIterations(const Writer& write) {
  const HealthSettings& health = settings_.health;
  if (!report_.pressure.converged) {
    const PressureSettings& bounds = settings_.pressure;
    const PressureStats& stats = report_.pressure;
    const bool particleUnmet = bounds.maxParticleDensityError > 0.0 && stats.maxError > bounds.maxParticleDensityError;
    const bool skeletonUnmet =
        bounds.maxSkeletonParticleDensityError > 0.0 && stats.maxSkeletonError > bounds.maxSkeletonParticleDensityError;
    const bool meanUnmet = stats.meanError > bounds.maxDensityError;
    // Name the particle the unmet criterion is about: with only the skeletons' bound unmet, a skeleton particle.
    std::vector<std::size_t> searched;
    for (std::size_t a : dynamicSets_)
      if (setMaterials_[a] || meanUnmet || particleUnmet) searched.push_back(a);
    if (searched.empty()) searched = dynamicSets_;
    std::ostringstream msg;
    msg << std::setprecision(6) << "step " << state_.step << " (time " << state_.time
        << " s): the pressure solve reached pressure.maxIterations = " << bounds.maxIterations
        << " with mean density error " << stats.meanError << " % (target " << bounds.maxDensityError << " %)";
    if (particleUnmet)
      msg << ", a particle compressed " << stats.maxError << " % (bound pressure.maxParticleDensityError "
          << bounds.maxParticleDensityError << " %)";
    if (skeletonUnmet)
      msg << ", a skeleton particle compressed " << stats.maxSkeletonError
          << " % (bound pressure.maxSkeletonParticleDensityError " << bounds.maxSkeletonParticleDensityError << " %)";
    msg << mostCompressedOfTheRun(searched);
    msg << ". To converge: " << whatToChange() << ", or raise pressure.maxIterations";
    if (particleUnmet || skeletonUnmet) msg << " or the bound";
    msg << " in system/solverDict";
    if (health.pressureIterations == HealthAction::Stop)
      stopAfterWriting(write, msg.str() + " (health.pressureIterations stop).");
    warnings_.record(RunWarnings::Kind::PressureIterations, state_.step, state_.time);
    if (!ghosts_ || ghosts_->rank() == 0) log::warning(msg.str() + "."); // the run's solve: once, not per rank
  }
  if (!report_.implicit.converged) {
    std::ostringstream msg;
    msg << std::setprecision(6) << "step " << state_.step << " (time " << state_.time
        << " s): the implicit solve (viscosity, elasticity, drag, adhesion, buoyancy) reached implicit.maxIterations = "
        << settings_.implicit.maxIterations << " with relative residual " << report_.implicit.relativeResidual
        << " (tolerance " << settings_.implicit.tolerance << "). To converge: " << whatToChange()
        << ", or raise implicit.maxIterations in system/solverDict";
    if (health.implicitIterations == HealthAction::Stop)
      stopAfterWriting(write, msg.str() + " (health.implicitIterations stop).");
    warnings_.record(RunWarnings::Kind::ImplicitIterations, state_.step, state_.time);
    if (!ghosts_ || ghosts_->rank() == 0) log::warning(msg.str() + ".");
  }
}

std::string Solver::mostCompressedOfTheRun(const std::vector<std::size_t>& sets) const {
  const auto [s, i] = PressureSolver::mostCompressed(particles_, sets);
  // Residual, set, id and position of this rank's most compressed particle; none where the rank holds none of them.
  std::vector<double> candidate;
  if (i < particles_[s].size()) {
    const ParticleSet& set = particles_[s];
    const Vec3 p = set.x()[i];
    const double residual = set.vec3(PressureSolver::sweepStateField)[i][PressureSolver::kResidual];
    const auto id = static_cast<double>(set.integer(field::id)[i]);
    candidate = {residual, static_cast<double>(s), id, p.x(), p.y(), p.z()};
  }
  if (ghosts_) candidate = ghosts_->gather(candidate); // every rank's, in rank order: the first largest wins
  if (candidate.empty()) return {};
  std::size_t best = 0;
  for (std::size_t k = 6; k + 6 <= candidate.size(); k += 6)
    if (candidate[k] > candidate[best]) best = k;
  std::ostringstream out;
  out << std::setprecision(6)
      << "; most compressed: " << particles_[static_cast<std::size_t>(candidate[best + 1])].name() << " particle id "
      << static_cast<std::int64_t>(candidate[best + 2]) << " at (" << candidate[best + 3] << ", " << candidate[best + 4]
      << ", " << candidate[best + 5] << "), " << 100.0 * candidate[best] << " %";
  return out.str();
}

void Solver::notePoreFluidFill() const {
  if (settings_.pressure.latticeCorrectedPoreFluid) return;
  const bool fluid = std::any_of(dynamicSets_.begin(), dynamicSets_.end(),
                                 [&](std::size_t s) { return particles_[s].kind() == SetKind::Fluid; });
  if (!fluid || materials_.empty()) return;
  const PoreFluidDensityBias bias(kernel_, particles_.particleVolume());
  for (const PorousMaterial& m : materials_) {
    const double fill = bias.uncorrectedFill(m.porosity);
    if (m.porosity <= 0.0 || fill > 0.9) continue;
    std::ostringstream msg;
    msg << std::setprecision(3) << "porous material '" << m.name << "' (porosity " << m.porosity
        << "): with pressure.poreFluidDensity paper (Eq. 4 as published; the default once compatibility.preset is "
        << "named) fluid at rest fills about " << std::lround(100.0 * fill)
        << " % of its pores (lattice estimate); pressure.poreFluidDensity latticeCorrected in system/solverDict "
        << "(PoroSPH's default without a preset) fills them";
    log::warning(msg.str());
  }
}

RunOutcome Solver::run(const Writer& write, const Monitor& afterStep, const Observer& stepDone) {
  using StopAt = TimeControl::StopAt;
  const Timer clock;
  const double startTime = state_.time;
  lastWrittenStep_ = state_.step; // the start time directory is on disk
  const std::size_t movingAtStart = movingParticles();
  RunOutcome outcome;
  if (state_.step == 0) {
    if (!startChecked_) checkStart();
    if (control_.adjustTimeStep) { // the first step respects the start's speeds and the walls' as every later one
      state_.nextDeltaT =
          std::min(state_.nextDeltaT, cflStepSize(control_, maxSpeed(), particles_.spacing(), state_.nextDeltaT, 0));
      placeWalls(state_.time, state_.nextDeltaT);
    }
    // 0/ as sampled holds positions and velocities only; rewritten with the start's densities, saturations and
    // (zero) pressures, it offers ParaView every array at t = 0 that later times have.
    writeState(write);
  }
  notePoreFluidFill();
  log::info("Starting time loop\n");
  while (!control_.endTimeReached(state_.time)) {
    const double previousTime = state_.time;
    const double dt = stepSizeFor(state_.nextDeltaT);
    {
      ScopedPhase phase(phases_, "health");
      // Fields set once are moved only by a reordering or a parallel run's migration, which happen in the step.
      // A serial run sorts before the snapshot instead: the snapshot holds the sorted state, which is as good to
      // write and restart from, and a sort step needs no copy of them either. The same holds for fields the step
      // forms from the positions at its start only (rotations, saturations, phi^loc; the contact limits and rest
      // coverages of the first step): an undone step leaves them as they fit the restored positions (9.9 MB of the
      // published Seep at r = 1 cm).
      if (!ghosts_) sortIfDue();
      static const std::vector<std::string> keptInPlace{
          field::id,           field::objectId, field::materialId, field::fixed,         field::restPosition,
          field::sampledFixed, field::rotation, field::saturation, field::localPorosity, field::wallContactLimit,
          field::restCoverage};
      static const std::vector<std::string> none;
      const std::vector<std::string>& kept = ghosts_ ? none : keptInPlace; // a reference, not a copy
      // Formed again after a restore (checkHealth), not copied: p is pi rho^2 / rho^max of two copied fields, and
      // deltaV, the implicit solve's warm start, is set to zero (24 bytes per moving particle the step does not
      // hold: 5.4 MB of the published Seep at r = 1 cm).
      static const std::vector<std::string> formedAgain{field::pressure, field::deltaV};
      snapshot_.take(particles_, dynamicSets_, state_, kept, formedAgain);
    }
    step(dt);
    logProgress(clock.seconds(), startTime);
    {
      ScopedPhase phase(phases_, "health");
      checkHealth(write);
    }
    if (afterStep) afterStep(*this);
    const bool last = control_.endTimeReached(state_.time);
    int signal = signals::stopRequested();
    if (ghosts_) signal = static_cast<int>(ghosts_->max(signal)); // every rank stops after the same step
    const bool writeTime = isWriteStep(previousTime);
    const StopAt stopAt = control_.stopAt;
    const bool skipWrite = stopAt == StopAt::NoWriteNow && !signal;
    if ((writeTime || last || signal || stopAt == StopAt::WriteNow) && !skipWrite) {
      snapshot_.release(); // the step is healthy: the write's arrays take the snapshot's memory, not more
      writeState(write);
    }
    if (stepDone) stepDone(*this);
    if (last) break;
    std::ostringstream msg;
    msg << std::setprecision(10);
    if (signal) {
      msg << signals::name(signal) << " received: stopped after step " << state_.step << " at time " << state_.time
          << ", which is written. To continue, run poroSph again with startFrom latestTime in system/controlDict.";
      log::warning(msg.str());
      outcome = {RunOutcome::End::Signal, signal};
      break;
    }
    if (stopAt == StopAt::WriteNow || stopAt == StopAt::NoWriteNow || (stopAt == StopAt::NextWrite && writeTime)) {
      msg << "stopAt in system/controlDict: stopped after step " << state_.step << " at time " << state_.time
          << (lastWrittenStep_ == state_.step ? ", which is written" : ", which is not written")
          << ". To continue, set stopAt: endTime and startFrom: latestTime and run poroSph again.";
      log::info(msg.str());
      outcome.end = RunOutcome::End::StopAt;
      break;
    }
  }
  std::ostringstream summary;
  summary << "Phase breakdown over " << state_.step << " steps (wall time):\n";
  const double total = phases_.total();
  for (const auto& [name, seconds] : phases_.phases())
    summary << "  " << std::left << std::setw(10) << name << std::right << std::setw(10) << std::fixed
            << std::setprecision(3) << seconds << " s  " << std::setw(5) << std::setprecision(1)
            << (total > 0 ? 100.0 * seconds / total : 0.0) << " %\n";
  if (settings_.searchSkin > 0)
    summary << "Neighbour lists: " << search_.gridSearches() << " grid searches in " << search_.updates()
            << " steps (skin " << std::setprecision(2) << settings_.searchSkin << " H)\n";
  if (ghosts_) summary << rankSummary(*ghosts_, total);
  if (warnings_.any()) summary << warnings_.summary(movingAtStart, movingParticles());
  log::info(summary.str());
  if (outcome.end != RunOutcome::End::Signal) log::info("End\n");
  return outcome;
}

} // namespace poro
