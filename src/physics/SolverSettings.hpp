#pragma once
/// system/solverDict (METHOD.md §9): pressure solve, implicit solve, neighbour search, threads, and what to do
/// when the numerics go wrong (health).

#include "core/Types.hpp"

#include <optional>

namespace poro {
class Dictionary;

struct PressureSettings {
  double maxDensityError = 0.01; ///< mean compression per set [% of rho^max], > 0
  /// Largest compression of any one particle at convergence [% of rho^max]; 0: no bound (the mean alone, as
  /// published). With the mean alone a few compressed particles can wait until the rest of the set's error has
  /// drifted up to the tolerance, and then be released at once (bench/README.md, 2026-12-01).
  double maxParticleDensityError = 0.0;
  /// The same bound for the particles of porous skeletons alone [% of rho^max]; 0: none. A skeleton held by the
  /// mean alone can creep into compression in alternate layers until one step releases it, and the gap water beside
  /// it is thrown (bench/README.md, 2026-12-02). Default 0.2; 0 (the mean alone, as published) when
  /// system/solverDict names a compatibility preset. The key, when given, always wins.
  double maxSkeletonParticleDensityError = 0.2;
  int minIterations = 2;
  int maxIterations = 100;
  double relaxation = 0.5; ///< Jacobi relaxation omega, (0, 1]
  double warmStart = 0.5;  ///< warm-start factor, [0, 1]
  /// acceleration: chebyshev (true) | none (false, the relaxed Jacobi of METHOD.md §6.7 alone). Default chebyshev;
  /// none when compatibility names preset reference. The key, when given, always wins.
  bool chebyshev = true;
  double spectralRadius = 0.9; ///< Chebyshev's estimate of the sweeps' convergence factor, (0, 1)
  /// poreFluidDensity: paper (false, Eq. 4 as it stands) | latticeCorrected (true, PoreFluidDensityBias.hpp).
  /// Default latticeCorrected, so pores hold phi V; paper when system/solverDict names a compatibility preset.
  bool latticeCorrectedPoreFluid = true;
  /// wallContact: allSkeletons (true) | compressibleSkeletons (false): which porous skeletons get the contact
  /// constraint of WallContact.hpp. An incompressible skeleton otherwise meets a wall through its density alone, and
  /// a particle short of neighbours (a ball's underside) sinks into the floor: 0.54 r for a ball of radius 4r
  /// (WallContactTest). Default allSkeletons; compressibleSkeletons when system/solverDict names a compatibility
  /// preset. The key, when given, always wins.
  bool wallContactAllSkeletons = true;
};

struct ImplicitSettings {
  double tolerance = 1e-4; ///< relative CG residual, (0, 1)
  int maxIterations = 100;
  bool preconditioner = true; ///< blockJacobi (true) or none
  /// adhesionInFullPores: fades (true, PoreFill.hpp) | paper (false, Eq. 13 as it stands). Default fades; paper
  /// when system/solverDict names a compatibility preset. The key, when given, always wins.
  bool adhesionFadesInFullPores = true;
};

/// What a failed health check does: warn and go on, remove the particles concerned (with a warning), or stop
/// the run after writing the last good state.
enum class HealthAction { Warn, Remove, Stop };

/// Box-shaped region particles may not leave.
struct Domain {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  bool contains(const Vec3& p) const { return (p.array() >= min.array()).all() && (p.array() <= max.array()).all(); }
};

struct HealthSettings {
  HealthAction nonFinite = HealthAction::Stop;          ///< NaN/inf position or velocity: stop | remove
  HealthAction leavingDomain = HealthAction::Remove;    ///< outside `domain`: warn | remove | stop
  HealthAction pressureIterations = HealthAction::Warn; ///< pressure.maxIterations reached: warn | stop
  HealthAction implicitIterations = HealthAction::Warn; ///< implicit.maxIterations reached: warn | stop
  /// Largest normalised density rho/rho^max a particle that can move may start a run with (step 0 only, see
  /// physics/StartDensity.hpp); above it the run stops before step 1. >= 1.
  double startDensity = 1.005;
  /// Absent: the walls' bounding box grown by its longest side in every direction (no check without walls).
  std::optional<Domain> domain;
};

/// The switches of METHOD.md §10: the defaults follow the paper; the alternatives reproduce the behaviour behind
/// the authors' published setups (block `compatibility` of system/solverDict; `preset: reference` sets the five
/// switches of the table; the warm-start cap, meant for number-level comparisons, only by its own key).
struct CompatibilitySettings {
  bool unitLambdaVolumetricStress = false; ///< volumetricStress: lambda (false) | unitLambda: k_l tr(eps) I
  bool lambdaScaledBloating = false;       ///< bloatingStress: absolute (false) | lambdaScaled: -lambda eta S I
  bool deltaTScaledInitialGuess = false;   ///< implicitInitialGuess: deltaV (false) | deltaTDeltaV: v^n + dt dv
  bool restCouplingSolidDensity = false;   ///< couplingSolidDensity: current rho_t (false) | rest: rho_b in Eq. 11, 16
  bool setSequentialPressure = false;      ///< pressureSweep: jacobi (false) | setSequential: one set after another
  bool cappedPressureWarmStart = false;    ///< pressureWarmStartCap: none (false) | reference: 2.5e-4 m^2 / dt^2

  /// The alternatives of the five switches of METHOD.md §10 at once (`preset: reference`); not the cap.
  static CompatibilitySettings reference();
};

struct SolverSettings {
  PressureSettings pressure;
  /// XSPH smoothing eps of the fluid velocities (XsphSmoothing.hpp), [0, 1]. Not in the paper, and off by default:
  /// it acts like a viscosity of about 0.05 eps H^2 / dt, which slows seepage and sinking bodies.
  double xsph = 0.0;
  ImplicitSettings implicit;
  CompatibilitySettings compatibility;
  HealthSettings health;
  int sortInterval = 500;  ///< Morton reorder period in steps, 0 = never
  double searchSkin = 0.1; ///< Verlet skin of the neighbour lists, as a fraction of H; 0 = search every step
  int threads = 0;         ///< OpenMP threads, 0 = the OpenMP default

  /// Reads and validates every key; unknown keys are errors.
  static SolverSettings read(const Dictionary& dict);
};

} // namespace poro
