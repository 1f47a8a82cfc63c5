#include "sph/ParticleSystem.hpp"

#include <stdexcept>

namespace poro {

ParticleSet& ParticleSystem::add(const std::string& name, SetKind kind) {
  if (find(name)) throw std::logic_error("particle set '" + name + "' added twice");
  sets_.push_back(std::make_unique<ParticleSet>(name, kind));
  return *sets_.back();
}

ParticleSet& ParticleSystem::add(ParticleSet&& set) {
  if (find(set.name())) throw std::logic_error("particle set '" + set.name() + "' added twice");
  sets_.push_back(std::make_unique<ParticleSet>(std::move(set)));
  return *sets_.back();
}

ParticleSet* ParticleSystem::find(const std::string& name) {
  for (auto& s : sets_)
    if (s->name() == name) return s.get();
  return nullptr;
}

const ParticleSet* ParticleSystem::find(const std::string& name) const {
  for (const auto& s : sets_)
    if (s->name() == name) return s.get();
  return nullptr;
}

std::size_t ParticleSystem::particleCount() const {
  std::size_t n = 0;
  for (const auto& s : sets_) n += s->size();
  return n;
}

} // namespace poro
