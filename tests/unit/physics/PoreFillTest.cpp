// How full the pores near a porous particle are, and the adhesion's fade in over-full pores (PoreFill.hpp).

#include "physics/PoreFill.hpp"
#include "PorousTestSystems.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace poro {
namespace {

using namespace test;

const double kVolume = 8.0 * kR * kR * kR;

/// Lattice sites 2r k of a box of cells [lo, hi) per axis.
std::vector<Vec3> cells(const Eigen::Vector3i& lo, const Eigen::Vector3i& hi) {
  std::vector<Vec3> x;
  for (int i = lo.x(); i < hi.x(); ++i)
    for (int j = lo.y(); j < hi.y(); ++j)
      for (int k = lo.z(); k < hi.z(); ++k) x.push_back(2.0 * kR * Vec3(i, j, k));
  return x;
}

/// The integral of W(x_s - y) over the union of the cubes of edge 2r about the sites: the share of the
/// kernel's support at the origin that the body covers. Midpoint rule, 12^3 points per cube.
double kernelIntegralOverCubes(const std::vector<Vec3>& sites) {
  const CubicKernel kernel(4.0 * kR);
  constexpr int n = 12;
  const double h = 2.0 * kR / n;
  double sum = 0.0;
  for (const Vec3& c : sites)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k)
          sum += kernel.w(c + Vec3(-kR + h * (i + 0.5), -kR + h * (j + 0.5), -kR + h * (k + 0.5)));
  return sum * h * h * h;
}

TEST(PoreFill, BodyCoverageIsTheKernelIntegralOverTheBodyWhereTheLatticeSumIsNot) {
  // sum_t V Wbar_st equals the integral of W over the body at the interior, a face, an edge, a corner and
  // in strokes two and one particles wide. The ball of volume V stands in for the cube of edge 2r: equal
  // volume, but second moments of 0.308 r^2 against r^2/3 per axis, which leaves the sums within 2.5 %. The
  // plain lattice sum sum_t V W_st over-counts the particle's own cube: 4.6 % on a face, 24 % in the stroke
  // one particle wide.
  const CubicKernel kernel(4.0 * kR);
  const PoreFill fill(kernel, kVolume);
  struct Body {
    const char* name;
    std::vector<Vec3> sites; // the particle under test at the origin
    double latticeExcess;    // least over-count of the plain lattice sum
  };
  const std::vector<Body> bodies{
      {"interior", cells({-4, -4, -4}, {5, 5, 5}), -1.0},   {"face", cells({0, -4, -4}, {5, 5, 5}), 0.04},
      {"edge", cells({0, 0, -4}, {5, 5, 5}), 0.08},         {"corner", cells({0, 0, 0}, {5, 5, 5}), 0.12},
      {"stroke 2 x 2", cells({0, 0, -4}, {2, 2, 5}), 0.08}, {"stroke 1 x 1", cells({0, 0, -4}, {1, 1, 5}), 0.2},
  };
  for (const Body& body : bodies) {
    double coverage = 0.0, lattice = 0.0;
    for (const Vec3& t : body.sites) {
      coverage += fill.volumeWeight(t.norm());
      lattice += kVolume * kernel.w(t.norm());
    }
    const double integral = kernelIntegralOverCubes(body.sites);
    EXPECT_NEAR(coverage / integral, 1.0, 0.025) << body.name;
    EXPECT_GT(lattice / integral - 1.0, body.latticeExcess) << body.name;
  }
}

TEST(PoreFill, WeightEndsAtTheSupportAndTheDenseLatticeSumsToOne) {
  const CubicKernel kernel(4.0 * kR);
  const PoreFill fill(kernel, kVolume);
  EXPECT_EQ(fill.volumeWeight(4.0 * kR), 0.0);
  EXPECT_EQ(fill.volumeWeight(5.0 * kR), 0.0);
  EXPECT_GT(fill.volumeWeight(3.9 * kR), 0.0);
  double sum = 0.0;
  for (const Vec3& t : cells({-3, -3, -3}, {4, 4, 4})) sum += fill.volumeWeight(t.norm());
  EXPECT_NEAR(sum, 1.0, 1e-12);
  // Averaging over a ball lowers the peak: V Wbar(0) < V W(0) = 1/pi.
  EXPECT_LT(fill.volumeWeight(0.0), kVolume * kernel.w0());
}

TEST(PoreFill, FadeRunsFromFivePercentOverFullToTenPercent) {
  EXPECT_EQ(PoreFill::fade(0.0), 1.0);
  EXPECT_EQ(PoreFill::fade(1.0), 1.0);
  EXPECT_EQ(PoreFill::fade(1.05), 1.0);
  EXPECT_NEAR(PoreFill::fade(1.075), 0.5, 1e-12);
  EXPECT_NEAR(PoreFill::fade(1.1), 0.0, 1e-12);
  EXPECT_EQ(PoreFill::fade(2.0), 0.0);
  EXPECT_EQ(PoreFill::fade(1e9), 0.0);
}

TEST(PoreFill, CompressiblePoresCloseWhenSqueezedAndOpenWhenSwollen) {
  // Incompressible: phi times the coverage, whatever the rest coverage. Compressible: the rest coverage less
  // the solid volume (1 - phi) V per particle; at rest the two agree.
  EXPECT_DOUBLE_EQ(PoreFill::poreVolume(0.6, false, 0.8, 1.0), 0.6 * 0.8);
  EXPECT_DOUBLE_EQ(PoreFill::poreVolume(0.6, true, 0.8, 0.8), 0.6 * 0.8);
  EXPECT_DOUBLE_EQ(PoreFill::poreVolume(0.6, true, 1.2, 1.0), 1.0 - 0.4 * 1.2); // squeezed by 1/1.2
  EXPECT_DOUBLE_EQ(PoreFill::poreVolume(0.6, true, 0.8, 1.0), 1.0 - 0.4 * 0.8); // swollen
  EXPECT_EQ(PoreFill::poreVolume(0.6, true, 3.0, 1.0), 0.0);                    // squeezed shut
  EXPECT_DOUBLE_EQ(PoreFill::poreVolume(0.6, true, 0.8, -1.0), 0.6 * 0.8);      // rest not known yet
}

TEST(PoreFill, ReadsFullWhereFluidFillsAThinStrokesPoresAndSaturationDoesNot) {
  // A stroke two particles wide (phi = 0.5) whose volume holds fluid at phi/V particles per volume, placed at
  // random: in expectation every solid particle's fluid sum is phi times the kernel integral over the stroke,
  // so the pore fill is 1 within the coverage's 2.5 %; the bound adds three standard errors of the mean over
  // the realisations. S of Eq. 12 normalises by the Shepard sum instead, which the stroke's deficient
  // densities push to about 1, and reads about 0.6 (the stroke covers 66 % of the support).
  const double phi = 0.5;
  const Vec3 lo(-kR, -kR, -kR), hi(3.0 * kR, 3.0 * kR, 79.0 * kR); // 2 x 2 x 40 cells
  const std::vector<Vec3> solid = cells({0, 0, 0}, {2, 2, 40});
  const auto fluidCount = static_cast<std::size_t>(std::lround(phi * solid.size()));
  std::vector<double> fills, saturations;
  for (unsigned seed = 1; seed <= 30; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> fluid(fluidCount);
    for (Vec3& x : fluid) x = lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(hi - lo);
    ParticleSystem ps(kR);
    addSet(ps, "fluid", SetKind::Fluid, fluid);
    addSet(ps, "sand", SetKind::Porous, solid);
    PorousMaterial sand = material("sand", phi, 2000.0, false);
    sand.capillaryStrength = 1000.0;
    Solver solver(std::move(ps), weightless(), {sand}, SolverSettings{}, fixedStep(1e-3), RunState{});
    const StepContext ctx = solver.beginStep(1e-3);
    ASSERT_NE(ctx.poreFill, nullptr);
    const ParticleSet& set = solver.particles()[ctx.dynamicSets[1]];
    double fill = 0.0, saturation = 0.0;
    int middle = 0;
    for (std::size_t s = 0; s < set.size(); ++s)
      if (set.x()[s].z() > 8.0 * kR && set.x()[s].z() < 70.0 * kR) { // two supports off the stroke's ends
        fill += set.real(field::poreFill)[s];
        saturation += set.real(field::saturation)[s];
        ++middle;
      }
    ASSERT_GT(middle, 100);
    fills.push_back(fill / middle);
    saturations.push_back(saturation / middle);
  }
  double mean = 0.0, spread = 0.0, meanSaturation = 0.0;
  for (std::size_t k = 0; k < fills.size(); ++k) {
    mean += fills[k] / fills.size();
    meanSaturation += saturations[k] / fills.size();
  }
  for (double f : fills) spread += (f - mean) * (f - mean) / (fills.size() - 1);
  const double standardError = std::sqrt(spread / fills.size());
  EXPECT_NEAR(mean, 1.0, 0.025 + 3.0 * standardError) << "standard error " << standardError;
  EXPECT_LT(standardError, 0.02); // the realisations pin the mean down
  EXPECT_LT(meanSaturation, 0.8);
}

TEST(PoreFill, OnlyWhereTheAdhesionFadesAndSomeMaterialAdheres) {
  const auto contextOf = [](double strength, bool fades) {
    ParticleSystem ps(kR);
    addSet(ps, "fluid", SetKind::Fluid, {Vec3::Zero()});
    addSet(ps, "sand", SetKind::Porous, {Vec3(1.5 * kR, 0.0, 0.0)});
    PorousMaterial sand = material("sand", 0.5, 2000.0, false);
    sand.capillaryStrength = strength;
    SolverSettings settings;
    settings.implicit.adhesionFadesInFullPores = fades;
    auto solver = std::make_unique<Solver>(std::move(ps), weightless(), std::vector<PorousMaterial>{sand}, settings,
                                           fixedStep(1e-3), RunState{});
    return solver->beginStep(1e-3).poreFill != nullptr;
  };
  EXPECT_TRUE(contextOf(100.0, true));
  EXPECT_FALSE(contextOf(0.0, true));
  EXPECT_FALSE(contextOf(100.0, false));
}

TEST(PoreFill, CompressibleRestCoverageIsTakenAtTheFirstStep) {
  // The rest coverage of a compressible adhering material is the coverage of its first step, and a squeeze
  // afterwards shrinks the pore volume below phi times the new coverage.
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, {Vec3(20.0 * kR, 0.0, 0.0)});
  addSet(ps, "foam", SetKind::Porous, cells({0, 0, 0}, {5, 5, 5}));
  PorousMaterial foam = material("foam", 0.6, 800.0, true);
  foam.capillaryStrength = 500.0;
  Solver solver(std::move(ps), weightless(), {foam}, SolverSettings{}, fixedStep(1e-3), RunState{});
  ParticleSet& set = solver.particles()[1];
  ASSERT_TRUE(set.has(field::restCoverage));
  for (double c : set.real(field::restCoverage)) EXPECT_EQ(c, 0.0) << "unset";
  set.real(field::restCoverage).back() = -1.0; // unset as in files of older versions
  solver.beginStep(1e-3);
  EXPECT_GT(set.real(field::restCoverage).back(), 0.0);
  const auto at = [&](const Vec3& x) {
    for (std::size_t s = 0; s < set.size(); ++s)
      if ((set.x()[s] - x).norm() < 1e-9) return set.real(field::restCoverage)[s];
    ADD_FAILURE() << "no particle at " << x.transpose();
    return 0.0;
  };
  EXPECT_NEAR(at(2.0 * kR * Vec3(2, 2, 2)), 1.0, 1e-9); // two layers deep: the dense lattice's sum
  EXPECT_GT(at(Vec3::Zero()), 0.3);                     // a corner covers less
  EXPECT_LT(at(Vec3::Zero()), 0.6);
}

} // namespace
} // namespace poro
