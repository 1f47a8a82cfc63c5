#pragma once
/// system/particleDict: the particle radius and the regions sampleParticles turns into particles.
///   particleRadius: 0.005
///   regions:
///     - {name: water, phase: fluid, shape: box, min: [..], max: [..], velocity: [0, 0, 0]}
///     - {name: tank, phase: boundary, shape: container, min: [..], max: [..], layers: 2, open: [yMax]}

#include "core/Types.hpp"
#include "geometry/LatticeSampling.hpp"

#include <string>
#include <vector>

namespace poro {
class Dictionary;

struct ParticleRegion {
  enum class Phase { Fluid, Boundary };
  enum class Shape { Box, Container };
  std::string name;
  Phase phase = Phase::Fluid;
  Shape shape = Shape::Box;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  Vec3 velocity = Vec3::Zero(); ///< initial velocity of fluid regions [m/s]
  int layers = 2;               ///< wall layers of a container
  FaceFlags open{};             ///< faces of a container without wall
};

struct ParticleDict {
  double particleRadius = 0.0;
  std::vector<ParticleRegion> regions;

  static ParticleDict read(const Dictionary& dict);
};

} // namespace poro
