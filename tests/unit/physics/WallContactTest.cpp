// Wall contact of porous solids (physics/WallContact.hpp): the flat-wall share, a squeezed skeleton that stays out
// of the floor and the plate while the walls carry its load, and incompressible bodies resting on the floor.

#include "physics/WallContact.hpp"
#include "PorousTestSystems.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "physics/RigidBodyForces.hpp"
#include "sph/BoundaryVolume.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace poro::test {
namespace {

constexpr long long kBlock = 0, kFloor = 1, kPlate = 2;

/// Two wall layers whose surface is y = 0, wide enough for the bodies below.
ParticleSet& addFloor(ParticleSystem& ps) {
  return addSet(ps, "walls", SetKind::Boundary, sampleBox(Vec3(-0.1, -0.04, -0.1), Vec3(0.22, 0.0, 0.22), kR), kFloor);
}

/// A sponge-like block 12 x 8 x 12 cm (6 x 4 x 6 particles) on the floor, a plate 1 cm above.
ParticleSystem squeezeScene() {
  ParticleSystem ps(kR);
  addSet(ps, "foam", SetKind::Porous, sampleBox(Vec3(0.0, 0.0, 0.0), Vec3(0.12, 0.08, 0.12), kR), kBlock);
  ParticleSet& walls = addFloor(ps);
  appendObject(walls, sampleBox(Vec3(-0.1, 0.09, -0.1), Vec3(0.22, 0.13, 0.22), kR), kPlate);
  return ps;
}

PorousMaterial foam() {
  PorousMaterial m = material("foam", 0.6, 2500.0, true);
  m.youngsModulus = 2.5e5;
  m.poissonsRatio = 0.3;
  m.dampingViscosity = 5.0; // rings down the squeeze within the test's time
  return m;
}

/// The plate moves down from 0.09 to `bottom` over 0.2 s and holds there.
std::vector<ObjectMotion> plateDownTo(double bottom) {
  return {ObjectMotion{kPlate, "plate", "test",
                       WallMotion({{0.0, Vec3::Zero(), 0.0}, {0.2, Vec3(0.0, bottom - 0.09, 0.0), 0.0}})}};
}

TEST(WallContact, FlatWallShareIsThatOfASampledTwoLayerWall) {
  // A wide sampled floor with Akinci volumes: D at r above its surface, over a wall particle and between four.
  ParticleSystem ps(kR);
  ParticleSet& floor =
      addSet(ps, "floor", SetKind::Boundary, sampleBox(Vec3(-0.1, -0.04, -0.1), Vec3(0.1, 0.0, 0.1), kR), kFloor);
  const CubicKernel kernel(4.0 * kR);
  computeBoundaryVolumes(floor, kernel);
  const auto share = [&](const Vec3& p) {
    double d = 0.0;
    for (std::size_t k = 0; k < floor.size(); ++k)
      d += floor.real(kBoundaryVolumeField)[k] * kernel.w(p - floor.x()[k]);
    return d;
  };
  const double flat = flatWallShare(kernel, 2.0 * kR);
  EXPECT_NEAR(share(Vec3(0.01, kR, 0.01)), flat, 1e-12);
  // Off the wall lattice the share changes by the lattice's ripple only.
  EXPECT_NEAR(share(Vec3(0.0, kR, 0.0)), flat, 0.02 * flat);
  // With the half lattice of fluid on the wall's side it gives the first fluid layer's 1.026 (METHOD.md §2.2).
  double fluid = 0.0;
  for (int i = -2; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j)
      for (int k = -2; k <= 2; ++k) fluid += kernel.w(2.0 * kR * Vec3(i, j, k));
  EXPECT_NEAR(fluid * std::pow(2.0 * kR, 3) + flat, 1.026, 5e-4);
}

TEST(WallContact, SqueezedCompressibleBlockStaysOutOfFloorAndPlate) {
  // The plate presses the block from 8 to 5 cm. Resting on a wall, a particle centre lies r in front of the
  // wall surface; the issue allows 0.1 r of penetration. Without the contact constraint the skeleton entered
  // the walls until its pores closed there: 1.37 r into the floor and into the plate. Measured with it: 7e-4 r.
  const double bottom = 0.05;
  Solver solver(squeezeScene(), FluidProperties{}, {foam()}, SolverSettings{}, fixedStep(1e-3), RunState{},
                plateDownTo(bottom));
  double lowest = 1.0, intoPlate = -1.0;
  for (int n = 1; n <= 400; ++n) {
    solver.step(1e-3);
    const double plate = 0.09 + (bottom - 0.09) * std::min(n * 1e-3 / 0.2, 1.0); // its surface now
    for (const Vec3& x : solver.particles()[0].x()) {
      lowest = std::min(lowest, x.y());
      intoPlate = std::max(intoPlate, x.y() - (plate - kR));
    }
  }
  EXPECT_GE(lowest, kR - 0.1 * kR) << "the skeleton entered the floor";
  EXPECT_LE(intoPlate, 0.1 * kR) << "the skeleton entered the plate";
  // Squeezed, not shut: the pores must still be open on average (bulk density below the solid phase's).
  const auto& rho = solver.particles()[0].real(field::density);
  double mean = 0.0;
  for (double d : rho) mean += d / static_cast<double>(rho.size());
  EXPECT_LT(mean, 2500.0);
}

TEST(WallContact, FloorCarriesTheRestingBlocksWeight) {
  // No plate motion: the block settles under gravity; the floor's reaction (pressure and contact, the sums
  // rigid bodies feel) balances its weight once it rests (measured 0.99999 of it).
  Solver solver(squeezeScene(), FluidProperties{}, {foam()}, SolverSettings{}, fixedStep(1e-3), RunState{});
  Vec3 mean = Vec3::Zero();
  const int steps = 400, averaged = 100;
  for (int n = 0; n < steps; ++n) {
    solver.step(1e-3);
    if (n < steps - averaged) continue;
    const StepContext ctx = solver.beginStep(1e-3); // the pressures of the step just done on its positions
    mean += rigidBodyWrenches(ctx, {kFloor}, {Vec3::Zero()})[0].force / averaged;
  }
  const ParticleSet& block = solver.particles()[0];
  const double weight = block.mass * static_cast<double>(block.size()) * 9.81;
  EXPECT_NEAR(-mean.y(), weight, 0.02 * weight) << "the particles push the floor down by their weight";
  double lowest = 1.0;
  for (const Vec3& x : block.x()) lowest = std::min(lowest, x.y());
  EXPECT_GE(lowest, kR - 0.1 * kR);
}

/// The lowest centre of an incompressible skeleton settling for 0.4 s on the floor, with PoroSPH's defaults: the
/// deepest it reached at any step, and where it stands at the end.
struct Settled {
  double deepest = 1.0, last = 1.0;
};
Settled lowestOfSettlingIncompressibleBody(std::vector<Vec3> positions) {
  ParticleSystem ps(kR);
  addSet(ps, "stone", SetKind::Porous, std::move(positions), kBlock);
  addFloor(ps);
  PorousMaterial stone = material("stone", 0.6, 5000.0, false); // the published Seep's block: bulk 2000 kg/m^3
  stone.youngsModulus = 2.5e5;
  stone.poissonsRatio = 0.3;
  stone.dampingViscosity = 5.0;
  Solver solver(std::move(ps), FluidProperties{}, {stone}, SolverSettings{}, fixedStep(1e-3), RunState{});
  Settled s;
  for (int n = 0; n < 400; ++n) {
    solver.step(1e-3);
    s.last = 1.0;
    for (const Vec3& x : solver.particles()[0].x()) s.last = std::min(s.last, x.y());
    s.deepest = std::min(s.deepest, s.last);
  }
  return s;
}

std::vector<Vec3> ballOnFloor() { // radius 4r, its lowest lattice particles r above the floor
  std::vector<Vec3> ball;
  for (const Vec3& x : sampleBox(Vec3(0.0, 0.0, 0.0), Vec3(0.16, 0.16, 0.16), kR))
    if ((x - Vec3(0.08, 0.08, 0.08)).norm() <= 0.08 - 0.5 * kR) ball.push_back(x);
  return ball;
}

TEST(WallContact, IncompressibleBodiesRestOnTheFloorNotInIt) {
  // A box's floor layer is held by its full lattice's density (the control: it rests with or without the
  // contact), but the underside of a ball has few neighbours and density alone let it sink into the floor: 0.54 r
  // (pressure.wallContact compressibleSkeletons, as under either preset). With the contact constraint: 0.006 r.
  // Resting means on the floor too, not held above it: a particle centre r in front of the wall surface (measured
  // at 0.4 s: box 1.031 r, ball 0.996 r).
  for (const auto& body : {sampleBox(Vec3::Zero(), Vec3(0.12, 0.08, 0.12), kR), ballOnFloor()}) {
    const Settled s = lowestOfSettlingIncompressibleBody(body);
    EXPECT_GE(s.deepest, kR - 0.1 * kR) << "the body entered the floor";
    EXPECT_LE(s.last, kR + 0.1 * kR) << "the body does not rest on the floor";
  }
}

TEST(WallContact, EitherPresetLeavesIncompressibleSkeletonsToTheirDensity) {
  // readBack: the set holds the contact's restart fields, as one read from a run with the contact does.
  const auto contact = [](const std::string& text, bool compressible, bool readBack = false) {
    ParticleSystem ps(kR);
    ParticleSet& stone =
        addSet(ps, "stone", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3(0.04, 0.04, 0.04), kR), kBlock);
    if (readBack)
      for (const char* name : {field::contactPressure, field::wallContactLimit}) stone.addReal(name, Restart);
    addFloor(ps);
    const SolverSettings settings = SolverSettings::read(Dictionary::parse(text, "system/solverDict"));
    const Solver solver(std::move(ps), FluidProperties{}, {material("stone", 0.6, 5000.0, compressible)}, settings,
                        fixedStep(1e-3), RunState{});
    return hasWallContact(solver.particles()[0]);
  };
  EXPECT_TRUE(contact("threads: 0\n", false));
  EXPECT_FALSE(contact("compatibility: {preset: paper}\n", false));
  EXPECT_FALSE(contact("compatibility: {preset: reference}\n", false));
  EXPECT_TRUE(contact("compatibility: {preset: paper}\npressure: {wallContact: allSkeletons}\n", false));
  EXPECT_FALSE(contact("pressure: {wallContact: compressibleSkeletons}\n", false));
  EXPECT_TRUE(contact("compatibility: {preset: reference}\n", true)); // compressible skeletons always
  EXPECT_THROW(contact("pressure: {wallContact: all}\n", false), InputError);
  // A restart under a preset from a run that had the contact: the fields read back are dropped, not taken for it.
  EXPECT_FALSE(contact("compatibility: {preset: paper}\n", false, true));
  EXPECT_TRUE(contact("threads: 0\n", false, true));
}

} // namespace
} // namespace poro::test
