#pragma once
/// Densities, the pressure diagonal and the pair gradient cache (METHOD.md §3.3, §6.3; Eq. 1, 4).
///   rho~_a = f(a<-a) V W(0) + sum_b f(a<-b) V W_ab + sum_k V_k W_ak,   rho_a = rho^max_a rho~_a
///   G_a = sum_b f(a<-b) V gradW_ab + sum_k V_k gradW_ak,  Q_a = sum_{b same phase} f^2 (m_a/m_b) V^2 |gradW_ab|^2
///   alpha_a = 1/(|G_a|^2 + Q_a)  (0 for isolated particles)
/// For fluid alone every volume factor is 1.

#include "physics/StepContext.hpp"

namespace poro {

/// Registers the fields the density computation writes.
void registerDensityFields(ParticleSet& set);

/// Computes rho~, rho, G and alpha of every dynamic set at the current positions and fills `gradients`
/// for every list the step uses.
void computeDensities(const StepContext& ctx, PairGradients& gradients);

} // namespace poro
