// Coarse regression runs of the fluid tutorials (VALIDATION.md "Fluid alone") that need particle data: the
// pressure profile and the floor force of the hydrostatic tank. The dam-break front is checked by
// tutorials/fluid/damBreak/Alltest.

#include "CaseRunner.hpp"

#include "physics/FieldNames.hpp"
#include "sph/BoundaryVolume.hpp"
#include "sph/Kernel.hpp"
#include "sph/NeighbourSearch.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace poro::test {
namespace {

constexpr double kGravity = 9.81;
constexpr double kRho0 = 1000.0;

/// Hydrostatic tank as in the tutorial (20 x 25 x 20 particles, r = 1 cm, depth 0.5 m), but settled by a
/// viscosity: mu = 5 Pa s brings it to 6 mm/s rms by t = 1 s; at rest viscosity does not change the pressure.
/// Without the tutorial's XSPH smoothing, which compacts the column further (its surface ends about 1 % lower) and
/// leaves the third layer below the surface 5.2-5.3 % over rho0 g d (tutorial README, issue 23).
/// 1.5 s, the checks use the last 0.5 s.
class HydrostaticTank : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    runner_ = new CaseRunner("fluid/hydrostaticTank", "HydrostaticTank");
    runner_->setKey("constant/fluidProperties", "viscosity", "5");
    runner_->setKey("system/solverDict", "xsph", "0");
    // The tutorial's solve, 0.001 % with Chebyshev at 0.98. At the default 0.01 % the column's compression wanders
    // within the tolerance from step to step, and so does its floor force: single snapshots read 0.958-1.074 of the
    // weight, and round-off alone (a build with fused multiply-adds) moved their 0.5 s average from 1.007 to 1.022.
    // At 0.001 % they read 1.0072-1.0079, either way.
    runner_->setKey("system/solverDict", "  maxDensityError", std::to_string(kTolerancePercent));
    runner_->setKey("system/solverDict", "  spectralRadius", "0.98");
    runner_->setKey("system/controlDict", "endTime", "1.5");
    runner_->setKey("system/controlDict", "writeInterval", "0.02"); // 25 snapshots over the last 0.5 s
    ASSERT_EQ(runner_->sample(), 0) << runner_->read("log.sampleParticles");
    ASSERT_EQ(runner_->solve(), 0) << runner_->read("log.poroSph");
  }
  static void TearDownTestSuite() {
    delete runner_;
    runner_ = nullptr;
  }
  /// The last `count` written times.
  static std::vector<TimeDirectoryEntry> lastTimes(std::size_t count) {
    auto times = listTimeDirectories(runner_->dir());
    times.erase(times.begin(), times.end() - static_cast<long>(std::min(count, times.size())));
    return times;
  }
  static CaseRunner* runner_;
  static constexpr double radius_ = 0.01;
  static constexpr double kTolerancePercent = 0.001; ///< solverDict pressure.maxDensityError
};
CaseRunner* HydrostaticTank::runner_ = nullptr;

/// rho~ at the written positions (fluid and wall volumes, METHOD.md §3.3), so the check sees the state
/// after the last pressure correction rather than the density stored at the start of that step.
std::vector<double> densitiesAt(ParticleSystem& ps, double radius) {
  ParticleSet& fluid = *ps.find("fluid");
  ParticleSet& boundary = *ps.find("boundary");
  const CubicKernel kernel(4 * radius);
  computeBoundaryVolumes(boundary, kernel);
  NeighbourSearch search(4 * radius);
  search.update({&fluid.x(), &boundary.x()}, {{true, true}, {false, false}});
  const double volume = 8 * radius * radius * radius;
  std::vector<double> rho(fluid.size());
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    double sum = volume * kernel.w0();
    for (Index j : search.list(0, 0).of(i))
      sum += volume * kernel.w(fluid.x()[i] - fluid.x()[static_cast<std::size_t>(j)]);
    for (Index k : search.list(0, 1).of(i))
      sum += boundary.real(kBoundaryVolumeField)[static_cast<std::size_t>(k)] *
             kernel.w(fluid.x()[i] - boundary.x()[static_cast<std::size_t>(k)]);
    rho[i] = kRho0 * sum;
  }
  return rho;
}

/// Free-surface height: the median over lattice columns of each column's highest particle, plus r.
double surfaceHeight(const ParticleSet& fluid, double radius) {
  std::map<std::pair<long, long>, double> top;
  for (const Vec3& x : fluid.x()) {
    const auto key = std::make_pair(std::lround(x.x() / (2 * radius)), std::lround(x.z() / (2 * radius)));
    auto it = top.find(key);
    if (it == top.end() || it->second < x.y()) top[key] = x.y();
  }
  std::vector<double> heights;
  for (const auto& entry : top) heights.push_back(entry.second);
  std::nth_element(heights.begin(), heights.begin() + static_cast<long>(heights.size() / 2), heights.end());
  return heights[heights.size() / 2] + radius;
}

TEST_F(HydrostaticTank, DensityStaysWithinTolerance) {
  // The solver's own measure (METHOD.md §6.7): the mean compression after each step's pressure solve,
  // over the last 500 steps, against solverDict maxDensityError.
  std::istringstream log(runner_->read("log.poroSph"));
  std::vector<double> errors;
  for (std::string line; std::getline(log, line);) {
    const auto at = line.find("density error ");
    if (line.rfind("pressure:", 0) == 0 && at != std::string::npos) errors.push_back(std::stod(line.substr(at + 14)));
  }
  ASSERT_GE(errors.size(), 1500u);
  for (std::size_t s = errors.size() - 500; s < errors.size(); ++s)
    ASSERT_LE(errors[s], kTolerancePercent) << "step " << s + 1;
  // Recomputed at the written positions: no particle above 1.01 rho0 (VALIDATION.md).
  for (const auto& time : lastTimes(25)) {
    ParticleSystem ps = runner_->particles(time.name, radius_);
    const std::vector<double> rho = densitiesAt(ps, radius_);
    double meanCompression = 0.0;
    for (double r : rho) meanCompression += std::max(r / kRho0 - 1.0, 0.0);
    meanCompression /= static_cast<double>(rho.size());
    EXPECT_LE(*std::max_element(rho.begin(), rho.end()), 1.01 * kRho0) << "time " << time.name;
    RecordProperty("meanCompressionAt" + time.name, std::to_string(meanCompression));
  }
}

TEST_F(HydrostaticTank, PressureIsHydrostatic) {
  // Interior particles (three or more spacings from the walls, below the top two layers) of the last 0.5 s.
  // The free surface is where the least-squares line p(y) vanishes: it must lie within r of the particles'
  // own surface (top particle + r); the line's slope must be rho0 g within 5 %, and every layer's mean
  // pressure within 5 % of rho0 g d, d the depth below that surface (VALIDATION.md).
  const double spacing = 2 * radius_, side = 0.4;
  std::vector<double> heights, pressures;
  double particleSurface = 0.0;
  const auto times = lastTimes(25);
  for (const auto& time : times) {
    const ParticleSystem ps = runner_->particles(time.name, radius_);
    const ParticleSet& fluid = *ps.find("fluid");
    const double surface = surfaceHeight(fluid, radius_);
    particleSurface += surface / static_cast<double>(times.size());
    const auto& p = fluid.real(field::pressure);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      const Vec3& x = fluid.x()[i];
      const double wall = std::min({x.x(), side - x.x(), x.z(), side - x.z(), x.y()});
      if (wall < 3 * spacing || surface - x.y() < 2 * spacing) continue;
      heights.push_back(x.y());
      pressures.push_back(p[i]);
    }
  }
  ASSERT_GE(heights.size(), 50000u);
  // p = c0 + c1 y by least squares.
  const double n = static_cast<double>(heights.size());
  double sy = 0, sp = 0, syy = 0, syp = 0;
  for (std::size_t i = 0; i < heights.size(); ++i) {
    sy += heights[i];
    sp += pressures[i];
    syy += heights[i] * heights[i];
    syp += heights[i] * pressures[i];
  }
  const double c1 = (n * syp - sy * sp) / (n * syy - sy * sy), c0 = (sp - c1 * sy) / n;
  const double freeSurface = -c0 / c1;
  EXPECT_NEAR(-c1 / (kRho0 * kGravity), 1.0, 0.05) << "pressure gradient / (rho0 g)";
  EXPECT_NEAR(freeSurface, particleSurface, radius_) << "level where p vanishes against top particle + r";
  RecordProperty("surfaceAboveTopParticlesOverR", std::to_string((freeSurface - particleSurface) / radius_));

  std::map<long, std::pair<double, double>> layers; // layer -> (sum p, sum rho0 g d)
  for (std::size_t i = 0; i < heights.size(); ++i) {
    auto& layer = layers[std::lround(heights[i] / spacing)];
    layer.first += pressures[i];
    layer.second += kRho0 * kGravity * (freeSurface - heights[i]);
  }
  ASSERT_GE(layers.size(), 18u);
  double worst = 0.0;
  for (const auto& [layer, sums] : layers) {
    EXPECT_NEAR(sums.first / sums.second, 1.0, 0.05) << "layer " << layer << " (y = " << layer * spacing << " m)";
    worst = std::max(worst, std::abs(sums.first / sums.second - 1.0));
  }
  RecordProperty("pressureGradientOverRho0g", std::to_string(-c1 / (kRho0 * kGravity)));
  RecordProperty("worstLayerDeviation", std::to_string(worst));
}

TEST_F(HydrostaticTank, BottomForceEqualsWeight) {
  // Force of the fluid on the floor: the reaction of the one-sided wall pressure term -V_k pi_i gradW_ik
  // (METHOD.md §6.7), summed over the particles below the fluid, averaged over the last 0.5 s.
  double forceSum = 0.0, weightSum = 0.0;
  double lowest = INFINITY, highest = -INFINITY; // of single snapshots: how much the average smooths
  for (const auto& time : lastTimes(25)) {
    double force = 0.0;
    ParticleSystem ps = runner_->particles(time.name, radius_);
    ParticleSet& fluid = *ps.find("fluid");
    ParticleSet& boundary = *ps.find("boundary");
    const CubicKernel kernel(4 * radius_);
    computeBoundaryVolumes(boundary, kernel);
    NeighbourSearch search(4 * radius_);
    search.update({&fluid.x(), &boundary.x()}, {{false, true}, {false, false}});
    const auto& pi = fluid.real(field::pi);
    const auto& volume = boundary.real(kBoundaryVolumeField);
    const double mass = kRho0 * 8 * radius_ * radius_ * radius_;
    for (std::size_t i = 0; i < fluid.size(); ++i)
      for (Index k : search.list(0, 1).of(i)) {
        const std::size_t kk = static_cast<std::size_t>(k);
        const Vec3& xk = boundary.x()[kk];
        // The floor under the fluid; the walls' corner columns carry the side walls' share.
        if (xk.y() > 0.0 || xk.x() < 0.0 || xk.x() > 0.4 || xk.z() < 0.0 || xk.z() > 0.4) continue;
        force += mass * pi[i] * volume[kk] * kernel.grad(fluid.x()[i] - boundary.x()[kk]).y();
      }
    const double weight = static_cast<double>(fluid.size()) * mass * kGravity;
    lowest = std::min(lowest, -force / weight);
    highest = std::max(highest, -force / weight);
    forceSum += force;
    weightSum += weight;
  }
  EXPECT_NEAR(-forceSum / weightSum, 1.0, 0.02) << "floor force / weight";
  RecordProperty("floorForceOverWeight", std::to_string(-forceSum / weightSum));
  RecordProperty("floorForceOverWeightOfOneSnapshot", std::to_string(lowest) + " to " + std::to_string(highest));
}

} // namespace
} // namespace poro::test
