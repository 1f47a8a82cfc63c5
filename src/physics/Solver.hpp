#pragma once
/// The PoroSPH solver: the algorithm of one time step (METHOD.md §5) and the time loop around it.
/// Output is not its business: run() calls a writer at every write time (io implements it).

#include "core/Timer.hpp"
#include "linalg/ConjugateGradient.hpp"
#include "physics/FluidProperties.hpp"
#include "physics/ImplicitSolver.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/PressureSolver.hpp"
#include "physics/RigidBody.hpp"
#include "physics/RunState.hpp"
#include "physics/RunWarnings.hpp"
#include "physics/SolverSettings.hpp"
#include "physics/StateSnapshot.hpp"
#include "physics/StepContext.hpp"
#include "physics/TimeControl.hpp"
#include "physics/WallMotion.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <set>

namespace poro {

/// What the last step did, for the progress log and postProcessing.
struct StepReport {
  double deltaT = 0.0;
  PressureStats pressure;
  linalg::CgResult implicit;
  double maxSpeed = 0.0;            ///< largest particle speed, or prescribed wall speed within the next step [m/s]
  double maxFluidDensity = 0.0;     ///< largest fluid rho~ = rho^/rho_f^0 at the start of the step (Eq. 4)
  double maxPoreFluidDensity = 0.0; ///< the same over fluid particles with porous neighbours
};

/// Why run() returned.
struct RunOutcome {
  enum class End { EndTime, StopAt, Signal };
  End end = End::EndTime;
  int signal = 0; ///< with End::Signal: SIGINT, SIGTERM or SIGHUP
};

class Solver {
public:
  /// Takes the particles of a case (loaded from 0/ or a restart time directory) and validated settings.
  /// Each porous set is named after its material in `materials` (constant/porosityProperties). Walls whose
  /// object id has an entry in `wallMotions` move as prescribed; the others stay where they are. Throws
  /// InputError when a motion's object has no wall particle, and when particles of the fluid or porous sets lie
  /// outside the domain (health.domain, or the walls' box grown) unless health.leavingDomain is warn.
  /// Rigid bodies (physics/RigidBody.hpp) are the boundary particles of their object id; their state comes from
  /// `start.rigidBodies` (a restart) or, when that is empty, from the sampled particles at rest.
  /// With `ghosts` the solver is one rank of a parallel run (physics/GhostExchange.hpp): every step then starts by
  /// sending particles that left this rank's part and fetching the ghosts, and ends by dropping them; what the
  /// constructor checks and derives from all particles (wall motions, the walls' volumes, the domain) is the run's.
  Solver(ParticleSystem particles, const FluidProperties& fluid, std::vector<PorousMaterial> materials,
         const SolverSettings& settings, const TimeControl& control, const RunState& start,
         std::vector<ObjectMotion> wallMotions = {}, std::vector<RigidBody::Spec> rigidBodies = {},
         GhostExchange* ghosts = nullptr);

  /// Called at each write time and at the end; receives the solver to read particles and state from.
  using Writer = std::function<void(const Solver&)>;
  /// Called after each step, before the write decision; may change the time control (runTimeModifiable).
  using Monitor = std::function<void(Solver&)>;
  /// Called at the very end of each step, after any write (per-step records such as solverPerformance).
  using Observer = std::function<void(const Solver&)>;
  /// Advances to endTime, logging progress per step and calling `write` at every write time. A run from step 0
  /// first logs the densest particles and throws InputError above health.startDensity (physics/StartDensity.hpp).
  /// SIGINT, SIGTERM or SIGHUP (core/StopSignals.hpp) and stopAt end the run after the current step. After each step
  /// the health checks of solverDict run; a failed check with policy stop writes the last good state and throws
  /// NumericalError naming the particles, where they are and what to change.
  /// At step 0: computes the start's densities and refuses a start denser than health.startDensity (an
  /// InputError naming the particles). Call it before anything is written; run() calls it if it was not.
  void checkStart();
  RunOutcome run(const Writer& write, const Monitor& afterStep = {}, const Observer& stepDone = {});
  /// One time step of size `deltaT` (METHOD.md §5).
  void step(double deltaT);
  /// Steps 1-4 of METHOD.md §5 at the current positions (neighbour search, densities, alpha, saturation,
  /// local porosity) and the context the rest of the step uses; step() starts with it, tests probe it.
  StepContext beginStep(double deltaT);
  ImplicitSolver& implicitSolver() { return implicit_; }
  const PressureSolver& pressureSolver() const { return pressure_; }
  const NeighbourSearch& neighbourSearch() const { return search_; }

  const ParticleSystem& particles() const { return particles_; }
  ParticleSystem& particles() { return particles_; }
  const RunState& state() const { return state_; }
  const StepReport& lastStep() const { return report_; }
  const std::vector<RigidBody>& rigidBodies() const { return rigidBodies_; }
  const PhaseTimes& phaseTimes() const { return phases_; }
  /// The warnings the steps of run() gave so far, by kind (the log ends with their summary).
  const RunWarnings& warnings() const { return warnings_; }
  const TimeControl& timeControl() const { return control_; }
  /// Replaces the time settings while running (runTimeModifiable); the next step uses them.
  void setTimeControl(const TimeControl& control);
  /// Tests the health checks end to end: in step `step` one particle's velocity becomes NaN.
  void injectNaN(long long step) { injectNaNStep_ = step; }

private:
  StepContext context(double deltaT);
  void searchNeighbours(double deltaT);
  /// Whether the coming step puts the particles into Morton order (every sortInterval steps).
  bool sortsThisStep() const;
  /// Puts the moving particles into Morton order if the coming step is due one and has not had it yet (a second
  /// sort would only cost time: the order is a stable sort of cells).
  void sortIfDue();
  /// Parallel runs: whether the Verlet skin still holds over every rank since the last migration (searchOrigin), so
  /// that the ranks keep their particles and ghosts instead of migrating and building a new halo.
  bool skinHoldsOnEveryRank() const;
  /// Parallel runs: the own particles' searchOrigin, at a migration.
  void markSearchOrigins();
  double maxSpeed() const;
  /// The fluid and porous particles of the whole run (every rank's).
  std::size_t movingParticles() const;
  /// The largest speed but that of a few fast particles (at most one of NeighbourSearch::particlesPerMover
  /// listed particles) that would outrun the search's skin in a step of deltaT: those are its movers.
  double bulkSpeed(double deltaT) const;
  void measureFluidDensity();
  void logProgress(double elapsed, double startTime) const;
  /// Without the pore-fluid correction, warns of porous materials whose pores fluid fills 10 % short or more
  /// (the absorbed-volume tolerance of VALIDATION.md): porosity below about 0.45.
  void notePoreFluidFill() const;
  void checkStartPositions();
  void checkStartDensity();
  /// health.domain, or the walls' box where they are now (NumericalHealth.hpp's wallDomain): a function of the time
  /// alone, so that a restart checks against the domain of a run from the start.
  void updateDomain();
  /// "(lo) - (hi)" of the domain, and where it comes from when not from health.domain.
  std::string describeDomain() const;
  void checkHealth(const Writer& write);
  void checkIterations(const Writer& write);
  /// adjustTimeStep: warns (once, then counts) when the CFL step falls below minDeltaT, which the step takes instead.
  void checkCourant();
  /// A rigid body whose centre left the domain stops the run (it cannot be deleted), or with health.leavingDomain
  /// warn is warned of once.
  void checkRigidBodiesInDomain(const Writer& write);
  /// "; most compressed: <set> particle id <id> at (x, y, z), <residual> %" over every rank's particles of `sets`.
  std::string mostCompressedOfTheRun(const std::vector<std::size_t>& sets) const;
  void writeState(const Writer& write);
  [[noreturn]] void stopAfterWriting(const Writer& write, const std::string& message);
  std::string whatToChange() const;
  double stepSizeFor(double deltaT) const;
  bool isWriteStep(double previousTime) const;

  /// The implicit and pressure solves' fields of a moving set.
  void registerSolveFields(ParticleSet& set) const;
  void setUpPorousSet(ParticleSet& set, const PorousMaterial& material);
  void setUpBoundarySet(ParticleSet& set);
  /// A parallel run: the walls' volumes again, with the ghost walls a subdomain's edge needs.
  void computeWallVolumesWithGhosts();
  /// Moving walls to x(t) = c0 + d(t) + R(t) (X - c0), with the velocity that carries them to x(t + deltaT).
  void placeWalls(double t, double deltaT);
  /// Builds the rigid bodies from their particles' rest positions and their state (start or restart).
  void setUpRigidBodies(std::vector<RigidBody::Spec> specs);
  /// Newton-Euler step of every rigid body under the reactions of the pressure forces of this step and gravity.
  void moveRigidBodies(const StepContext& ctx, double deltaT);
  /// The boxes of the circles the particles of rotating walls run on, for the default domain.
  std::vector<Domain> sweptByRotatingWalls() const;

  ParticleSystem particles_;
  FluidProperties fluid_;
  std::vector<PorousMaterial> materials_;
  std::vector<const PorousMaterial*> setMaterials_; ///< by set index
  SolverSettings settings_;
  TimeControl control_;
  RunState state_;
  CubicKernel kernel_;
  std::optional<PoreFluidDensityBias> poreFluidBias_; ///< set when pressure.poreFluidDensity is latticeCorrected
  std::optional<PoreFill> poreFill_; ///< set when implicit.adhesionInFullPores fades and some material adheres
  NeighbourSearch search_;
  PairGradients gradients_;
  std::vector<std::size_t> dynamicSets_, boundarySets_;
  ImplicitSolver implicit_;
  PressureSolver pressure_;
  std::vector<ObjectMotion> wallMotions_;
  double flatWallShare_; ///< D of a particle resting on a flat wall (WallContact.hpp)
  bool hasRigidBodies_ = false;
  std::vector<RigidBody> rigidBodies_; ///< their states are in state_.rigidBodies, same order
  std::vector<double> wallReach_;      ///< by motion: largest distance of its body's particles from its axis [m]
  StepReport report_;
  PhaseTimes phases_;
  StateSnapshot snapshot_;          ///< before the current step: undoes a step that ends in NaN
  std::optional<Domain> domain_;    ///< particles outside it fail the leaving-domain check
  std::size_t outsideReported_ = 0; ///< particles outside the domain already warned about (policy warn)
  RunWarnings warnings_;
  std::set<std::size_t> rigidBodiesOutside_; ///< bodies outside the domain already warned about (policy warn)
  long long lastWrittenStep_ = -1;
  long long sortedAtStep_ = -1;     ///< the step whose Morton sort is done (sortIfDue)
  bool startChecked_ = false;       ///< checkStart() ran (main calls it before anything is written)
  GhostExchange* ghosts_ = nullptr; ///< a parallel run's ranks, else null
  long long injectNaNStep_ = -1;
};

} // namespace poro
