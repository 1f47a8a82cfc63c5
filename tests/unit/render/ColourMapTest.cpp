// Colour maps: wet reads dark, every sequential map orders its values by lightness.

#include "render/ColourMap.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

TEST(ColourMap, SequentialMapsChangeLightnessMonotonically) {
  for (const char* name : {"wetness", "blues", "greys"}) {
    const ColourMap& map = ColourMap::named(name);
    double previous = ColourMap::lightness(map.at(0.0));
    for (int k = 1; k <= 100; ++k) {
      const double l = ColourMap::lightness(map.at(k / 100.0));
      ASSERT_LT(l, previous + 1e-9) << name << " at " << k / 100.0;
      previous = l;
    }
  }
  const ColourMap& viridis = ColourMap::named("viridis");
  for (int k = 1; k <= 100; ++k)
    ASSERT_GT(ColourMap::lightness(viridis.at(k / 100.0)), ColourMap::lightness(viridis.at((k - 1) / 100.0)) - 1e-9);
}

TEST(ColourMap, WetIsDarkAndSaturatedDryIsLight) {
  const ColourMap& wetness = ColourMap::named("wetness");
  const Vec3 dry = wetness.at(0.0), wet = wetness.at(1.0);
  EXPECT_GT(ColourMap::lightness(dry), 95.0);
  EXPECT_LT(ColourMap::lightness(wet), 20.0);
  // Saturated: blue well above red and green.
  EXPECT_GT(wet.z(), 2.0 * wet.x());
  EXPECT_GT(wet.z(), 1.5 * wet.y());
}

TEST(ColourMap, InterpolatesAndClamps) {
  const ColourMap& greys = ColourMap::named("greys");
  EXPECT_TRUE(greys.at(0.25).isApprox(Vec3::Constant(0.75)));
  EXPECT_EQ(greys.at(-1.0), greys.at(0.0));
  EXPECT_EQ(greys.at(2.0), greys.at(1.0));
  EXPECT_THROW(ColourMap::named("jet"), std::out_of_range);
  EXPECT_EQ(ColourMap::names().front(), "wetness");
}

} // namespace
} // namespace poro
