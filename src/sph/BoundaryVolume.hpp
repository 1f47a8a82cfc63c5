#pragma once
/// Akinci et al. 2012 boundary particle volumes (METHOD.md §6.2): V_k = 1/(W(0) + sum_{c != k, same body} W_kc).

#include "sph/Kernel.hpp"
#include "sph/ParticleSet.hpp"

namespace poro {

/// Name of the boundary volume field V_k [m^3].
inline constexpr const char* kBoundaryVolumeField = "volume";

/// Computes V_k for every particle of a boundary set from its positions and object ids (bodies are
/// rigid, so this is done once per body) and stores it in the set's "volume" field.
void computeBoundaryVolumes(ParticleSet& boundary, const CubicKernel& kernel);

} // namespace poro
