// The solver's use of the Verlet skin (solverDict neighbourSearch.skin): a few particles that outrun it (a
// jet) are the search's movers and leave the others on the skin; a crowd of them makes every step search at H.

#include "geometry/LatticeSampling.hpp"
#include "physics/FieldNames.hpp"
#include "physics/Solver.hpp"
#include "sph/NeighbourSearch.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

constexpr double kR = 0.01;

/// A weightless fluid block at rest (18³ = 5,832 particles, 2 cm apart), with particles of its top `layers` shot
/// upwards at 5 m/s, every `fastEvery`-th of them: at Δt = 1 ms they move 5 mm a step, more than the skin of
/// 0.1 H = 4 mm, and leave the block without pushing the others.
Solver jetSolver(int layers, std::size_t fastEvery) {
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  const std::vector<Vec3> points = sampleBox(Vec3::Zero(), Vec3::Constant(0.36), kR);
  fluid.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    fluid.x()[i] = points[i];
    const bool top = points[i].y() > 0.36 - 0.02 * layers;
    fluid.v()[i] = top && i % fastEvery == 0 ? Vec3(0.0, 5.0, 0.0) : Vec3::Zero();
    fluid.integer(field::id)[i] = static_cast<std::int64_t>(i);
  }
  FluidProperties water;
  water.gravity = Vec3::Zero();
  TimeControl control;
  control.deltaT = 1e-3;
  control.endTime = 1.0;
  control.writeInterval = 1.0;
  SolverSettings settings; // skin 0.1 H
  return Solver(std::move(ps), water, {}, settings, control, RunState{});
}

TEST(SearchSkin, AFewFastParticlesLeaveTheOthersOnTheSkin) {
  Solver solver = jetSolver(1, 4); // 81 particles, 1.4 %
  ASSERT_EQ(solver.particles()[0].size(), 5832u);
  for (int n = 0; n < 20; ++n) solver.step(1e-3);
  EXPECT_EQ(solver.neighbourSearch().updates(), 20u);
  EXPECT_EQ(solver.neighbourSearch().gridSearches(), 1u) << "1.4 % of the particles outrunning the skin searched the grid";
}

TEST(SearchSkin, ACrowdOfFastParticlesSearchesAtHEveryStep) {
  Solver solver = jetSolver(3, 1); // 972 particles, 17 %
  for (int n = 0; n < 20; ++n) solver.step(1e-3);
  EXPECT_EQ(solver.neighbourSearch().gridSearches(), solver.neighbourSearch().updates());
}

} // namespace
} // namespace poro
