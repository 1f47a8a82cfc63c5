#include "analysis/PorousObjects.hpp"

#include <map>

namespace poro {

std::vector<PorousObject> findPorousObjects(const ParticleSystem& particles,
                                            const std::vector<std::string>& regionNames) {
  std::map<std::int64_t, PorousObject> byId;
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleSet& set = particles[s];
    if (set.kind() != SetKind::Porous) continue;
    const auto& objectIds = set.integer(field::objectId);
    for (std::size_t i = 0; i < set.size(); ++i) byId[objectIds[i]].particles.emplace_back(s, i);
  }
  std::vector<PorousObject> objects;
  for (auto& [id, object] : byId) {
    object.objectId = id;
    const bool named = id >= 0 && static_cast<std::size_t>(id) < regionNames.size() &&
                       !regionNames[static_cast<std::size_t>(id)].empty();
    object.name = named ? regionNames[static_cast<std::size_t>(id)] : "object" + std::to_string(id);
    objects.push_back(std::move(object));
  }
  return objects;
}

} // namespace poro
