#pragma once
/// system/particleDict: the particle radius and the regions sampleParticles turns into particles.
///   particleRadius: 0.005
///   regions:
///     - {name: water, phase: fluid, shape: box, min: [..], max: [..], velocity: [0, 0, 0]}
///     - {name: bed, phase: porous, material: sand, shape: box, min: [..], max: [..], fixed: false}
///     - {name: tank, phase: boundary, shape: container, min: [..], max: [..], layers: 2, open: [yMax]}

#include "core/Types.hpp"
#include "geometry/LatticeSampling.hpp"
#include "physics/PorousMaterial.hpp"

#include <string>
#include <vector>

namespace poro {
class Dictionary;

struct ParticleRegion {
  enum class Phase { Fluid, Porous, Boundary };
  enum class Shape { Box, Container };
  std::string name;
  Phase phase = Phase::Fluid;
  Shape shape = Shape::Box;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  Vec3 velocity = Vec3::Zero(); ///< initial velocity of fluid and porous regions [m/s]
  std::size_t materialId = 0;   ///< porous: index of its material in constant/porosityProperties
  bool fixed = false;           ///< porous: particles held in place (Fixed, METHOD.md §4.2)
  int layers = 2;               ///< wall layers of a container
  FaceFlags open{};             ///< faces of a container without wall
};

struct ParticleDict {
  double particleRadius = 0.0;
  std::vector<ParticleRegion> regions;

  /// Reads and validates every key. `materials` are those of constant/porosityProperties (empty when the case
  /// has none): a porous region must name one of them. Before anything is sampled, it also refuses a region
  /// that would hold no particle, a case without fluid region, and a particleRadius that would give a set more
  /// particles than a 32-bit index counts or need more memory to sample than the machine has.
  static ParticleDict read(const Dictionary& dict, const std::vector<PorousMaterial>& materials);
};

} // namespace poro
