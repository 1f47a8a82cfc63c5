#pragma once
/// Porous IISPH pressure solve (METHOD.md §6.6, §6.7; Eq. 5-8): predicted densities, then relaxed Jacobi
/// sweeps on pi = rho^max p / rho^2, clamped at 0, warm-started, every set updated together; from the fourth sweep
/// on, Chebyshev-accelerated unless pressure.acceleration is none (it is under preset reference).
/// Keys: system/solverDict pressure.{maxDensityError, minIterations, maxIterations, relaxation, warmStart,
/// acceleration, spectralRadius};
/// compatibility.pressureSweep setSequential solves the sets one after another (fluid first, then the porous
/// materials in file order), each against the others' latest a^p; pressureWarmStartCap reference caps the
/// warm start (METHOD.md §10).

#include "physics/SolverSettings.hpp"
#include "physics/StepContext.hpp"

#include <utility>
#include <vector>

namespace poro {

struct PressureStats {
  int iterations = 0;
  double meanError = 0.0;        ///< mean compression of the worst set in the last sweep [% of rho^max]
  double maxError = 0.0;         ///< largest single-particle compression in the last sweep [%]
  double maxSkeletonError = 0.0; ///< the same over the porous sets' particles alone [%]
  bool converged = false;
};

class PressureSolver {
public:
  explicit PressureSolver(const PressureSettings& settings) : settings_(settings) {}

  /// Scratch of a solve, per particle side by side in one Vec3 field: rho~* (Eq. 6), the sweep's compression
  /// max(-r, 0) and the pi of the sweep before (Chebyshev). A sweep reads the three of a particle together, and the
  /// field can use storage of the implicit solve, which is done before predictDensities (Solver shares them).
  static constexpr const char* sweepStateField = "pressureSweepState";
  enum SweepSlot : int { kPredictedDensity = 0, kResidual = 1, kPreviousPi = 2 };

  /// Registers pi (restart), pressure (output) and the solver's scratch fields. With setSequential a^p is
  /// restart state too: the first sets of a step see the previous step's a^p of the sets not yet solved.
  static void registerFields(ParticleSet& set, const CompatibilitySettings& compatibility);

  /// rho~* = rho~ + dt [sum f V (v*_a - v*_b).gradW_ab + sum V_k (v*_a - v_k).gradW_ak] (Eq. 6).
  void predictDensities(const StepContext& ctx) const;

  /// Solves for pi, then v <- v* + dt a^p for every dynamic set. Needs predictDensities first.
  /// With setSequential, `iterations` is the most any one set needed.
  PressureStats solve(const StepContext& ctx) const;

  /// pi <- the warm start from the previous step's pi where rho~* > 1, else 0 (METHOD.md §6.7, §10).
  void warmStart(const StepContext& ctx) const;

  /// p = pi rho^2 / rho^max of every particle of `sets` from the pi and densities they hold, as solve() leaves it
  /// (after a restore: the snapshot does not copy p).
  static void formPressures(ParticleSystem& particles, const std::vector<std::size_t>& sets);

  /// The particle left most compressed by the last solve (set, index), for messages when it did not converge.
  static std::pair<std::size_t, std::size_t> mostCompressed(const ParticleSystem& particles,
                                                            const std::vector<std::size_t>& sets);

  /// (A pi)_a of the current pi for every particle, by dynamic set (tests probe the operator with it).
  std::vector<std::vector<double>> applyOperator(const StepContext& ctx) const;
  /// (A pi)_a from the a^p each set holds now, without recomputing them (tests of the sequential sweep).
  std::vector<std::vector<double>> operatorOfStoredAccelerations(const StepContext& ctx) const;

private:
  void computeAccelerations(const StepContext& ctx, const std::vector<std::size_t>& sets) const;
  /// Relaxed Jacobi sweeps updating pi of `sets` until their errors converge; leaves their a^p from that pi.
  PressureStats iterate(const StepContext& ctx, const std::vector<std::size_t>& sets) const;
  PressureSettings settings_;
};

} // namespace poro
