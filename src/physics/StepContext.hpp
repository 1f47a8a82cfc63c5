#pragma once
/// What every part of one time step sees (STYLE.md §5: no globals; everything arrives through here).

#include "physics/FluidProperties.hpp"
#include "physics/GhostExchange.hpp"
#include "physics/PoreFill.hpp"
#include "physics/PoreFluidDensityBias.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/SolverSettings.hpp"
#include "sph/Kernel.hpp"
#include "sph/NeighbourSearch.hpp"
#include "sph/ParticleSystem.hpp"

#include <vector>

namespace poro {

/// Per-pair kernel gradient factors s_ab (gradW_ab = s_ab x_ab), stored in the order of the neighbour
/// lists so the iterative solvers do not re-evaluate the kernel.
class PairGradients {
public:
  void resize(std::size_t sets) {
    factors_.assign(sets * sets, {});
    sets_ = sets;
  }
  std::vector<double>& of(std::size_t a, std::size_t b) { return factors_[a * sets_ + b]; }
  const std::vector<double>& of(std::size_t a, std::size_t b) const { return factors_[a * sets_ + b]; }

private:
  std::size_t sets_ = 0;
  std::vector<std::vector<double>> factors_;
};

struct StepContext {
  ParticleSystem& particles;
  const NeighbourSearch& search;
  const PairGradients& gradients;
  const CubicKernel& kernel;
  const FluidProperties& fluid;
  double dt;                                    ///< the step size of this step [s]
  std::vector<std::size_t> dynamicSets;         ///< fluid and porous sets: the unknowns
  std::vector<std::size_t> boundarySets;        ///< walls: known positions and velocities
  std::vector<const PorousMaterial*> materials; ///< by set index: the material of a porous set, else null
  CompatibilitySettings compatibility;          ///< METHOD.md §10 (defaults: the paper's behaviour)
  double previousDt = 0.0;                      ///< the step size of the step before [s], 0 before the first
  const PoreFluidDensityBias* poreFluidBias = nullptr; ///< pressure.poreFluidDensity latticeCorrected, else null
  GhostExchange* ghosts = nullptr;                     ///< a parallel run's ranks, else null
  const PoreFill* poreFill = nullptr; ///< implicit.adhesionInFullPores fades and some material adheres, else null

  /// Particles of set a this rank computes: all of them in a serial run.
  std::size_t owned(std::size_t a) const { return ghosts ? ghosts->owned(a) : particles[a].size(); }
  /// Ghosts get their owners' `names` fields (every field when empty); nothing in a serial run.
  void refreshGhosts(const std::vector<std::string>& names = {}) const {
    if (ghosts) ghosts->refresh(particles, names);
  }
  double sumOverRanks(double value) const { return ghosts ? ghosts->sum(value) : value; }
  double maxOverRanks(double value) const { return ghosts ? ghosts->max(value) : value; }
};

} // namespace poro
