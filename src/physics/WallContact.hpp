#pragma once
/// Wall contact of porous solids. The density constraint of a compressible skeleton (rho~ <= 1,
/// METHOD.md §3.3) counts a wall like closed pores, so it pushes back only once the pores next to the wall are
/// shut: a squeezed sponge sank about r into the floor. A second unilateral constraint per particle keeps the
/// walls' share of its kernel, D_a = sum_k V_k W_ak, at most what a flat wall gives a particle resting on it
/// (its centre r in front of the wall surface, like a fluid lattice continuing into the wall):
///   D*_a = D_a + dt sum_k V_k (v*_a - v_k).gradW_ak <= D^max_a,
/// enforced by a contact pressure kappa_a >= 0 in the pressure solve with the force -kappa_a sum_k V_k gradW_ak,
/// the shape of the wall part of the pressure force (so rigid bodies feel its reaction the same way). Fluid is
/// untouched: its density constraint holds it at that distance. Incompressible skeletons take part too unless
/// pressure.wallContact is compressibleSkeletons (either compatibility preset): their density holds a full lattice
/// there, but a particle short of neighbours (a ball's underside) sank half a radius into the floor.
/// D^max_a is the flat-wall share, or the particle's share where it starts closer (in a corner): at step 0, or at the
/// first step of a restart that switches the contact on (a body that sank in before stays that deep).

#include "physics/StepContext.hpp"
#include "sph/Kernel.hpp"

namespace poro {

/// Registers kappa and D^max (restart) and the scratch fields on a porous set. D^max starts at zero (unset) on a set
/// that does not hold it yet (files of older versions hold -1 there); initialiseWallContactLimits sets it.
void registerWallContactFields(ParticleSet& set);
/// Drops those fields from a porous set without wall contact (read with porous.vtp, which holds every set's fields).
void dropWallContactFields(ParticleSet& set);

/// Whether the set takes part in wall contact (it has the fields).
bool hasWallContact(const ParticleSet& set);

/// D of a particle whose centre lies r in front of a flat wall of two Akinci layers on the particle lattice
/// (spacing 2r), the particle right above a wall particle. Only the first layer is within H = 4r of it.
double flatWallShare(const CubicKernel& kernel, double spacing);

/// D^max = max(flat, D) for every particle whose limit is unset (not positive); needs the densities of the step.
void initialiseWallContactLimits(const StepContext& ctx, double flatShare);

/// D* of every contact set from v* (Eq. 6 restricted to the walls).
void predictWallShares(const StepContext& ctx);

/// kappa <- factor kappa where D* > D^max, else 0 (the warm start of pi, METHOD.md §6.7).
void warmStartContactPressure(const StepContext& ctx, double factor);

} // namespace poro
