#pragma once
/// Builds the Scene of a time directory from system/renderDict: surfaces reconstructed in memory as fluidSurface
/// makes them (system/surfaceDict), particles, and walls: a `shape: container` region of system/particleDict as the
/// outline of its box with its floor (its near walls would hide everything), any other wall body as a surface,
/// reconstructed once when the walls are static. Where the water touches a porous body or a wall body its surface
/// and theirs coincide and would flicker through each other (z-fighting), so the scene leaves out the triangles of
/// the water's surface that lie on them (fluidSurface's files keep the closed surface).

#include "render/Scene.hpp"
#include "surface/SurfaceReconstruction.hpp"
#include "surface/SurfaceSettings.hpp"

#include <filesystem>
#include <map>

namespace poro {

class ParticleSystem;

class SceneBuilder {
public:
  SceneBuilder(std::filesystem::path caseDir, const RenderSettings& render, const SurfaceSettings& surface,
               const Vec3& gravity);

  /// The scene of the time directory `timeName` whose particles are `particles`. A colourBy field a set does not
  /// carry is an InputError naming system/renderDict's line.
  Scene build(const ParticleSystem& particles, const std::string& timeName, double time);

  /// The values `style` colours `set` by at the particles (|f| for vectors), for the colour range over all frames;
  /// empty without colourBy or particles. Particles without a finite position (a diverged run) are left out, as
  /// build() leaves them out of a particle layer.
  static std::vector<double> particleValues(const ParticleSystem& particles, const SetStyle& style);

private:
  SceneLayer wallLayer(const ParticleSystem& particles, const std::string& timeName);
  /// Removes the triangles of `water` whose corners all lie where another body's colour field is >= 0.2.
  void trimContact(TriangleSurface& water) const;

  std::filesystem::path caseDir_;
  const RenderSettings& render_;
  SurfaceSettings surface_;
  Vec3 up_;
  std::vector<std::array<Vec3, 2>> containers_;
  std::vector<std::int64_t> containerIds_; ///< objectIds (region indices) of the containers
  std::optional<Reconstruction> staticWalls_;
  std::vector<ScalarGrid> contact_; ///< colour fields of this frame's porous and wall bodies
};

} // namespace poro
