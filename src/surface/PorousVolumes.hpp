#pragma once
/// Volumes of porous particles in their deformed state, for the colour field of a porous body: a body that swells
/// (bloating) or is squeezed keeps c = 1 inside, as a rest lattice does, instead of thinning out below the
/// iso-level.

#include <vector>

namespace poro {

class ParticleSet;

/// V_s = (2r)^3 det F_s with the deformation gradient of the rest neighbours (the corrected SPH gradient the
/// elasticity uses, physics/ElasticRestState, solver kernel H = 4r):
///   F_s = sum_{t in N0(s)} V0_t (x_t - x_s) (L_s gradW(X_s - X_t))^T,
/// exact for any affine motion, at a body's faces too (the correction L_s accounts for the missing neighbours).
/// det F is clamped to [0.05, 20] where a body tears or folds. A set without rest positions (X) gets (2r)^3 for
/// every particle.
std::vector<double> deformedVolumes(const ParticleSet& set, double particleRadius);

} // namespace poro
