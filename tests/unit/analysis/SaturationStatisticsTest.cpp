// Absorbed fluid, pore volume, saturation statistics and fronts of a synthetic system with known answers.

#include "AnalysisTestSystems.hpp"
#include "analysis/AbsorbedFluid.hpp"
#include "analysis/SaturationAnalysis.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <random>

namespace poro::test {
namespace {

const double kV = 8.0 * kR * kR * kR;

TEST(PorousObjects, GroupsPorousParticlesByObjectIdAndNamesThemByRegion) {
  const ParticleSystem ps = syntheticSystem();
  const auto objects = findPorousObjects(ps, syntheticSettings().regionNames);
  ASSERT_EQ(objects.size(), 2u);
  EXPECT_EQ(objects[0].objectId, 1);
  EXPECT_EQ(objects[0].name, "block");
  EXPECT_EQ(objects[0].particles.size(), 64u);
  EXPECT_EQ(objects[1].objectId, 3);
  EXPECT_EQ(objects[1].name, "object3"); // beyond the region list
  EXPECT_EQ(objects[1].particles.size(), 8u);
}

TEST(AbsorbedFluid, CountsFluidInTheLatticeCellsOfEachObject) {
  const ParticleSystem ps = syntheticSystem();
  const auto objects = findPorousObjects(ps, {});
  const auto counts = countAbsorbedFluid(ps[0].x(), ps, objects, kR);
  EXPECT_EQ(counts[0], fluidInBlock().size()); // faces and corners inside, the shared corner counted once
  EXPECT_EQ(counts[1], fluidInSand().size());
}

TEST(AbsorbedFluid, EqualsBruteForceOnADeformedLattice) {
  // Cabana-style: the hash grid finds exactly the pairs an all-pairs max-norm test finds.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.6 * kR, 0.6 * kR), place(-0.02, 0.14);
  ParticleSystem ps(kR);
  std::vector<Vec3> fluid(3000);
  for (Vec3& x : fluid) x = Vec3(place(random), place(random), place(random));
  addSet(ps, "fluid", SetKind::Fluid, fluid, 0);
  std::vector<Vec3> solid = lattice(6, Vec3::Zero());
  for (Vec3& x : solid) x += Vec3(jitter(random), jitter(random), jitter(random));
  ParticleSet& set = addSet(ps, "soil", SetKind::Porous, solid, 0);
  for (std::size_t i = 0; i < set.size(); i += 2) set.integer(field::objectId)[i] = 1; // two interleaved objects
  const auto objects = findPorousObjects(ps, {});
  const auto counts = countAbsorbedFluid(fluid, ps, objects, kR);
  for (std::size_t k = 0; k < objects.size(); ++k) {
    std::size_t expected = 0;
    for (const Vec3& f : fluid) {
      bool inside = false;
      for (const auto& [s, i] : objects[k].particles) inside = inside || (f - ps[s].x()[i]).cwiseAbs().maxCoeff() <= kR;
      expected += inside ? 1 : 0;
    }
    EXPECT_EQ(counts[k], expected) << "object " << objects[k].objectId;
    EXPECT_GT(expected, 100u);
  }
}

TEST(SaturationStatistics, ExactVolumesSaturationsAndFront) {
  const ParticleSystem ps = syntheticSystem();
  const AnalysisSettings settings = syntheticSettings();
  const TimeRecord record = analyse(ps, settings);
  ASSERT_EQ(record.objects.size(), 2u);

  const ObjectStatistics& block = record.objects[0];
  EXPECT_EQ(block.name, "block");
  EXPECT_EQ(block.solidParticles, 64u);
  EXPECT_EQ(block.absorbedParticles, 10u);
  EXPECT_DOUBLE_EQ(block.absorbedVolume, 10 * kV);
  EXPECT_DOUBLE_EQ(block.absorbedMass, 10 * 1000.0 * kV);
  EXPECT_DOUBLE_EQ(block.poreVolume, 0.4 * 64 * kV);
  EXPECT_DOUBLE_EQ(block.fractionFilled, 10.0 / (0.4 * 64));
  EXPECT_DOUBLE_EQ(*block.meanSaturation, 0.5); // layers 0, 0.25, 0.75, 1
  EXPECT_DOUBLE_EQ(*block.maxSaturation, 1.0);
  EXPECT_EQ(block.wetParticles, 32u); // the two upper layers
  EXPECT_NEAR(*block.wetMin, 0.05, 1e-15);
  EXPECT_NEAR(*block.wetMax, 0.07, 1e-15);
  EXPECT_NEAR(*block.wetHeight, 0.02, 1e-15);

  const ObjectStatistics& sand = record.objects[1];
  EXPECT_EQ(sand.absorbedParticles, 3u);
  EXPECT_DOUBLE_EQ(sand.poreVolume, 0.6 * 8 * kV);
  EXPECT_DOUBLE_EQ(*sand.meanSaturation, kSandSaturation);
  EXPECT_EQ(sand.wetParticles, 0u);
  EXPECT_FALSE(sand.wetMin);
  EXPECT_FALSE(sand.wetMax);
  EXPECT_EQ(*sand.wetHeight, 0.0); // nothing wet: height 0
}

TEST(SaturationStatistics, WetThresholdAndAxisDirection) {
  AnalysisSettings settings = syntheticSettings();
  settings.wetThreshold = 0.2;
  settings.axis = Axis::parse("-y");
  const TimeRecord record = analyse(syntheticSystem(), settings);
  const ObjectStatistics& block = record.objects[0];
  EXPECT_EQ(block.wetParticles, 48u); // 0.25, 0.75 and 1
  EXPECT_NEAR(*block.wetMin, -0.07, 1e-15);
  EXPECT_NEAR(*block.wetMax, -0.03, 1e-15);
  EXPECT_EQ(record.objects[1].wetParticles, 8u); // saturation 0.2 >= 0.2
}

TEST(SaturationStatistics, CentreExtentAndLargestDensityOfEachObject) {
  ParticleSystem ps = syntheticSystem();
  auto& rho = ps[1].addReal(field::density, Output);
  for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = 600.0 + static_cast<double>(i);
  AnalysisSettings settings = syntheticSettings();
  settings.axis = Axis::parse("-x");
  const TimeRecord record = analyse(ps, settings);
  const ObjectStatistics& block = record.objects[0];
  EXPECT_NEAR(*block.centre, -0.04, 1e-15); // x = 0.01 ... 0.07, mean 0.04, along -x
  EXPECT_NEAR(*block.minPosition, -0.07, 1e-15);
  EXPECT_NEAR(*block.maxPosition, -0.01, 1e-15);
  EXPECT_EQ(*block.maxDensity, 663.0);
  const ObjectStatistics& sand = record.objects[1];
  EXPECT_NEAR(*sand.centre, -0.52, 1e-15);
  EXPECT_FALSE(sand.maxDensity); // no density field on that set
}

TEST(SaturationStatistics, WithoutSaturationFieldSaturationIsUnknown) {
  const TimeRecord record = analyse(syntheticSystem(false), syntheticSettings());
  const ObjectStatistics& block = record.objects[0];
  EXPECT_EQ(block.absorbedParticles, 10u); // positions alone decide what is absorbed
  EXPECT_FALSE(block.meanSaturation);
  EXPECT_FALSE(block.maxSaturation);
  EXPECT_FALSE(block.wetHeight);
  EXPECT_TRUE(record.profiles[0].empty());
  EXPECT_FALSE(record.fluid.meanDensityError);
}

TEST(SaturationStatistics, UnknownMaterialIsAnInputError) {
  AnalysisSettings settings = syntheticSettings();
  settings.materials.pop_back(); // no "sand"
  EXPECT_THROW(analyse(syntheticSystem(), settings), InputError);
}

TEST(SaturationProfiles, OneBinPerLatticeLayer) {
  const ParticleSystem ps = syntheticSystem();
  const TimeRecord record = analyse(ps, syntheticSettings());
  const auto& block = record.profiles[0];
  ASSERT_EQ(block.size(), 4u);
  for (std::size_t j = 0; j < 4; ++j) {
    EXPECT_NEAR(block[j].position, kR + 2 * kR * static_cast<double>(j), 1e-15);
    EXPECT_DOUBLE_EQ(block[j].meanSaturation, kLayerSaturation[j]);
    EXPECT_EQ(block[j].particles, 16u);
  }
  const auto& sand = record.profiles[1];
  ASSERT_EQ(sand.size(), 2u);
  EXPECT_NEAR(sand[1].position, 3 * kR, 1e-15);
  EXPECT_DOUBLE_EQ(sand[1].meanSaturation, kSandSaturation);
  EXPECT_EQ(sand[1].particles, 4u);
}

TEST(SaturationProfiles, AlongANegativeAxisTheLayersComeReversed) {
  AnalysisSettings settings = syntheticSettings();
  settings.axis = Axis::parse("-y");
  const auto profile = analyse(syntheticSystem(), settings).profiles[0];
  ASSERT_EQ(profile.size(), 4u);
  EXPECT_NEAR(profile[0].position, -0.07, 1e-15);
  EXPECT_DOUBLE_EQ(profile[0].meanSaturation, kLayerSaturation[3]);
  EXPECT_DOUBLE_EQ(profile[3].meanSaturation, kLayerSaturation[0]);
}

TEST(SaturationProfiles, AlongXEveryBinMixesAllLayers) {
  AnalysisSettings settings = syntheticSettings();
  settings.axis = Axis::parse("x");
  const auto profile = analyse(syntheticSystem(), settings).profiles[0];
  ASSERT_EQ(profile.size(), 4u);
  for (const ProfileBin& bin : profile) EXPECT_DOUBLE_EQ(bin.meanSaturation, 0.5);
}

TEST(FluidStatistics, KineticEnergyMomentumAndCompressionOnlyDensityError) {
  ParticleSystem ps(kR);
  ParticleSet& fluid = addSet(ps, "fluid", SetKind::Fluid, {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}, 0);
  fluid.v() = {Vec3(1, 0, 0), Vec3(0, -2, 0), Vec3(0, 0, 3), Vec3(-1, 1, 0)};
  fluid.addReal(field::density, Output) = {1000.0, 1010.0, 990.0, 1000.5};
  const double m = 1000.0 * kV;
  const FluidStatistics stats = fluidStatistics(fluid, syntheticSettings());
  EXPECT_EQ(stats.particles, 4u);
  EXPECT_DOUBLE_EQ(stats.kineticEnergy, 0.5 * m * (1 + 4 + 9 + 2));
  EXPECT_DOUBLE_EQ(stats.momentum.x(), 0.0);
  EXPECT_DOUBLE_EQ(stats.momentum.y(), -1.0 * m);
  EXPECT_DOUBLE_EQ(stats.momentum.z(), 3.0 * m);
  EXPECT_DOUBLE_EQ(stats.maxSpeed, 3.0);
  EXPECT_DOUBLE_EQ(stats.meanSpeed, (1.0 + 2.0 + 3.0 + std::sqrt(2.0)) / 4);
  EXPECT_FALSE(stats.pressureGradient.has_value());              // no pressure field
  EXPECT_NEAR(*stats.meanDensityError, (1.0 + 0.05) / 4, 1e-12); // 990 is expansion: no error
  EXPECT_NEAR(*stats.maxDensityError, 1.0, 1e-12);
}

TEST(FluidStatistics, PotentialEnergyAndExtentFollowGravityAndTheAxis) {
  // A column of three particles at heights 0.1, 0.2, 0.4 m along y and spread along x; gravity tilted so
  // that g.x mixes both components.
  ParticleSystem ps(kR);
  ParticleSet& fluid =
      addSet(ps, "fluid", SetKind::Fluid, {Vec3(0.3, 0.1, 0), Vec3(-0.2, 0.2, 5), Vec3(0.0, 0.4, -5)}, 0);
  AnalysisSettings settings = syntheticSettings();
  settings.gravity = Vec3(1.0, -10.0, 0.0);
  const double m = 1000.0 * kV;
  FluidStatistics stats = fluidStatistics(fluid, settings);
  EXPECT_NEAR(stats.potentialEnergy, m * (10.0 * 0.7 - 0.1), 1e-15); // -m g.x summed
  EXPECT_DOUBLE_EQ(*stats.minPosition, 0.1);                         // default axis +y
  EXPECT_DOUBLE_EQ(*stats.maxPosition, 0.4);
  settings.axis = Axis::parse("-x");
  stats = fluidStatistics(fluid, settings);
  EXPECT_DOUBLE_EQ(*stats.minPosition, -0.3);
  EXPECT_DOUBLE_EQ(*stats.maxPosition, 0.2);
  // Lifting every particle by h raises the potential energy by M |g_y| h exactly.
  for (Vec3& x : fluid.x()) x.y() += 0.5;
  EXPECT_NEAR(fluidStatistics(fluid, settings).potentialEnergy - stats.potentialEnergy, 3 * m * 10.0 * 0.5, 1e-15);
  // No fluid: no extent.
  ParticleSystem empty(kR);
  const FluidStatistics none = fluidStatistics(addSet(empty, "fluid", SetKind::Fluid, {}, 0), settings);
  EXPECT_FALSE(none.minPosition.has_value());
  EXPECT_FALSE(none.maxPosition.has_value());
  EXPECT_EQ(none.potentialEnergy, 0.0);
}

TEST(FluidStatistics, PressureGradientOfAPoolIsFittedInsideTheSideWallLayers) {
  // A 16 x 20 x 16 lattice pool with p = rho0 |g| (top - y) * 1.03 inside and a wall ring three spacings wide and
  // the bottom and top 15 % at other gradients: only the interior band counts.
  std::vector<Vec3> x;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 20; ++j)
      for (int k = 0; k < 16; ++k) x.emplace_back((2 * i + 1) * kR, (2 * j + 1) * kR, (2 * k + 1) * kR);
  ParticleSystem ps(kR);
  ParticleSet& fluid = addSet(ps, "fluid", SetKind::Fluid, x, 0);
  AnalysisSettings settings = syntheticSettings();
  settings.gravity = Vec3(0.0, -9.81, 0.0);
  const double rhoG = settings.fluidDensity * 9.81, top = 0.4;
  auto& p = fluid.addReal(field::pressure, Output);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double depth = top - x[i].y();
    const bool ring = std::min({x[i].x(), x[i].z(), 0.32 - x[i].x(), 0.32 - x[i].z()}) < 6 * kR;
    const double band = (x[i].y() - kR) / (0.39 - kR);
    p[i] = rhoG * depth * (ring ? 1.6 : band < 0.15 || band > 0.85 ? 0.5 : 1.03);
  }
  EXPECT_NEAR(*fluidStatistics(fluid, settings).pressureGradient, 1.03, 1e-12);
}

TEST(FluidStatistics, AnalyseUsesTheSetNamedFluid) {
  ParticleSystem ps = syntheticSystem();
  for (Vec3& v : ps[0].v()) v = Vec3(0, 2, 0);
  const TimeRecord record = analyse(ps, syntheticSettings());
  const double n = static_cast<double>(ps[0].size());
  EXPECT_DOUBLE_EQ(record.fluid.kineticEnergy, 0.5 * 1000.0 * kV * 4 * n);
  EXPECT_DOUBLE_EQ(record.fluid.momentum.y(), 1000.0 * kV * 2 * n);
  EXPECT_DOUBLE_EQ(*record.fluid.maxDensityError, 0.0);
}

} // namespace
} // namespace poro::test
