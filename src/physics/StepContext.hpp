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

#include <limits>
#include <vector>

namespace poro {

/// Per-pair numbers kept for a step (kernel gradient factors, the implicit terms' coefficients) are computed in
/// double and stored in single precision: half the bytes of the largest arrays, at a relative rounding of
/// 6e-8, far below the solvers' tolerances. Both sides of a pair round the same double, so pair forces stay
/// equal and opposite, and the operators symmetric. The state and every sum stay in double.
using PairFactor = float;
/// The relative rounding of one stored pair number, 2^-24.
inline constexpr double kPairFactorRounding = std::numeric_limits<PairFactor>::epsilon() / 2;

/// Per-pair kernel gradient factors s_ab (gradW_ab = s_ab x_ab), stored in the order of the neighbour
/// lists so the iterative solvers do not re-evaluate the kernel.
class PairGradients {
public:
  void resize(std::size_t sets) {
    factors_.assign(sets * sets, {});
    sets_ = sets;
  }
  std::vector<PairFactor>& of(std::size_t a, std::size_t b) { return factors_[a * sets_ + b]; }
  const std::vector<PairFactor>& of(std::size_t a, std::size_t b) const { return factors_[a * sets_ + b]; }

private:
  std::size_t sets_ = 0;
  std::vector<std::vector<PairFactor>> factors_;
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
