#pragma once
/// Particles to surfaces (fluidSurface, renderCase): the fluid's free surface with its velocity, the porous bodies'
/// surface with their saturation, or the surface of any particle cloud (walls), each the contour of its colour
/// field (ColourField) at system/surfaceDict's iso-level.

#include "surface/ColourField.hpp"
#include "surface/SurfaceSettings.hpp"
#include "surface/TriangleSurface.hpp"

namespace poro {

class ParticleSystem;

struct Reconstruction {
  TriangleSurface surface;
  ScalarGrid grid; ///< the colour field it was contoured from (renderCase cuts it open)
  double iso = 0.5;
};

/// The surface of `cloud` with every field of the cloud read off at its points (ShepardInterpolation).
Reconstruction reconstruct(const ParticleCloud& cloud, const ReconstructionSettings& settings, double particleRadius);

/// The set named "fluid" with V = (2r)^3 and its velocity `v`. Pore fluid (inside a porous object, as
/// saturationAnalysis counts it) is left out unless settings.poreFluid is Include. Empty without fluid.
ParticleCloud fluidCloud(const ParticleSystem& particles, const SurfaceSettings& settings);
/// Every porous set, V from deformedVolumes, with `saturation` (0 where the set has none, as at time 0).
ParticleCloud porousCloud(const ParticleSystem& particles);

} // namespace poro
