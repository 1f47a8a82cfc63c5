#pragma once
/// XSPH velocity smoothing of the fluid (Monaghan 1989, J. Comput. Phys. 82; SPlisHSPlasH's default fluid
/// viscosity method) — not in Böttcher et al. 2025. Explicit, on v^n at the start of a step, fluid-fluid pairs only:
///   v_i <- v_i + eps sum_j (2 m / (rho_i + rho_j)) (v_j - v_i) W_ij.
/// The pair weight is symmetric and fluid masses are equal, so every pair exchanges equal and opposite momentum
/// (total momentum is conserved to round-off). It is one damped Jacobi sweep of a graph Laplacian: for
/// eps <= 1 the kinetic energy never grows, and it falls by eps sum_pairs m w W |v_ij|^2 to first order.
/// Walls stay free-slip. Key: system/solverDict xsph [-], in [0, 1].

#include "physics/StepContext.hpp"

namespace poro {

/// Smooths the fluid's velocities with strength `eps` (nothing when eps = 0 or there is no fluid).
void smoothFluidVelocities(const StepContext& ctx, double eps);

} // namespace poro
