#pragma once
/// Porous particle sets on disk (ARCHITECTURE.md "A case directory"). In memory there is one porous set per
/// material, named after it; a time directory holds all of them in one file `porous.vtp`, concatenated in
/// ParticleSystem order, whose Int field `materialId` (physics/FieldNames.hpp) is the index of each
/// particle's material in constant/porosityProperties.

#include "io/ParticleVtk.hpp"
#include "physics/PorousMaterial.hpp"
#include "sph/ParticleSystem.hpp"

#include <filesystem>
#include <vector>

namespace poro {

/// Name of the merged set, its file stem (`porous.vtp`) and its case.pvd part.
inline constexpr const char* kPorousSetName = "porous";

/// What porous.vtp holds: every porous set of `particles` in ParticleSystem order, named "porous" (kind Porous),
/// with every field of role Output or Restart that any of them has, sorted by name; Scratch fields are left out.
/// Materials differ in their fields (elasticity, wall contact, ...): a set without one of them is written as zeros
/// there, which its model reads back as unset if it takes the field up later. The sets are referred to, not
/// copied. Throws std::logic_error when two sets have a field of one name with another type or role, or a set
/// lacks the Int field materialId.
ParticleFile porousFile(const ParticleSystem& particles);

/// Splits a set read from `file` (porous.vtp) by its Int field materialId into one set per material, named
/// materials[id].name, kind Porous, appended to `into` in material order; materials without particles get
/// no set, unless `everyMaterial` (a rank's share of a decomposed case: every rank holds the same sets). Each keeps the
/// file order of its particles and every field of `merged` (Real, Vec3, Mat3, Int) with the same role; materialId
/// becomes a Restart field. Throws InputError naming `file` when `materials` is empty (the case has no
/// constant/porosityProperties), when the file has no Int field materialId, or when a materialId lies outside [0,
/// materials.size()) (naming the first such particle's id).
void splitPorousSet(ParticleSet&& merged, const std::vector<PorousMaterial>& materials, ParticleSystem& into,
                    const std::filesystem::path& file, bool everyMaterial = false);

} // namespace poro
