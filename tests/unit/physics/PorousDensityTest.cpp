// Densities with the volume-factor table, saturation and local porosity on lattices (METHOD.md §3.3, §6.4).

#include "PorousTestSystems.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace poro {
namespace {

using namespace test;

/// Interior kernel sum of the 2r lattice incl. self (METHOD.md §2.2): what every formula below scales.
constexpr double kInteriorSum = 0.99997;
constexpr double kLatticeTolerance = 1e-4; // the §2.2 table is quoted to 5 digits

/// Runs steps 1-4 of the step on a system (Eq. 4 as published) and returns the solver for inspection.
std::unique_ptr<Solver> prepared(ParticleSystem ps, std::vector<PorousMaterial> materials) {
  auto solver = std::make_unique<Solver>(std::move(ps), weightless(), std::move(materials), eq4AsPublished(),
                                         fixedStep(1e-3), RunState{});
  solver->beginStep(1e-3);
  return solver;
}

const std::vector<Vec3> kBlock = sampleBox(Vec3::Zero(), Vec3::Constant(0.16), kR); // 8^3, centre (0.08)^3
const Vec3 kCentre = Vec3::Constant(0.07);                                          // an interior site

class PorousLatticeDensity : public ::testing::TestWithParam<bool> {};

TEST_P(PorousLatticeDensity, MatchesEquation3) {
  // Porous lattice alone: rho~ = c 0.99997, and rho_s = 0.99997 rho_b for both kinds of pores.
  const bool compressible = GetParam();
  const double phi = 0.6;
  ParticleSystem ps(kR);
  addSet(ps, "sand", SetKind::Porous, kBlock);
  const auto solver = prepared(std::move(ps), {material("sand", phi, 2500.0, compressible)});
  const ParticleSet& set = solver->particles()[0];
  const std::size_t i = nearest(set.x(), kCentre);
  const double c = compressible ? 1.0 - phi : 1.0;
  EXPECT_NEAR(set.real(field::rhoTilde)[i], c * kInteriorSum, kLatticeTolerance);
  EXPECT_NEAR(set.real(field::density)[i] / ((1.0 - phi) * 2500.0), kInteriorSum, kLatticeTolerance);
}

INSTANTIATE_TEST_SUITE_P(BothPoreKinds, PorousLatticeDensity, ::testing::Bool());

TEST(PorousDensity, OtherObjectsCountWithFactorOne) {
  // Two objects of one compressible material side by side: across the contact the other body counts
  // fully (bodies do not interpenetrate), so a contact particle is denser than c times the face sum.
  const double phi = 0.5;
  ParticleSystem ps(kR);
  ParticleSet& set = addSet(ps, "foam", SetKind::Porous, kBlock, 0);
  std::vector<Vec3> second = kBlock;
  for (Vec3& p : second) p.x() += 0.16;
  appendObject(set, second, 1);
  const auto solver = prepared(std::move(ps), {material("foam", phi, 1000.0, true)});
  const ParticleSet& s = solver->particles()[0];
  const std::size_t contact = nearest(s.x(), Vec3(0.15, 0.07, 0.07)); // last layer of object 0
  // Own half-space (face sum 0.850) counts c = 1 - phi, the other body's half (0.99997 - 0.850) counts 1.
  const double face = 0.850288;
  EXPECT_NEAR(s.real(field::rhoTilde)[contact], (1.0 - phi) * face + (kInteriorSum - face), 2e-4);
}

TEST(FluidInPores, FluidParticleAtLatticeSiteOfPorousLattice) {
  // rho~_i = 1/pi (self) + (1 - phi) 0.99997 (Eq. 4); phi^loc = 1 - (1 - phi) 0.99997 (METHOD.md §6.4).
  const double phi = 0.4;
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, {kBlock[nearest(kBlock, kCentre)]});
  addSet(ps, "sand", SetKind::Porous, kBlock);
  const auto solver = prepared(std::move(ps), {material("sand", phi, 2650.0, false)});
  const ParticleSet& fluid = solver->particles()[0];
  EXPECT_NEAR(fluid.real(field::rhoTilde)[0], 1.0 / M_PI + (1.0 - phi) * kInteriorSum, kLatticeTolerance);
  EXPECT_NEAR(fluid.real(field::localPorosity)[0], 1.0 - (1.0 - phi) * kInteriorSum, kLatticeTolerance);
  // The porous particle at the same site sees no fluid in its density (solids do not see fluid).
  const ParticleSet& sand = solver->particles()[1];
  const std::size_t s = nearest(sand.x(), kCentre);
  EXPECT_NEAR(sand.real(field::rhoTilde)[s], kInteriorSum, kLatticeTolerance);
}

/// Sum of V W over an infinite simple cubic lattice of spacing d, at a lattice site (self included).
double latticeSum(double d) {
  const CubicKernel kernel(4.0 * kR);
  const int n = static_cast<int>(4.0 * kR / d) + 1;
  double sum = 0.0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) sum += kernel.w(d * Vec3(i, j, k).norm());
  return 8.0 * kR * kR * kR * sum;
}

TEST(FluidInPores, FilledPoresAreAtRestDensity) {
  // A fluid lattice whose own kernel sum is phi 0.99997 (spacing near 2r phi^(-1/3), found by bisection on
  // the lattice sum) inside a porous lattice of porosity phi is at rest density: rho~ = phi 0.99997 +
  // (1 - phi) x (the 2r lattice sum at the fluid particle's offset, 0.99997 +- 0.2 %).
  for (const double phi : {0.5, 0.6, 0.8}) {
    double lo = 2.0 * kR, hi = 3.0 * kR; // the sum falls with the spacing on this interval
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (latticeSum(mid) > phi * kInteriorSum ? lo : hi) = mid;
    }
    ParticleSystem ps(kR);
    addSet(ps, "fluid", SetKind::Fluid, latticeOfSpacing(Vec3::Zero(), Vec3::Constant(0.24), lo));
    addSet(ps, "sand", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3::Constant(0.24), kR));
    const auto solver = prepared(std::move(ps), {material("sand", phi, 2650.0, false)});
    const ParticleSet& fluid = solver->particles()[0];
    EXPECT_NEAR(fluid.real(field::rhoTilde)[nearest(fluid.x(), Vec3::Constant(0.12))], 1.0, 2e-3 * (1.0 - phi))
        << "phi " << phi;
  }
}

TEST(FluidInPores, LatticeCorrectionPutsPoreFluidAtTheIdealSpacingAtRestDensity) {
  // pressure.poreFluidDensity latticeCorrected: a fluid lattice at exactly 2r phi^(-1/3) inside a porous
  // lattice of porosity phi is at rest density (within the solid lattice's +-0.2 % at the fluid particle's
  // offset); Eq. 4 as it stands reads it b(phi) too dense (+4.6 % at phi = 0.4), so the fluid would have to
  // spread out to ~10 % fewer particles.
  for (const double phi : {0.3, 0.4, 0.6}) {
    const double spacing = 2.0 * kR / std::cbrt(phi);
    for (const bool correct : {false, true}) {
      ParticleSystem ps(kR);
      addSet(ps, "fluid", SetKind::Fluid, latticeOfSpacing(Vec3::Zero(), Vec3::Constant(0.24), spacing));
      addSet(ps, "sand", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3::Constant(0.24), kR));
      Solver solver(std::move(ps), weightless(), {material("sand", phi, 2650.0, false)},
                    correct ? SolverSettings{} : eq4AsPublished(), fixedStep(1e-3), RunState{});
      solver.beginStep(1e-3);
      const ParticleSet& fluid = solver.particles()[0];
      const double rho = fluid.real(field::rhoTilde)[nearest(fluid.x(), Vec3::Constant(0.12))];
      const double bias = latticeSum(spacing) - phi * kInteriorSum;
      EXPECT_NEAR(rho, correct ? 1.0 : 1.0 + bias, 2e-3 * (1.0 - phi)) << "phi " << phi << " corrected " << correct;
    }
  }
}

TEST(FluidInPores, LatticeCorrectionLeavesFluidAwayFromSolidsUnchanged) {
  // b(1) = 0 and walls do not count as solid: a fluid block on a wall has bit-identical densities.
  std::vector<double> rho[2];
  for (const bool correct : {false, true}) {
    ParticleSystem ps(kR);
    addSet(ps, "fluid", SetKind::Fluid, kBlock);
    addSet(ps, "floor", SetKind::Boundary, sampleBox(Vec3(-0.04, -0.04, -0.04), Vec3(0.2, 0.0, 0.2), kR));
    Solver solver(std::move(ps), weightless(), {}, correct ? SolverSettings{} : eq4AsPublished(), fixedStep(1e-3),
                  RunState{});
    solver.beginStep(1e-3);
    rho[correct] = solver.particles()[0].real(field::rhoTilde);
  }
  EXPECT_EQ(rho[0], rho[1]);
}

TEST(Saturation, CoincidentFluidClampsToOneAndNoFluidIsZero) {
  const double phi = 0.5;
  {
    ParticleSystem ps(kR);
    addSet(ps, "fluid", SetKind::Fluid, kBlock);
    addSet(ps, "sand", SetKind::Porous, kBlock);
    const auto solver = prepared(std::move(ps), {material("sand", phi, 2000.0, false)});
    const ParticleSet& sand = solver->particles()[1];
    EXPECT_EQ(sand.real(field::saturation)[nearest(sand.x(), kCentre)], 1.0); // 0.99997 / phi, clamped
  }
  {
    ParticleSystem ps(kR);
    addSet(ps, "sand", SetKind::Porous, kBlock);
    const auto solver = prepared(std::move(ps), {material("sand", phi, 2000.0, false)});
    for (double s : solver->particles()[0].real(field::saturation)) EXPECT_EQ(s, 0.0);
  }
}

TEST(Saturation, AtAFluidFrontIsTheFaceSumOverPorosity) {
  // Fluid fills the lower half of a porous block on the same lattice. N_s = 1 in the interior
  // (m/rho = V/0.99997), so S = (sum over the fluid half-space)/phi: the flat-face sum 0.850288 in the top
  // fluid layer and 0.99997 - 0.850288 one layer above (METHOD.md §2.2, Eq. 12).
  const double phi = 0.9;
  const auto block = sampleBox(Vec3::Zero(), Vec3::Constant(0.24), kR);
  std::vector<Vec3> lowerHalf;
  for (const Vec3& p : block)
    if (p.y() < 0.12) lowerHalf.push_back(p);
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, lowerHalf);
  addSet(ps, "sand", SetKind::Porous, block);
  const auto solver = prepared(std::move(ps), {material("sand", phi, 2000.0, false)});
  const ParticleSet& sand = solver->particles()[1];
  const double face = 0.850288;
  EXPECT_NEAR(sand.real(field::saturation)[nearest(sand.x(), Vec3(0.11, 0.11, 0.11))], face / phi, 1e-5);
  EXPECT_NEAR(sand.real(field::saturation)[nearest(sand.x(), Vec3(0.11, 0.13, 0.11))], (kInteriorSum - face) / phi,
              1e-4);
}

TEST(IsolatedParticles, FallFreelyWithFiniteFields) {
  // METHOD.md §4.3: rho~ = 1/pi (incompressible) or c/pi (compressible), alpha = 0, S = 0, phi^loc = 1.
  for (const bool compressible : {false, true}) {
    const double phi = 0.7;
    ParticleSystem ps(kR);
    addSet(ps, "fluid", SetKind::Fluid, {Vec3(1.0, 1.0, 1.0)});
    addSet(ps, "cork", SetKind::Porous, {Vec3(0.0, 1.0, 0.0)});
    Solver solver(std::move(ps), FluidProperties{}, {material("cork", phi, 500.0, compressible, 5.0)}, SolverSettings{},
                  fixedStep(1e-3), RunState{});
    for (int n = 1; n <= 20; ++n) solver.step(1e-3);
    const ParticleSet& cork = solver.particles()[1];
    const ParticleSet& fluid = solver.particles()[0];
    const double c = compressible ? 1.0 - phi : 1.0;
    EXPECT_DOUBLE_EQ(cork.real(field::rhoTilde)[0], c / M_PI);
    EXPECT_EQ(cork.real(field::alpha)[0], 0.0);
    EXPECT_EQ(cork.real(field::saturation)[0], 0.0);
    EXPECT_EQ(fluid.real(field::localPorosity)[0], 1.0);
    const double fallen = 9.81 * 1e-6 * 20 * 21 / 2.0; // symplectic Euler, METHOD.md §6.8
    EXPECT_NEAR(cork.x()[0].y(), 1.0 - fallen, 1e-12);
    EXPECT_NEAR(fluid.x()[0].y(), 1.0 - fallen, 1e-12);
  }
}

TEST(FixedParticles, StayPutAndHoldUpTheirActiveNeighbours) {
  // METHOD.md §4.2: a Fixed particle keeps x and v and pi = 0; Active neighbours feel it. Without
  // elasticity the free part of the block is a granular liquid: it slumps and spreads under gravity, but
  // solid-solid pressure (Eq. 8) against the Fixed layers keeps it above them, where free fall over
  // 0.1 s would have carried it 49 mm down, through the fixed layers.
  PorousMaterial wall = material("wall", 0.6, 7500.0, false);
  wall.fixedBox = std::make_pair(Vec3(-1.0, -1.0, -1.0), Vec3(1.0, 0.04, 1.0)); // the lowest 2 layers
  ParticleSystem ps(kR);
  addSet(ps, "wall", SetKind::Porous, kBlock);
  Solver solver(std::move(ps), FluidProperties{}, {wall}, SolverSettings{}, fixedStep(1e-3), RunState{});
  const std::vector<Vec3> before = solver.particles()[0].x();
  for (int n = 0; n < 100; ++n) solver.step(1e-3);
  const ParticleSet& set = solver.particles()[0];
  const auto& fixed = set.integer(field::fixed);
  std::size_t fixedCount = 0, above = 0;
  for (std::size_t i = 0; i < set.size(); ++i) {
    const std::size_t original = static_cast<std::size_t>(set.integer(field::id)[i]);
    const Vec3& x = set.x()[i];
    if (fixed[i]) {
      ++fixedCount;
      EXPECT_EQ(x, before[original]);
      EXPECT_EQ(set.v()[i], Vec3::Zero());
      EXPECT_EQ(set.real(field::pi)[i], 0.0);
    } else if (x.x() > 0.0 && x.x() < 0.16 && x.z() > 0.0 && x.z() < 0.16) {
      EXPECT_GT(x.y(), 0.03) << "particle " << original << " sank into the fixed layers";
      ++above;
    }
  }
  EXPECT_EQ(fixedCount, 2u * 8u * 8u);
  EXPECT_GT(above, 100u);
}

} // namespace
} // namespace poro
