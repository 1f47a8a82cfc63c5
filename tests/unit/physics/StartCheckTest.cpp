// What a run must not start from: particles packed denser than their density
// limit (health.startDensity, physics/StartDensity.hpp) and particles outside the domain. Both are found before
// step 1 and reported as input errors.

#include "PorousTestSystems.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

namespace poro::test {
namespace {

/// Water filling [0, 0.16]^3 in a closed two-layer container whose inner faces stand `gap` off it.
ParticleSystem waterInTank(double gap) {
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, sampleBox(Vec3::Zero(), Vec3::Constant(0.16), kR));
  addSet(ps, "boundary", SetKind::Boundary,
         sampleContainer(Vec3::Constant(-gap), Vec3::Constant(0.16 + gap), kR, 2, FaceFlags{}), 1);
  return ps;
}

/// Runs one step; returns the InputError's message, or "" when the run went through.
std::string startError(ParticleSystem ps, std::vector<PorousMaterial> materials = {},
                       const SolverSettings& settings = SolverSettings{}, int* writes = nullptr) {
  TimeControl oneStep = fixedStep(1e-3);
  oneStep.endTime = 1e-3;
  Solver solver(std::move(ps), FluidProperties{}, std::move(materials), settings, oneStep, RunState{});
  try {
    solver.run([&](const Solver&) {
      if (writes) ++*writes;
    });
  } catch (const InputError& e) {
    EXPECT_EQ(solver.state().step, 0) << "refused after a step";
    return e.what();
  }
  return "";
}

TEST(StartDensity, WaterSampledAgainstTheWallsIsRefusedBeforeStep1) {
  // The box's faces are the wall surface (first layer 2r from the first wall layer): rho~ = 1.047 at its
  // edges; 0.05 r off the walls (0.062 r between the particles here) still 1.021. The message names the
  // particle, its distance to the walls and the cure.
  ParticleSystem ps = waterInTank(0.0);
  ps[0].source = "case/0/fluid.vtp";
  int writes = 0;
  const std::string message = startError(std::move(ps), {}, SolverSettings{}, &writes);
  EXPECT_EQ(writes, 0);
  EXPECT_EQ(message.rfind("case/0/fluid.vtp: ", 0), 0u) << message;
  EXPECT_NE(message.find("fluid particles start denser than health.startDensity = 1.005 allows"), std::string::npos)
      << message;
  EXPECT_NE(message.find("starts at 1.047, 2 r from its nearest wall particle"), std::string::npos) << message;
  EXPECT_NE(message.find("a gap of 0 r"), std::string::npos) << message;
  EXPECT_NE(message.find("Leave a gap of 0.1 r or more"), std::string::npos) << message;
  EXPECT_NE(message.find("raise health.startDensity in system/solverDict"), std::string::npos) << message;

  const std::string close = startError(waterInTank(0.05 * kR));
  EXPECT_NE(close.find("starts at 1.021, 2.062 r from its nearest wall particle"), std::string::npos) << close;
}

TEST(StartDensity, OfEquallyDenseParticlesTheLowestIdIsNamed) {
  // The tank's eight corners are equally dense but for round-off, which the order of the sums decides. Ids
  // numbered backwards put the lowest one at the corner the Morton order visits last.
  ParticleSystem ps = waterInTank(0.0);
  std::vector<std::int64_t>& id = ps[0].integer(field::id);
  for (std::size_t i = 0; i < id.size(); ++i) id[i] = static_cast<std::int64_t>(id.size() - 1 - i);
  const std::string message = startError(std::move(ps));
  EXPECT_NE(message.find("the densest, id 0 at (0.15, 0.15, 0.15), starts at 1.047"), std::string::npos) << message;
}

TEST(StartDensity, WaterATenthOfARadiusOffTheWallsStarts) { EXPECT_EQ(startError(waterInTank(0.1 * kR)), ""); }

TEST(StartDensity, TheLimitIsTheSolverDictKey) {
  SolverSettings settings;
  settings.health.startDensity = 1.05;
  EXPECT_EQ(startError(waterInTank(0.0), {}, settings), "");
}

TEST(StartDensity, ARestartIsNotChecked) {
  // Compression in the middle of a run is the pressure solve's business, not the input's.
  RunState restart;
  restart.step = 10;
  restart.time = 0.01;
  TimeControl oneStep = fixedStep(1e-3);
  oneStep.endTime = 0.011;
  Solver solver(waterInTank(0.0), FluidProperties{}, {}, SolverSettings{}, oneStep, restart);
  EXPECT_NO_THROW(solver.run([](const Solver&) {}));
  EXPECT_EQ(solver.state().step, 11);
}

/// A porous block of porosity `phi` filling [0, 0.2]^3, with fluid on the lattice of spacing `spacing` in it.
ParticleSystem soakedBlock(double spacing) {
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, latticeOfSpacing(Vec3::Zero(), Vec3::Constant(0.2), spacing));
  addSet(ps, "soil", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3::Constant(0.2), kR), 1);
  return ps;
}

TEST(StartDensity, APreSaturatedBodyStartsInBothPoreFluidModes) {
  // Pore fluid at spacing 2r phi^(-1/3): rho~ = 1.047 in paper mode at phi = 0.4 (the lattice excess of Eq. 4),
  // 1.000 with latticeCorrected; the check judges both without the excess.
  const double phi = 0.4;
  for (const SolverSettings& settings : {eq4AsPublished(), SolverSettings{}})
    EXPECT_EQ(
        startError(soakedBlock(2.0 * kR * std::pow(phi, -1.0 / 3.0)), {material("soil", phi, 2000.0, false)}, settings),
        "");
}

TEST(StartDensity, FluidSampledThroughAPorousBodyIsRefused) {
  // The full fluid lattice in pores: rho~ = 1 + (1 - phi) = 1.6, judged without the lattice excess 0.046.
  const std::string message = startError(soakedBlock(2.0 * kR), {material("soil", 0.4, 2000.0, false)});
  EXPECT_NE(message.find("fluid particles start denser than health.startDensity"), std::string::npos) << message;
  EXPECT_NE(message.find("starts at 1.554,"), std::string::npos) << message;
  EXPECT_NE(message.find("more than 4 r from every wall particle"), std::string::npos) << message;
}

/// A porous block sampled against the walls of its container (no fluid), Fixed (fixed: true) or not.
ParticleSystem blockInTank(bool fixed) {
  ParticleSystem ps(kR);
  ParticleSet& block = addSet(ps, "soil", SetKind::Porous, sampleBox(Vec3::Zero(), Vec3::Constant(0.16), kR));
  auto& flags = block.addInt(field::fixed, Restart);
  std::fill(flags.begin(), flags.end(), fixed ? 1 : 0);
  addSet(ps, "boundary", SetKind::Boundary, sampleContainer(Vec3::Zero(), Vec3::Constant(0.16), kR, 2, FaceFlags{}), 1);
  return ps;
}

TEST(StartDensity, ActivePorousParticlesAreJudgedFixedOnesAreNot) {
  const std::vector<PorousMaterial> soil{material("soil", 0.4, 2000.0, false)};
  const std::string message = startError(blockInTank(false), soil);
  EXPECT_NE(message.find("soil particles start denser"), std::string::npos) << message;
  EXPECT_NE(message.find("starts at 1.047,"), std::string::npos) << message;
  EXPECT_EQ(startError(blockInTank(true), soil), "");
}

/// Water 0.1 r off the walls with one particle moved to 1e6 m (a damaged restart file).
ParticleSystem waterWithAStray() {
  ParticleSystem ps = waterInTank(0.1 * kR);
  ps[0].x()[5] = Vec3(1e6, 0.05, 0.05);
  ps[0].source = "case/0.5/fluid.vtp";
  return ps;
}

TEST(StartPositions, AParticleOutsideTheDomainIsAnInputErrorNamingFileIdAndPosition) {
  for (const HealthAction action : {HealthAction::Remove, HealthAction::Stop}) {
    SolverSettings settings;
    settings.health.leavingDomain = action;
    try {
      Solver solver(waterWithAStray(), FluidProperties{}, {}, settings, fixedStep(1e-3), RunState{0.5, 500, 1e-3});
      ADD_FAILURE() << "a particle at 1e6 m was accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(
          message.rfind("case/0.5/fluid.vtp: 1 fluid particle: id 5 at (1e+06, 0.05, 0.05) outside the domain (", 0),
          0u)
          << message;
      EXPECT_NE(message.find("the walls' bounding box grown by its longest side, at the start (time 0.5 s, step 500)"),
                std::string::npos)
          << message;
      EXPECT_NE(message.find("Restore the file or start from an earlier time directory"), std::string::npos) << message;
    }
  }
}

TEST(StartPositions, UnderLeavingDomainWarnTheyStay) {
  SolverSettings settings;
  settings.health.leavingDomain = HealthAction::Warn;
  Solver solver(waterWithAStray(), FluidProperties{}, {}, settings, fixedStep(1e-3), RunState{0.5, 500, 1e-3});
  EXPECT_EQ(solver.particles()[0].size(), 512u);
}

} // namespace
} // namespace poro::test
