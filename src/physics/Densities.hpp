#pragma once
/// Densities, the pressure diagonal, saturation, local porosity and the pair gradient cache
/// (METHOD.md §3.3, §6.3, §6.4; Eq. 1, 3, 4, 12).
///   rho~_a = f(a<-a) V W(0) + sum_b f(a<-b) V W_ab + sum_k V_k W_ak,   rho_a = rho^max_a rho~_a
///   G_a = sum_b f(a<-b) V gradW_ab + sum_k V_k gradW_ak,  Q_a = sum_{b same phase, Active} f^2 (m_a/m_b) V^2
///   |gradW_ab|^2 alpha_a = 1/(|G_a|^2 + Q_a)  (0 for isolated particles) S_s = sum_j V W_sj / (phi_s N_s),  N_s =
///   sum_{t same material, incl. self} (m_t/rho_t) W_st, clamped to [0, 1] phi^loc_i = 1 - sum_t (1 - phi_t) V W_it -
///   sum_k V_k W_ik
/// f is the volume-factor table (physics/VolumeFactors.hpp).

#include "physics/StepContext.hpp"

#include <string>
#include <vector>

namespace poro {

/// Registers the fields the density computation writes (saturation on porous sets, local porosity on
/// the fluid).
void registerDensityFields(ParticleSet& set);

/// Computes rho~, rho, G and alpha of every dynamic set at the current positions, S and phi^loc, and fills
/// `gradients` for every list between dynamic sets and from dynamic sets to walls. In a parallel run for this
/// rank's own particles: their ghosts' values come from their owners (densityFields()).
void computeDensities(const StepContext& ctx, PairGradients& gradients);

/// The fields computeDensities writes (those a set does not register are skipped where they are used).
std::vector<std::string> densityFields();

} // namespace poro
