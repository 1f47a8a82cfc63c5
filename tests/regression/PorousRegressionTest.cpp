// Coarse regression runs of the porous tutorials (VALIDATION.md "Porous coupling"): r = 2 cm.

#include "CaseRunner.hpp"

#include "physics/FieldNames.hpp"

#include <cmath>
#include <sstream>

namespace poro::test {
namespace {

constexpr double kCoarse = 0.02;
const double kVolume = 8.0 * kCoarse * kCoarse * kCoarse;

/// The seepage block of tutorials/porous/seepage and seepageDrag: [0, 0.6] x [0, 0.4] x [0, 0.6].
const Vec3 kBlockMin(0.0, 0.0, 0.0), kBlockMax(0.6, 0.4, 0.6);
const double kBlockVolume = 0.6 * 0.4 * 0.6;

bool inside(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
}

/// Fluid volume inside the block: particles in it times V (each fluid particle carries V of fluid).
double absorbedVolume(const ParticleSystem& ps) {
  std::size_t n = 0;
  for (const Vec3& x : ps.find("fluid")->x()) n += inside(x, kBlockMin, kBlockMax) ? 1 : 0;
  return static_cast<double>(n) * kVolume;
}

void coarsen(CaseRunner& runner, double endTime) {
  runner.setKey("system/particleDict", "particleRadius", std::to_string(kCoarse));
  runner.setKey("system/controlDict", "endTime", std::to_string(endTime));
  runner.setKey("system/controlDict", "maxDeltaT", "0.004");
  runner.setKey("system/controlDict", "writeInterval", "0.1");
}

class Seepage : public ::testing::TestWithParam<double> {};

TEST_P(Seepage, AbsorbedVolumeIsSetByPorosity) {
  // VALIDATION.md "Absorbed volume is set by porosity": at saturation the fluid volume inside the fixed
  // block is phi V_block within 10 %, and interior solid particles are saturated (mean S >= 0.95).
  const double phi = GetParam();
  CaseRunner runner("porous/seepage", "Seepage_" + std::to_string(static_cast<int>(phi * 10)));
  coarsen(runner, 2.5);
  runner.replace("constant/porosityProperties", "porosity: 0.6", "porosity: " + std::to_string(phi));
  ASSERT_EQ(runner.sample(), 0) << runner.read("log.sampleParticles");
  ASSERT_EQ(runner.solve(), 0) << runner.read("log.poroSph");
  const auto times = listTimeDirectories(runner.dir());
  const ParticleSystem ps = runner.particles(times.back().name, kCoarse);
  const double absorbed = absorbedVolume(ps);
  EXPECT_NEAR(absorbed / (phi * kBlockVolume), 1.0, 0.10) << "absorbed " << absorbed << " m^3";

  // Interior: one kernel support H = 4r away from the walls and the floor; the top is under the pool.
  const ParticleSet& soil = *ps.find("soil");
  const auto& saturation = soil.real(field::saturation);
  double sum = 0.0;
  int n = 0;
  for (std::size_t s = 0; s < soil.size(); ++s)
    if (inside(soil.x()[s], kBlockMin + Vec3::Constant(4 * kCoarse), kBlockMax - Vec3(4, 0, 4) * kCoarse)) {
      sum += saturation[s];
      ++n;
    }
  ASSERT_GT(n, 0);
  EXPECT_GE(sum / n, 0.95);
  std::cout << "[ measured ] phi " << phi << ": absorbed / (phi V_block) = " << absorbed / (phi * kBlockVolume)
            << ", mean interior saturation " << sum / n << '\n';
}

const auto kPorosityName = [](const auto& info) { return "phi" + std::to_string(static_cast<int>(info.param * 10)); };
INSTANTIATE_TEST_SUITE_P(Porosities, Seepage, ::testing::Values(0.4, 0.6, 0.8), kPorosityName);

} // namespace
} // namespace poro::test
