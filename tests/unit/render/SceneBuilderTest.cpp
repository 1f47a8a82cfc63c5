// SceneBuilder with the particles of a diverged run: non-finite positions never reach the picture (render/SceneBuilder.hpp).

#include "render/SceneBuilder.hpp"

#include "physics/FieldNames.hpp"
#include "sph/ParticleSystem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace poro {
namespace {

constexpr double kR = 0.01;

/// A 3 x 3 x 3 lattice of fluid moving at speeds 1, 2, ...; particles 4 and 9 diverged (NaN and infinite x).
ParticleSystem divergedFluid() {
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.resize(27);
  for (int i = 0; i < 27; ++i) {
    fluid.x()[i] = Vec3(kR + 2 * kR * (i % 3), kR + 2 * kR * (i / 3 % 3), kR + 2 * kR * (i / 9));
    fluid.v()[i] = Vec3(i + 1.0, 0.0, 0.0);
    fluid.integer(field::id)[i] = i;
  }
  fluid.x()[4] = Vec3(std::nan(""), 0.0, 0.0);
  fluid.x()[9] = Vec3(0.0, std::numeric_limits<double>::infinity(), 0.0);
  return ps;
}

RenderSettings fluidOnly(SetStyle::Show show) {
  RenderSettings settings = readRenderSettings("/nonexistent", false);
  settings.fluid.show = show;
  settings.fluid.colourBy = field::v;
  settings.porous.show = settings.boundary.show = SetStyle::Show::None;
  return settings;
}

TEST(SceneBuilder, ParticlesWithoutAFinitePositionAreLeftOutWithTheirValues) {
  const ParticleSystem particles = divergedFluid();
  const RenderSettings settings = fluidOnly(SetStyle::Show::Particles);
  SceneBuilder builder("/nonexistent", settings, SurfaceSettings{}, Vec3(0, -9.81, 0));
  const Scene scene = builder.build(particles, "1", 1.0);
  ASSERT_EQ(scene.layers.size(), 1u);
  const SceneLayer& layer = scene.layers[0];
  ASSERT_EQ(layer.particles.size(), 25u);
  ASSERT_EQ(layer.values.size(), layer.particles.size());
  for (std::size_t p = 0; p < layer.particles.size(); ++p) {
    ASSERT_TRUE(layer.particles[p].allFinite()) << p;
    // Values stay with their particles: the speed is the particle's index + 1, and x tells the index.
    const Vec3 cell = (layer.particles[p] - Vec3::Constant(kR)) / (2 * kR);
    const double index = std::round(cell.x()) + 3 * std::round(cell.y()) + 9 * std::round(cell.z());
    EXPECT_DOUBLE_EQ(layer.values[p], index + 1.0) << p;
  }
  EXPECT_EQ(SceneBuilder::particleValues(particles, settings.fluid), layer.values);
}

TEST(SceneBuilder, ASurfaceOfADivergedRunIsFinite) {
  const ParticleSystem particles = divergedFluid();
  const RenderSettings settings = fluidOnly(SetStyle::Show::Surface);
  SceneBuilder builder("/nonexistent", settings, SurfaceSettings{}, Vec3(0, -9.81, 0));
  const Scene scene = builder.build(particles, "1", 1.0);
  ASSERT_EQ(scene.layers.size(), 1u);
  const SceneLayer& layer = scene.layers[0];
  ASSERT_FALSE(layer.surface.empty());
  for (const Vec3& p : layer.surface.points) ASSERT_TRUE(p.allFinite());
  ASSERT_EQ(layer.values.size(), layer.surface.points.size());
  for (double v : layer.values) ASSERT_TRUE(std::isfinite(v));
}

} // namespace
} // namespace poro
