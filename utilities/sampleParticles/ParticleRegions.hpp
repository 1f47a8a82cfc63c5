#pragma once
/// system/particleDict: the particle radius and the regions sampleParticles turns into particles.
///   particleRadius: 0.005
///   regions:
///     - {name: water, phase: fluid, shape: box, min: [..], max: [..], velocity: [0, 0, 0]}
///     - {name: bed, phase: porous, material: sand, shape: box, min: [..], max: [..], fixed: false}
///     - {name: tank, phase: boundary, shape: container, min: [..], max: [..], layers: 2, open: [yMax]}
///     - {name: drop, phase: fluid, shape: sphere, centre: [..], radius: 0.1}
///     - {name: stone, phase: porous, material: sand, shape: surface, file: stone.stl, scale: 0.01,
///        rotate: {axis: [0, 0, 1], angle: 90}, translate: [..], repair: false}
///     - {name: bowl, phase: boundary, shape: surface, file: bowl.obj, layers: 2, side: outside}
///     - {name: log, phase: rigid, shape: box, min: [..], max: [..], density: 500}   (physics/RigidBody.hpp)
/// Spheres and surfaces (RegionShapes.hpp) are filled on the lattice of their bounding box; as boundaries they
/// are wall bodies of `layers` layers inside the surface, or outside it with `side: outside` (ShapeSampling.hpp).

#include "RegionShapes.hpp"
#include "core/Types.hpp"
#include "geometry/LatticeSampling.hpp"
#include "geometry/ShapeSampling.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/RigidBody.hpp"
#include "physics/WallMotion.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace poro {
class Dictionary;

struct ParticleRegion {
  enum class Phase { Fluid, Porous, Boundary, Rigid }; ///< Rigid: boundary particles of a rigid body
  enum class Shape { Box, Container, Sphere, Surface };
  std::string name;
  std::string where; ///< "file:line" of the region, for what only sampling finds out
  Phase phase = Phase::Fluid;
  Shape shape = Shape::Box;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero(); ///< box and container
  std::shared_ptr<const ClosedShape> body;     ///< sphere and surface: the closed surface to sample
  Vec3 velocity = Vec3::Zero();                ///< initial velocity of fluid and porous regions [m/s]
  std::size_t materialId = 0;                  ///< porous: index of its material in constant/porosityProperties
  bool fixed = false;                          ///< porous: particles held in place (Fixed, METHOD.md §4.2)
  int layers = 2;                              ///< wall layers of a container, or of a boundary sphere or surface
  FaceFlags open{};                            ///< faces of a container without wall
  WallSide side = WallSide::Inside;            ///< boundary sphere or surface: which side of it the wall lies on
  std::optional<WallMotion> motion;            ///< boundary: prescribed motion (the solver reads it again)
  std::optional<RigidBody::Spec> rigid;        ///< rigid: mass and constraints (the solver reads them again)

  /// The region's particle positions. A sphere or surface that holds no lattice point is an InputError.
  std::vector<Vec3> sample(double particleRadius) const;
};

struct ParticleDict {
  double particleRadius = 0.0;
  std::vector<ParticleRegion> regions;

  /// Reads and validates every key, and reads and checks the surfaces of surface regions, whose files are
  /// relative to `surfaceDirectory` (the case's constant/triSurface). `materials` are those of
  /// constant/porosityProperties (empty when the case has none): a porous region must name one of them. Before
  /// anything is sampled, it also refuses a box or container that would hold no particle, a case of walls only,
  /// and a particleRadius that would give a set more particles than a 32-bit index counts or need more memory to
  /// sample than the machine has (for spheres and surfaces, from their volume and area).
  static ParticleDict read(const Dictionary& dict, const std::vector<PorousMaterial>& materials,
                           const std::filesystem::path& surfaceDirectory);
};

} // namespace poro
