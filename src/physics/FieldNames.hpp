#pragma once
/// Names of the per-particle fields the solver registers (METHOD.md §7 lists what a restart saves).

namespace poro::field {

// Restart state.
inline constexpr const char* pi = "pi";         ///< pi = rho^max p / rho^2 of the last pressure solve [m^2/s^2]
inline constexpr const char* deltaV = "deltaV"; ///< last implicit increment u - v^n (CG warm start) [m/s]
inline constexpr const char* fixed = "fixed"; ///< porous: 1 = Fixed (held in place, METHOD.md §4.2), 0 = Active (Int)
/// porous: the Fixed flags as sampled (particleDict `fixed`), before a material's fixedBox adds to them (Int)
inline constexpr const char* sampledFixed = "sampledFixed";
inline constexpr const char* restPosition = "X"; ///< porous: initial position X (METHOD.md §4.1) [m]
inline constexpr const char* rotation = "R";     ///< elastic porous: rotation R of the last step (warm start, §6.5.2)
inline constexpr const char* materialId = "materialId"; ///< porous: index of the material in porosityProperties (Int)
/// porous with wall contact: kappa, the wall-contact pressure of the last solve (WallContact.hpp) [m^2/s^2]
inline constexpr const char* contactPressure = "contactPressure";
/// porous with wall contact: the largest wall share D the particle may reach (WallContact.hpp); 0 until set
inline constexpr const char* wallContactLimit = "wallContactLimit";
/// compressible porous whose adhesion fades in full pores: sum_t V Wbar_st at the particle's first step, the share
/// of its kernel support its body covered at rest (PoreFill.hpp); 0 until then
inline constexpr const char* restCoverage = "restCoverage";
/// parallel runs: where the particle stood when the ranks last migrated and searched afresh; the Verlet skin is
/// reused, without migrating, until some particle has moved half the skin from it (Solver::searchNeighbours) [m]
inline constexpr const char* searchOrigin = "searchOrigin";
// Output only.
inline constexpr const char* density = "density";             ///< rho [kg/m^3]
inline constexpr const char* pressure = "pressure";           ///< p = pi rho^2 / rho^max [Pa]
inline constexpr const char* saturation = "saturation";       ///< porous: S (Eq. 12), in [0, 1]
inline constexpr const char* localPorosity = "localPorosity"; ///< fluid: phi^loc, share of the volume open to fluid
// Scratch, recomputed every step.
inline constexpr const char* rhoTilde = "rhoTilde";           ///< normalised density rho / rho^max
inline constexpr const char* alpha = "alpha";                 ///< 1/(|G|^2 + Q), the pressure diagonal factor [m^2]
inline constexpr const char* gradSum = "gradSum";             ///< G = sum f V gradW [1/m]
inline constexpr const char* accelP = "accelP";               ///< pressure acceleration a^p [m/s^2]
inline constexpr const char* wallShare = "wallShare";         ///< porous with wall contact: D = sum_k V_k W_ak
inline constexpr const char* wallShareStar = "wallShareStar"; ///< porous with wall contact: D predicted with v*
inline constexpr const char* wallGradient = "wallGradient";   ///< porous with wall contact: sum_k V_k gradW_ak [1/m]
/// porous of an adhering material whose adhesion fades: how full the pores near the particle are, 1 = full
/// (PoreFill.hpp)
inline constexpr const char* poreFill = "poreFill";

} // namespace poro::field
