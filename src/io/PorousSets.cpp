#include "io/PorousSets.hpp"

#include "core/Error.hpp"
#include "physics/FieldNames.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace poro {

namespace {

using FieldInfo = ParticleSet::FieldInfo;

/// The fields a time directory holds (role Output or Restart), sorted by name for comparison.
std::vector<FieldInfo> writtenFields(const ParticleSet& set) {
  std::vector<FieldInfo> fields = set.fields();
  fields.erase(std::remove_if(fields.begin(), fields.end(), [](const FieldInfo& f) { return f.role == Scratch; }),
               fields.end());
  std::sort(fields.begin(), fields.end(), [](const FieldInfo& a, const FieldInfo& b) { return a.name < b.name; });
  return fields;
}

/// Adds to `into` (sorted by name) the fields of `more` it lacks; a name with another type or role is a logic error.
void unite(std::vector<FieldInfo>& into, const std::vector<FieldInfo>& more, const std::string& setName) {
  for (const FieldInfo& f : more) {
    const auto at = std::lower_bound(into.begin(), into.end(), f,
                                     [](const FieldInfo& a, const FieldInfo& b) { return a.name < b.name; });
    if (at == into.end() || at->name != f.name)
      into.insert(at, f);
    else if (at->type != f.type || at->role != f.role)
      throw std::logic_error("porous set '" + setName + "' has field '" + f.name +
                             "' with another type or role than the porous set before it; they cannot share porous.vtp");
  }
}

void registerField(ParticleSet& set, const FieldInfo& f) {
  switch (f.type) {
  case FieldType::Real:
    set.addReal(f.name, f.role);
    break;
  case FieldType::Vec3:
    set.addVec3(f.name, f.role);
    break;
  case FieldType::Mat3:
    set.addMat3(f.name, f.role);
    break;
  case FieldType::Int:
    set.addInt(f.name, f.role);
    break;
  }
}

template <class T> void gather(const std::vector<T>& from, std::vector<T>& to, const std::vector<std::size_t>& slots) {
  for (std::size_t k = 0; k < slots.size(); ++k) to[k] = from[slots[k]];
}

/// Copies slots `slots` of field `f` of `from` into slots 0, 1, ... of `to`.
void gatherField(const ParticleSet& from, ParticleSet& to, const std::vector<std::size_t>& slots, const FieldInfo& f) {
  switch (f.type) {
  case FieldType::Real:
    gather(from.real(f.name), to.real(f.name), slots);
    break;
  case FieldType::Vec3:
    gather(from.vec3(f.name), to.vec3(f.name), slots);
    break;
  case FieldType::Mat3:
    gather(from.mat3(f.name), to.mat3(f.name), slots);
    break;
  case FieldType::Int:
    gather(from.integer(f.name), to.integer(f.name), slots);
    break;
  }
}

std::string materialNames(const std::vector<PorousMaterial>& materials) {
  std::string names;
  for (const PorousMaterial& m : materials) names += (names.empty() ? "" : ", ") + m.name;
  return names;
}

} // namespace

ParticleFile porousFile(const ParticleSystem& particles) {
  ParticleFile file{kPorousSetName, SetKind::Porous, {}, {}};
  for (std::size_t s = 0; s < particles.size(); ++s)
    if (particles[s].kind() == SetKind::Porous) file.parts.push_back(&particles[s]);
  if (file.parts.empty()) return file;
  for (const ParticleSet* set : file.parts) {
    const FieldInfo* material = set->info(field::materialId);
    if (!material || material->type != FieldType::Int || material->role == Scratch)
      throw std::logic_error("porous set '" + set->name() + "' has no Int field '" + field::materialId +
                             "' of role Output or Restart; porous.vtp could not say which material its particles are");
    unite(file.fields, writtenFields(*set), set->name());
  }
  return file;
}

void splitPorousSet(ParticleSet&& merged, const std::vector<PorousMaterial>& materials, ParticleSystem& into,
                    const std::filesystem::path& file, bool everyMaterial) {
  const std::string where = file.string() + ": ";
  if (materials.empty())
    throw InputError(where + "porous particles, but the case defines no porous material; define "
                             "the materials the particles were sampled with in constant/porosityProperties "
                             "(template: etc/caseDicts/porosityProperties)");
  const FieldInfo* material = merged.info(field::materialId);
  if (!material || material->type != FieldType::Int)
    throw InputError(where + "no Int point array '" + field::materialId +
                     "', so the material of each porous particle is unknown; write the file with sampleParticles "
                     "(or add materialId, the index of the material in constant/porosityProperties)");

  // Slots of each material's particles, in file order.
  const auto& ids = merged.integer(field::id);
  const auto& materialIds = merged.integer(field::materialId);
  std::vector<std::vector<std::size_t>> slots(materials.size());
  for (std::size_t i = 0; i < merged.size(); ++i) {
    const std::int64_t m = materialIds[i];
    if (m < 0 || m >= static_cast<std::int64_t>(materials.size()))
      throw InputError(where + "particle id " + std::to_string(ids[i]) + " has materialId " + std::to_string(m) +
                       ", expected 0 to " + std::to_string(materials.size() - 1) +
                       " (the index of its material in constant/porosityProperties, which defines " +
                       materialNames(materials) + ")");
    slots[static_cast<std::size_t>(m)].push_back(i);
  }

  merged.addInt(field::materialId, Restart); // io's own restart field, whatever role the file gave it
  const std::vector<FieldInfo> fields = merged.fields();
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (slots[m].empty() && !everyMaterial) continue;
    ParticleSet& set = into.add(materials[m].name, SetKind::Porous);
    for (const FieldInfo& f : fields) registerField(set, f);
    set.resize(slots[m].size());
    for (const FieldInfo& f : fields) gatherField(merged, set, slots[m], f);
  }
}

} // namespace poro
