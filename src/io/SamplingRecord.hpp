#pragma once
/// What the particles of a time directory were sampled from: `<t>/uniform/sampling`,
/// written by sampleParticles into 0/ and copied by TimeWriter into every later time directory, so that a run from any
/// of them is checked against the case as it stands. It holds
///   regions:          every region of system/particleDict as sampled, in order, with every key but a wall's `motion`
///                     (poroSph reads motions at run time, so they may change between runs), each value in
///                     Dictionary::canonical form: comments, layout, quoting, key order and the spelling of a number
///                     ("0.20", "2e-1") are no change, any other edit is. A surface region also gets `fileDigest`, the
///                     FNV-1a digest of its surface file's bytes.
///   porousMaterials:  the material each materialId of porous.vtp stands for. porous.vtp stores only the index into
///                     constant/porosityProperties, so reordering that file would silently swap materials.
/// Values are kept rather than a digest of them, so that a refusal can say what changed from what. Time directories
/// written before the record existed have none, and their checks are skipped.

#include "core/Dictionary.hpp"
#include "physics/PorousMaterial.hpp"
#include "sph/ParticleSystem.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace poro {

/// The record's file name in a time directory's `uniform/`.
inline constexpr const char* kSamplingRecordName = "sampling";

/// The text of `uniform/sampling` for what sampleParticles is about to write: `particleDict` as it was read for
/// sampling, the surface files its surface regions name in `surfaceDirectory`, and the porous sets of `particles`,
/// each named after its material in `materials` (constant/porosityProperties order).
std::string samplingRecord(const Dictionary& particleDict, const std::filesystem::path& surfaceDirectory,
                           const ParticleSystem& particles, const std::vector<PorousMaterial>& materials);

/// Refuses, with an InputError that names what changed and how to fix it, a run from `timeDir` when the regions of
/// the case's system/particleDict are not those its particles were sampled from: a region added, removed or moved
/// in the list (objectId is a region's position), a key of a region changed, added or removed (a wall's `motion`
/// aside), or a surface file changed (one that is no longer there cannot be compared and is passed over).
void checkSampledRegions(const std::filesystem::path& caseDir, const std::filesystem::path& timeDir);

/// Refuses reading porous.vtp of `timeDir` when a materialId would now name another material than the one it was
/// sampled as: constant/porosityProperties reordered, or a sampled material renamed or removed.
void checkSampledMaterials(const std::filesystem::path& caseDir, const std::filesystem::path& timeDir,
                           const std::vector<PorousMaterial>& materials);

} // namespace poro
