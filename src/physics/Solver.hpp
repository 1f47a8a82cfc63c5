#pragma once
/// The PoroSPH solver: the algorithm of one time step (METHOD.md §5) and the time loop around it.
/// Output is not its business: run() calls a writer at every write time (io implements it).

#include "core/Timer.hpp"
#include "linalg/ConjugateGradient.hpp"
#include "physics/FluidProperties.hpp"
#include "physics/ImplicitSolver.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/PressureSolver.hpp"
#include "physics/SolverSettings.hpp"
#include "physics/StepContext.hpp"
#include "physics/TimeControl.hpp"

#include <functional>
#include <memory>

namespace poro {

/// Where a run stands: what uniform/time stores (METHOD.md §7).
struct RunState {
  double time = 0.0;
  long long step = 0;
  double nextDeltaT = 0.0; ///< the step size of the coming step [s]
};

/// What the last step did, for the progress log and postProcessing.
struct StepReport {
  double deltaT = 0.0;
  PressureStats pressure;
  linalg::CgResult implicit;
  double maxSpeed = 0.0;
  double maxFluidDensity = 0.0; ///< largest fluid rho~ = rho^/rho_f^0 at the start of the step (Eq. 4)
  double maxPoreFluidDensity = 0.0; ///< the same over fluid particles with porous neighbours
};

class Solver {
public:
  /// Takes the particles of a case (loaded from 0/ or a restart time directory) and validated settings.
  /// Each porous set is named after its material in `materials` (constant/porosityProperties).
  Solver(ParticleSystem particles, const FluidProperties& fluid, std::vector<PorousMaterial> materials,
         const SolverSettings& settings, const TimeControl& control, const RunState& start);

  /// Called at each write time and at the end; receives the solver to read particles and state from.
  using Writer = std::function<void(const Solver&)>;
  /// Advances to endTime, logging progress per step and calling `write` at every write time. SIGINT or
  /// SIGTERM (core/StopSignals.hpp) end the run after the current step, which is written; returns that
  /// signal, or 0 when endTime was reached.
  int run(const Writer& write);
  /// One time step of size `deltaT` (METHOD.md §5).
  void step(double deltaT);
  /// Steps 1-4 of METHOD.md §5 at the current positions (neighbour search, densities, alpha, saturation,
  /// local porosity) and the context the rest of the step uses; step() starts with it, tests probe it.
  StepContext beginStep(double deltaT);
  ImplicitSolver& implicitSolver() { return implicit_; }
  const PressureSolver& pressureSolver() const { return pressure_; }

  const ParticleSystem& particles() const { return particles_; }
  ParticleSystem& particles() { return particles_; }
  const RunState& state() const { return state_; }
  const StepReport& lastStep() const { return report_; }
  const PhaseTimes& phaseTimes() const { return phases_; }
  const TimeControl& timeControl() const { return control_; }
  /// Replaces the time settings while running (runTimeModifiable); the next step uses them.
  void setTimeControl(const TimeControl& control) { control_ = control; }

private:
  StepContext context(double deltaT);
  void searchNeighbours();
  double maxSpeed() const;
  void measureFluidDensity();
  void checkFinite() const;
  double stepSizeFor(double deltaT) const;
  bool isWriteStep(double previousTime) const;
  double endSlack() const;

  void setUpPorousSet(ParticleSet& set, const PorousMaterial& material);

  ParticleSystem particles_;
  FluidProperties fluid_;
  std::vector<PorousMaterial> materials_;
  std::vector<const PorousMaterial*> setMaterials_; ///< by set index
  SolverSettings settings_;
  TimeControl control_;
  RunState state_;
  CubicKernel kernel_;
  NeighbourSearch search_;
  PairGradients gradients_;
  std::vector<std::size_t> dynamicSets_, boundarySets_;
  ImplicitSolver implicit_;
  PressureSolver pressure_;
  StepReport report_;
  PhaseTimes phases_;
};

} // namespace poro
