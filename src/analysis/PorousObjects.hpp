#pragma once
/// Porous objects of a particle system: the porous particles of one sampled region. sampleParticles gives
/// every region of system/particleDict its index as objectId, so region k's particles share objectId k
/// whatever their material.

#include "sph/ParticleSystem.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace poro {

struct PorousObject {
  std::int64_t objectId = 0;
  std::string name; ///< the region's name in system/particleDict, else "object<objectId>"
  /// The object's particles as (set number in the ParticleSystem, index in the set), in set order.
  std::vector<std::pair<std::size_t, std::size_t>> particles;
};

/// The porous objects of `particles` by increasing objectId. `regionNames[k]` names objectId k (empty names
/// and ids beyond the list fall back to "object<k>").
std::vector<PorousObject> findPorousObjects(const ParticleSystem& particles,
                                            const std::vector<std::string>& regionNames);

} // namespace poro
