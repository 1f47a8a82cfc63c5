#pragma once
/// Every particle set of a case (METHOD.md §1): the fluid set, porous sets, then boundary sets, plus the
/// particle radius that fixes the spacing 2r, the support H = 4r and the sampling volume V = (2r)^3.

#include "sph/ParticleSet.hpp"

#include <memory>
#include <string>
#include <vector>

namespace poro {

class ParticleSystem {
public:
  explicit ParticleSystem(double particleRadius = 0.0) : radius_(particleRadius) {}

  double particleRadius() const { return radius_; }
  void setParticleRadius(double r) { radius_ = r; }
  double spacing() const { return 2.0 * radius_; }
  double supportRadius() const { return 4.0 * radius_; }
  double particleVolume() const { return 8.0 * radius_ * radius_ * radius_; }

  /// Adds a set and returns it; names are unique ("fluid", "boundary", material names).
  ParticleSet& add(const std::string& name, SetKind kind);
  /// Adds a set made elsewhere (ParticleSet::select) and returns it; its name must be new.
  ParticleSet& add(ParticleSet&& set);
  std::size_t size() const { return sets_.size(); }
  ParticleSet& operator[](std::size_t i) { return *sets_[i]; }
  const ParticleSet& operator[](std::size_t i) const { return *sets_[i]; }
  /// The set of that name, or nullptr.
  ParticleSet* find(const std::string& name);
  const ParticleSet* find(const std::string& name) const;
  /// Number of particles over all sets.
  std::size_t particleCount() const;

private:
  double radius_;
  std::vector<std::unique_ptr<ParticleSet>> sets_;
};

} // namespace poro
