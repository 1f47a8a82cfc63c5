#pragma once
/// How close each fluid and porous region of system/particleDict comes to the walls, reported after sampling.
/// The gap is the space left between the particles' surfaces, centre distance - 2r: for a box
/// region, the distance of its faces to the wall surface. Below kStartWallGap = 0.1 r the region's first layer
/// starts denser than its density limit and poroSph refuses the start above health.startDensity
/// (physics/StartDensity.hpp), so such a region is warned about here, where it can still be moved.

#include "ParticleRegions.hpp"
#include "sph/ParticleSystem.hpp"

namespace poro {

/// Logs the smallest gap between each fluid and porous region and the wall particles, and warns for the fluid
/// and non-fixed porous regions below kStartWallGap r. Particles belong to the region whose index is their object
/// id (sampleParticles numbers them so).
void reportWallGaps(const ParticleSystem& particles, const ParticleDict& dict);

} // namespace poro
