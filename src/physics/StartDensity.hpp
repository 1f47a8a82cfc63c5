#pragma once
/// The start check of solverDict `health.startDensity`: particles that
/// start a run packed denser than their density limit. Incompressibility is rho~ = rho/rho^max <= 1
/// (METHOD.md §3.3), so the first pressure solve pushes any excess apart within one step, at speeds of order
/// (rho~ - 1) 2r / deltaT: a smaller deltaT makes the start more violent, not gentler (measured, r = 2 cm,
/// rho~ = 1.020: max |v| 2.2, 25 and 314 m/s after 3 ms at deltaT = 1e-3, 1e-4 and 1e-5 s).
/// On the lattice (two wall layers, any r) a fluid box whose faces are the wall surface, i.e. whose first
/// layer is 2r from the first wall layer, starts at 1.047 at its edges (1.026 on flat faces, METHOD.md
/// §2.2); 0.05 r off the walls at 1.020, 0.067 r off at 1.010, 0.1 r off at the interior value 0.99997.
///
/// The default limit 1.005 lies between what a sound start has and what a wall too close gives: every shipped
/// tutorial, full and coarse, starts at 0.99997; pre-saturated pore fluid at <= 1.0008; a state a run settled
/// to (reused as an initial condition) at <= 1.004 (hydrostatic tank 1.0012, floating block 1.0034 over
/// 0.3 s); regions less than about 0.08 r off the walls exceed it.
///
/// Judged are fluid particles and Active porous particles (Fixed ones never move). Fluid in pores is judged
/// without the cubic spline's excess over the pore lattice (PoreFluidDensityBias) when the run does not
/// subtract it itself (pressure.poreFluidDensity: paper): a body pre-saturated at its porosity (pore fluid at
/// spacing 2r phi^(-1/3)) then starts at <= 1.001 in both modes instead of 1.047 (phi = 0.4, paper), while
/// fluid sampled through a porous body on the full lattice (rho~ = 2 - phi, judged 1.554 at phi = 0.4) is
/// refused.

#include "physics/StepContext.hpp"

#include <string>
#include <vector>

namespace poro {

/// The gap between a region's particles and the walls, in units of r, that starts its first layer at rho~ <= 1:
/// the space left between the particles' surfaces, centre distance - 2r (a lattice box 0.1 r inside the wall
/// surface). sampleParticles warns below it.
inline constexpr double kStartWallGap = 0.1;

/// The densest judged particle of one set at the start.
struct DensestParticle {
  std::size_t set = 0;
  std::size_t index = 0; ///< in the set
  double density = 0.0;  ///< its judged rho~
  std::size_t above = 0; ///< particles of the set above the limit
};

/// For every dynamic set of `ctx` with particles to judge: its densest particle and how many exceed `limit`.
/// Needs the densities of the current positions (Solver::beginStep).
std::vector<DensestParticle> densestAtStart(const StepContext& ctx, double limit);

/// "fluid 0.99997, soil 1.0003": the densest value of each set, for the log.
std::string listDensest(const ParticleSystem& particles, const std::vector<DensestParticle>& densest);

/// The message refusing a start above `limit`: for each set above it, how many particles, the densest with
/// id, position and value and how far its nearest wall particle is; then the cure. Starts with the file of the
/// first such set (ParticleSet::source) when known.
std::string describeOverDense(const StepContext& ctx, const std::vector<DensestParticle>& densest, double limit);

} // namespace poro
