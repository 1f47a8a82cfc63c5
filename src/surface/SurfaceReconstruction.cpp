#include "surface/SurfaceReconstruction.hpp"

#include "analysis/AbsorbedFluid.hpp"
#include "physics/FieldNames.hpp"
#include "sph/ParticleSystem.hpp"
#include "surface/IsoSurface.hpp"
#include "surface/PorousVolumes.hpp"
#include "surface/ShepardInterpolation.hpp"

namespace poro {

Reconstruction reconstruct(const ParticleCloud& cloud, const ReconstructionSettings& settings, double particleRadius) {
  Reconstruction result;
  result.iso = settings.isoValue;
  result.grid = colourField(cloud, settings.kernelRadius * particleRadius, settings.gridSpacing * particleRadius,
                            settings.where);
  result.surface = contour(result.grid, settings.isoValue, settings.smoothingIterations);
  if (result.surface.empty()) return result;
  const ShepardInterpolation interpolation(cloud, settings.kernelRadius * particleRadius, settings.where);
  for (const ParticleField& f : cloud.fields)
    result.surface.fields.push_back({f.name, f.components, interpolation.at(result.surface.points, f)});
  return result;
}

ParticleCloud fluidCloud(const ParticleSystem& particles, const SurfaceSettings& settings) {
  ParticleCloud cloud;
  const ParticleSet* fluid = particles.find("fluid");
  if (!fluid) return cloud;
  std::vector<bool> skip(fluid->size(), false);
  if (settings.poreFluid == PoreFluid::Exclude)
    skip = absorbedFluid(fluid->x(), particles, findPorousObjects(particles, {}), particles.particleRadius());
  const double r = particles.particleRadius();
  ParticleField velocity{field::v, 3, {}};
  for (std::size_t i = 0; i < fluid->size(); ++i) {
    if (skip[i]) continue;
    cloud.positions.push_back(fluid->x()[i]);
    cloud.volumes.push_back(8.0 * r * r * r);
    for (int c = 0; c < 3; ++c) velocity.values.push_back(fluid->v()[i][c]);
  }
  cloud.fields.push_back(std::move(velocity));
  return cloud;
}

ParticleCloud porousCloud(const ParticleSystem& particles) {
  ParticleCloud cloud;
  ParticleField saturation{field::saturation, 1, {}};
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const ParticleSet& set = particles[s];
    if (set.kind() != SetKind::Porous) continue;
    const std::vector<double> volumes = deformedVolumes(set, particles.particleRadius());
    const bool wet = set.has(field::saturation);
    for (std::size_t i = 0; i < set.size(); ++i) {
      cloud.positions.push_back(set.x()[i]);
      cloud.volumes.push_back(volumes[i]);
      saturation.values.push_back(wet ? set.real(field::saturation)[i] : 0.0);
    }
  }
  cloud.fields.push_back(std::move(saturation));
  return cloud;
}

} // namespace poro
