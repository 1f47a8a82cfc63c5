#pragma once
/// system/renderDict: what renderCase draws and how. The file and each of its keys are optional; the defaults give
/// a good picture of any tutorial. etc/caseDicts/renderDict documents every key.

#include "core/Types.hpp"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace poro {

/// How one particle set is drawn: "fluid", "porous" or "boundary".
struct SetStyle {
  enum class Show { Surface, Particles, None };
  std::string set;
  Show show = Show::Surface;
  std::string colourBy;                      ///< a point field (vectors: magnitude); empty: the solid `colour`
  std::string colourMap = "viridis";         ///< ColourMap::named
  std::optional<std::array<double, 2>> range; ///< of colourBy; default: 0-1 for saturation, else over all frames
  Vec3 colour = Vec3(0.7, 0.7, 0.7);
  double opacity = 1.0;
  std::string where; ///< "system/renderDict:12" of colourBy (or of the set), for errors found while drawing
};

struct CameraSettings {
  std::optional<Vec3> position, focalPoint, viewUp; ///< default: CameraView::framing
  double viewAngle = 30.0;                          ///< vertical [degrees]
  std::string viewUpWhere;                          ///< "system/renderDict:9" of camera.viewUp, for viewUpProblem
};

/// A plane that cuts sets open: the half-space the normal points to is removed (point it at the camera).
struct ClipSettings {
  Vec3 origin = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  std::vector<std::string> sets{"porous"};
};

struct RenderSettings {
  int width = 1280, height = 720;
  Vec3 background = Vec3(1.0, 1.0, 1.0);
  double frameRate = 10.0; ///< of -movie [frames/s]
  bool timeLabel = true;   ///< "t = 0.5 s" top left
  bool legend = true;      ///< a colour bar per set coloured by a field
  CameraSettings camera;
  SetStyle fluid, porous, boundary;
  std::optional<ClipSettings> clip;

  /// The three styles in drawing order (boundary, porous, fluid: translucent water last).
  std::vector<const SetStyle*> styles() const { return {&boundary, &porous, &fluid}; }
};

/// Why `viewUp` cannot be the picture's up direction when looking along `viewDirection` (parallel to it), or "".
std::string viewUpProblem(const Vec3& viewUp, const Vec3& viewDirection);

/// Reads `<caseDir>/system/renderDict`, with defaults for what it leaves out. `porousBodies`: whether the case has
/// porous bodies (the fluid is then more translucent, so they show through it). Unknown keys, wrong types, unknown
/// colour maps, surface colours other than the surface's own field, colours outside [0, 1], a colourMap or range
/// without colourBy, and a camera viewUp parallel to its view direction are InputErrors naming file, line and key.
RenderSettings readRenderSettings(const std::filesystem::path& caseDir, bool porousBodies);

} // namespace poro
