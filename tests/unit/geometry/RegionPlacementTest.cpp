// What sampleParticles allows of regions placed against each other (utilities/sampleParticles/RegionPlacement.hpp).
// The refusals of whole cases are in the bad-input corpus (tests/data/bad/particleDict_overlapping*, *ThroughWall,
// *InsideFluid, *OutsideContainer); these are the placements that must still sample.
#include "RegionPlacement.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

std::vector<PorousMaterial> materials() {
  PorousMaterial sand;
  sand.name = "sand";
  return {sand};
}

/// Samples `regions` (particleDict entries at r = 1 cm) as sampleParticles does: one set per phase, each particle
/// with its region's index as objectId; then runs the checks. Returns the InputError's message or "no error".
std::string place(const std::string& regions) {
  const ParticleDict dict = ParticleDict::read(
      Dictionary::parse("particleRadius: 0.01\nregions:\n" + regions, "system/particleDict"), materials(), "");
  ParticleSystem particles(dict.particleRadius);
  ParticleSet& fluid = particles.add("fluid", SetKind::Fluid);
  ParticleSet& porous = particles.add("sand", SetKind::Porous);
  ParticleSet& walls = particles.add("boundary", SetKind::Boundary);
  for (std::size_t r = 0; r < dict.regions.size(); ++r) {
    const ParticleRegion& region = dict.regions[r];
    ParticleSet& set = region.phase == ParticleRegion::Phase::Fluid    ? fluid
                       : region.phase == ParticleRegion::Phase::Porous ? porous
                                                                       : walls;
    for (const Vec3& p : region.sample(dict.particleRadius)) {
      set.resize(set.size() + 1);
      set.x().back() = p;
      set.integer(field::objectId).back() = static_cast<std::int64_t>(r);
    }
  }
  try {
    checkRegionPlacement(dict, particles);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kOpenTank =
    "  - {name: tank, phase: boundary, shape: container, min: [0, 0, 0], max: [0.4, 0.4, 0.4], open: [yMax]}\n";

TEST(RegionPlacement, RegionsThatTouchPoresThatHoldFluidAndADropAboveAnOpenTankPass) {
  EXPECT_EQ(place(kOpenTank +
                  "  - {name: bed, phase: porous, material: sand, shape: box, min: [0, 0, 0], max: [0.4, 0.1, 0.4]}\n"
                  "  - {name: soaked, phase: fluid, shape: box, min: [0, 0, 0], max: [0.4, 0.1, 0.4]}\n"
                  "  - {name: pool, phase: fluid, shape: box, min: [0, 0.1, 0], max: [0.4, 0.2, 0.4]}\n"
                  "  - {name: block, phase: porous, material: sand, shape: box, min: [0.1, 0.2, 0.1], "
                  "max: [0.3, 0.3, 0.3]}\n"
                  "  - {name: drop, phase: fluid, shape: sphere, centre: [0.2, 0.6, 0.2], radius: 0.05}\n"),
            "no error");
}

TEST(RegionPlacement, ASphereRestingOnAWallPasses) {
  EXPECT_EQ(place("  - {name: floor, phase: boundary, shape: box, min: [-0.2, -0.04, -0.2], max: [0.2, 0, 0.2]}\n"
                  "  - {name: ball, phase: porous, material: sand, shape: sphere, centre: [0, 0.05, 0], "
                  "radius: 0.05}\n"),
            "no error");
}

TEST(RegionPlacement, WallsThatEncloseNothingAreNotCheckedForOutside) {
  // Fluid poured onto a plate: the plate encloses no space, so nothing lies outside it.
  EXPECT_EQ(place("  - {name: plate, phase: boundary, shape: box, min: [0, 0, 0], max: [0.4, 0.04, 0.4]}\n"
                  "  - {name: water, phase: fluid, shape: box, min: [0.1, 0.1, 0.1], max: [0.3, 0.3, 0.3]}\n"),
            "no error");
}

TEST(RegionPlacement, ADropAboveAClosedTankLiesOutsideEveryWall) {
  const std::string e =
      place("  - {name: tank, phase: boundary, shape: container, min: [0, 0, 0], max: [0.4, 0.4, 0.4]}\n"
            "  - {name: drop, phase: fluid, shape: sphere, centre: [0.2, 0.6, 0.2], radius: 0.05}\n");
  EXPECT_NE(e.find("system/particleDict:4: region 'drop' (fluid) lies outside every wall"), std::string::npos) << e;
}

TEST(RegionPlacement, LatticesOffsetByRAlongEveryAxisStillOverlap) {
  // The farthest the nearest points of two overlapping lattices can be apart: sqrt(3) r, 8 pairs per point of b
  // inside a (19^3 of them).
  const std::string e =
      place("  - {name: a, phase: fluid, shape: box, min: [0, 0, 0], max: [0.2, 0.2, 0.2]}\n"
            "  - {name: b, phase: fluid, shape: box, min: [0.01, 0.01, 0.01], max: [0.21, 0.21, 0.21]}\n");
  EXPECT_NE(e.find("region 'b' (fluid) overlaps region 'a' (fluid, system/particleDict:3): 6859 pairs"),
            std::string::npos)
      << e;
}

} // namespace
} // namespace poro
