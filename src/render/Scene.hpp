#pragma once
/// What one picture shows, without VTK: SceneBuilder makes it from a time directory, FrameRenderer draws it.

#include "render/RenderSettings.hpp"
#include "surface/TriangleSurface.hpp"

#include <array>
#include <string>
#include <vector>

namespace poro {

/// One set as drawn: a surface, particles, or container outlines with their floors. `values` colour the points
/// (surface points or particles) through the style's map and range; empty: the style's solid colour.
struct SceneLayer {
  const SetStyle* style = nullptr;
  TriangleSurface surface;
  std::vector<Vec3> particles;
  double particleRadius = 0.0;
  std::vector<double> values;
  std::vector<std::array<Vec3, 2>> containers; ///< inner boxes (min, max) of container walls
  /// Where the clip plane cuts the body open (ClipCap), coloured by `capValues` like the surface.
  TriangleSurface cap;
  std::vector<double> capValues;
};

struct Scene {
  std::string timeName; ///< the time directory
  double time = 0.0;
  Vec3 up = Vec3::UnitY(); ///< against gravity: where container floors are
  std::vector<SceneLayer> layers; ///< in drawing order
};

} // namespace poro
