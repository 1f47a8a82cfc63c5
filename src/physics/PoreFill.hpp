#pragma once
/// How full the pores near a porous particle are, and the adhesion's fade in over-full pores (option
/// `implicit.adhesionInFullPores: fades` of system/solverDict; not in the paper).
///
/// Eq. 13 pulls fluid towards every solid neighbour as long as S < 1/eta_cap, and S of Eq. 12 is clamped to 1.
/// Where a body is thinner than the kernel support (strokes 2-3 particles wide) neither the fluid's density
/// estimate nor S sees how much fluid the pores hold: both are kernel sums over a support that is mostly air, and
/// the Shepard sum N_s of Eq. 12 normalises the fluid by the particle volumes m/rho, which the deficient densities
/// of the body's surface inflate. The adhesion then packs two pore volumes of fluid into such a body, and nothing
/// pushes it out. The pore fill
///   F_s = sum_j V W_sj / (phi_s sum_t V Wbar_st),   t over the particles of s's material, s included,
/// compares the fluid near s with the pore volume near s: Wbar is W averaged over a ball of volume V, so the
/// denominator is the kernel's integral over the body's volume (within 2.5 % of it at faces, edges, corners and
/// strokes one particle wide; the plain lattice sum over-counts the own particle, by 10 % on an edge), and the
/// numerator is the same integral over the fluid. F_s = 1 where fluid fills the body's pores at the pore
/// spacing. The adhesion coefficient of the pairs of s is multiplied by fade(F_s): 1 up to 1.05, 0 from 1.1,
/// linear between, so suction never presses fluid into full pores. The fade starts above 1 because a full
/// pore reads up to about 1.05: the coverage is good to 2.5 % and pore fluid at rest fills 0.99-1.03 phi V
/// (PoreFluidDensityBias.hpp); the incompressible pore volume is phi times the coverage, a compressible one
/// is poreVolume below.

#include "physics/PorousMaterial.hpp"
#include "sph/Kernel.hpp"

#include <vector>

namespace poro {
class ParticleSet;

class PoreFill {
public:
  /// Tabulates V Wbar over [0, H] for the kernel and the particle volume V = (2r)^3, scaled so that the simple
  /// cubic lattice of spacing 2r sums to 1 (the neighbour lists end at H, so Wbar is cut there).
  PoreFill(const CubicKernel& kernel, double volume);

  /// V Wbar at distance `dist` [-], 0 from H on.
  double volumeWeight(double dist) const;

  /// The pore volume near s, sum_t V_t^pore Wbar_st, from the body coverage sum_t V Wbar_st at s now
  /// (`coverage`) and at rest (`restCoverage`, < 0 when unknown). Pores of an incompressible material keep
  /// their volume: phi times the coverage. A compressible skeleton keeps its solid volume (1 - phi) V per
  /// particle within the space its body covered at rest, so squeezing closes its pores and swelling opens them:
  /// restCoverage - (1 - phi) coverage, at least 0.
  static double poreVolume(double porosity, bool compressible, double coverage, double restCoverage);

  /// Adds poreFill to the set of an adhering material and, for a compressible one, the restart field
  /// restCoverage, zero (unset) where it was not read back (set at the particle's first step; older files hold -1
  /// there). An incompressible material's set loses a restCoverage read from file.
  static void registerFields(ParticleSet& set, const PorousMaterial& material);

  /// The factor on the adhesion coefficient of a solid particle whose pores are filled to `fill`.
  static double fade(double fill);

  /// The fade runs from kFadeStart to kFadeStart + kFadeWidth.
  static constexpr double kFadeStart = 1.05;
  static constexpr double kFadeWidth = 0.05;

private:
  double step_;               ///< table spacing [m]
  std::vector<double> table_; ///< V Wbar at k step_
};

} // namespace poro
