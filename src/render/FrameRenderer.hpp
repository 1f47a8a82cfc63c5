#pragma once
/// Draws Scenes into PNG files with VTK's OpenGL renderer, off screen (an X display is still needed: Debian's
/// VTK 9.1 renders through GLX; HeadlessDisplay provides one). VTK stays in FrameRenderer.cpp.

#include "render/CameraView.hpp"
#include "render/Scene.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <memory>

namespace poro {

class FrameRenderer {
public:
  /// `ranges`: the colour range of each coloured set ("fluid", "porous", "boundary") for every frame.
  FrameRenderer(const RenderSettings& settings, const CameraView& camera,
                std::map<std::string, std::array<double, 2>> ranges);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  /// Draws `scene` with a time label and colour legends and writes it as an RGB PNG. Throws OutputError.
  void render(const Scene& scene, const std::filesystem::path& png);

  /// The share of the picture's width, at its right, that `legends` colour legends and their titles take (0 for
  /// none), for a camera that keeps it free.
  static double legendsWidth(int legends);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace poro
