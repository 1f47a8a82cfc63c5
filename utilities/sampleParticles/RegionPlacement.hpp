#pragma once
/// Checks of the sampled regions of system/particleDict against each other, after sampling and before anything is
/// written. Each region's particles carry its index in `regions` as objectId.
///
/// Overlaps. Two regions must not sample the same space: where they do, the density is twice the rest density and
/// the first pressure solve blows the particles apart (such cases ran at up to 55,940 m/s). Refused are
/// particles of two regions closer than kOverlapFraction * 2r for the pairs fluid-fluid, fluid-wall, porous-wall and
/// porous-porous (bodies do not interpenetrate, METHOD.md §3.2). Fluid inside a porous region stays allowed (a
/// pre-saturated body), and walls may overlap walls (a wall particle's volume comes from its wall neighbours).
///
/// Regions outside every wall. A fluid or porous region none of whose particles lies in the space the case's walls
/// enclose is refused (a box beside the tank fell away, or was removed as leaving the domain at step 1). That space
/// is the union of each container's inner box, unbounded beyond its open faces (a drop may fall into an open tank
/// from above), and the bounding box of each wall body sampled outside its surface (a bowl). Wall boxes and wall
/// bodies sampled inside their surface are obstacles and plates: they enclose nothing, and a case whose walls are
/// all of that kind (fluid poured onto a plate) is not checked.

#include "ParticleRegions.hpp"
#include "sph/ParticleSystem.hpp"

namespace poro {

/// Particles of two regions that must keep apart may come no closer than this fraction of the spacing 2r. Two
/// lattices of spacing 2r that share any space, however offset against each other, have a pair of points no
/// farther apart than sqrt(3) r, half the diagonal of a lattice cell, so sqrt(3)/2 of 2r catches every overlap;
/// regions that merely touch on one lattice are 2r apart, and a wall's first layer lies r behind its face, so a
/// region sampled up to a container's or wall box's face is 2r from the wall (no shipped tutorial has a closer pair).
/// Bodies on lattices of their own (spheres, surfaces) may touch closer than 2r; down to sqrt(3) r they still pass.
/// The 1e-9 counts lattices offset by exactly (r, r, r) as overlapping despite round-off.
inline constexpr double kOverlapFraction = 0.8660254037844386 * (1.0 + 1e-9);

/// Throws an InputError for the first region that lies outside every wall, or else for the first pair of regions
/// whose particles overlap, naming both regions (name, phase, particleDict file:line), how many pairs of their
/// particles are too close and where the closest pair lies.
void checkRegionPlacement(const ParticleDict& dict, const ParticleSystem& particles);

} // namespace poro
