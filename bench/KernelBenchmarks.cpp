/// Google Benchmark kernels of one time step at ~51k fluid particles (ARCHITECTURE.md "bench/"):
///   - NeighbourSearch::update for the fluid->fluid list, the fluid->boundary list and both (what
///     Solver::step asks for);
///   - computeDensities, PressureSolver::predictDensities and PressureSolver::solve with a fixed number of
///     Jacobi sweeps (minIterations = maxIterations), on fields prepared by one Solver::step;
///   - the 3x3 outer-product sum of the pair loops (viscosity, drag and elastic blocks): Eigen's expression
///     against addOuter (core/Types.hpp), over 40 pairs as one particle has;
///   - the rotation extraction of elastic bodies, warm-started as a step calls it (single thread).
/// Every benchmark takes the OpenMP thread count as its first argument. items_per_second counts fluid
/// particles processed (for the pressure solve: fluid particles x sweeps). Wall time is what is reported
/// (UseRealTime), since the work runs on OpenMP threads.
///
/// Scene: a dam-break-like fluid block 0.4 x 0.4 x 0.32 m at r = 0.005 m (40 x 40 x 32 = 51,200 particles,
/// each coordinate jittered deterministically by up to +-0.1 r, then Morton-sorted as the Solver does) in the
/// corner of a closed 1.2 x 0.6 x 0.32 m tank of two wall layers (the damBreak tutorial's tank, deeper).

#include "core/Parallel.hpp"
#include "geometry/LatticeSampling.hpp"
#include "physics/Densities.hpp"
#include "physics/FieldNames.hpp"
#include "physics/PressureSolver.hpp"
#include "physics/RotationExtraction.hpp"
#include "physics/Solver.hpp"

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

using namespace poro;

namespace {

constexpr double kRadius = 0.005;  ///< particle radius r [m]
constexpr double kDeltaT = 0.0005; ///< step size of the preparing step [s] (the damBreak tutorial's deltaT)
constexpr double kJitter = 0.1;    ///< jitter amplitude per coordinate [r]

/// SplitMix64: a fixed, platform-independent hash, so the jitter is the same on every machine.
std::uint64_t splitMix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// Uniform in [-1, 1) from (particle, axis).
double unitNoise(std::size_t i, int axis) {
  const std::uint64_t h = splitMix64(3 * static_cast<std::uint64_t>(i) + static_cast<std::uint64_t>(axis));
  return 2.0 * static_cast<double>(h >> 11) * 0x1.0p-53 - 1.0;
}

std::vector<Vec3> fluidPoints() {
  std::vector<Vec3> points = sampleBox(Vec3(0.0, 0.0, 0.0), Vec3(0.4, 0.4, 0.32), kRadius);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int d = 0; d < 3; ++d) points[i][d] += kJitter * kRadius * unitNoise(i, d);
  return points;
}

std::vector<Vec3> boundaryPoints() {
  // Inner faces 0.1 r off the fluid, as in tutorials/fluid/damBreak/system/particleDict.
  return sampleContainer(Vec3(-0.0005, -0.0005, -0.0005), Vec3(1.2005, 0.6005, 0.3205), kRadius, 2,
                         FaceFlags{false, false, false, false, false, false});
}

/// The scene as a ParticleSystem: "fluid" (SetKind::Fluid, object 0) and "boundary" (SetKind::Boundary,
/// object 1), with persistent ids, as sampleParticles writes them.
ParticleSystem makeScene() {
  ParticleSystem particles(kRadius);
  long long nextId = 0;
  auto fill = [&](ParticleSet& set, const std::vector<Vec3>& points, long long object) {
    set.resize(points.size());
    auto& ids = set.integer(field::id);
    auto& objects = set.integer(field::objectId);
    for (std::size_t k = 0; k < points.size(); ++k) {
      set.x()[k] = points[k];
      ids[k] = nextId++;
      objects[k] = object;
    }
  };
  fill(particles.add("fluid", SetKind::Fluid), fluidPoints(), 0);
  fill(particles.add("boundary", SetKind::Boundary), boundaryPoints(), 1);
  return particles;
}

/// Wall time in ms, and a "min" statistic beside mean, median and stddev when repetitions are asked for
/// (--benchmark_repetitions=N): on a shared machine the fastest repetition is the one least disturbed by
/// other processes. The statistic is taken per column, so in a min row the rate counters are minima too.
void timing(benchmark::internal::Benchmark* b) {
  b->UseRealTime()->Unit(benchmark::kMillisecond)->ComputeStatistics("min", [](const std::vector<double>& v) {
    return *std::min_element(v.begin(), v.end());
  });
}

/// One benchmark per OpenMP thread count.
void threadCounts(benchmark::internal::Benchmark* b) {
  b->ArgName("threads")->Arg(1)->Arg(2);
  timing(b);
}

// ---------------------------------------------------------------------------------------------------------
// Neighbour search

/// Positions of both sets in Morton order (the Solver sorts walls once and fluid every sortInterval steps), of the
/// cells of its search with the default skin.
struct SearchScene {
  std::vector<Vec3> fluid, boundary;
  SearchScene() {
    const NeighbourSearch search(4.0 * kRadius, 0.4 * kRadius);
    auto sorted = [&](const std::vector<Vec3>& x) {
      const std::vector<Index> order = search.mortonOrder(x);
      std::vector<Vec3> out(x.size());
      for (std::size_t i = 0; i < x.size(); ++i) out[i] = x[static_cast<std::size_t>(order[i])];
      return out;
    };
    fluid = sorted(fluidPoints());
    boundary = sorted(boundaryPoints());
  }
};

const SearchScene& searchScene() {
  static const SearchScene scene;
  return scene;
}

/// Times NeighbourSearch::update with sets {0: fluid, 1: boundary} and the requested lists.
void runSearch(benchmark::State& state, bool fluidFluid, bool fluidBoundary) {
  parallel::setThreads(static_cast<int>(state.range(0)));
  const SearchScene& scene = searchScene();
  const std::vector<const std::vector<Vec3>*> positions{&scene.fluid, &scene.boundary};
  const std::vector<std::vector<bool>> wanted{{fluidFluid, fluidBoundary}, {false, false}};
  NeighbourSearch search(4.0 * kRadius);
  for (auto _ : state) {
    search.update(positions, wanted);
    benchmark::ClobberMemory();
  }
  const double n = static_cast<double>(scene.fluid.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene.fluid.size()));
  state.counters["fluid"] = n;
  state.counters["boundary"] = static_cast<double>(scene.boundary.size());
  if (fluidFluid) state.counters["ffPairs/particle"] = static_cast<double>(search.list(0, 0).totalPairs()) / n;
  if (fluidBoundary) state.counters["fbPairs/particle"] = static_cast<double>(search.list(0, 1).totalPairs()) / n;
}

void BM_SearchFluidFluid(benchmark::State& state) { runSearch(state, true, false); }
void BM_SearchFluidBoundary(benchmark::State& state) { runSearch(state, false, true); }
/// Both lists in one update, as Solver::searchNeighbours requests them.
void BM_SearchStep(benchmark::State& state) { runSearch(state, true, true); }

/// The default skin (0.1 H) in a step of particles at rest: `gridSearch` 1 runs the grid search at 1.1 H (its lists in
/// ascending order) and the filtering to H in every update, 0 the filtering alone, as in the steps between.
void BM_SearchSkin(benchmark::State& state) {
  parallel::setThreads(static_cast<int>(state.range(0)));
  const bool gridSearch = state.range(1) != 0;
  const SearchScene& scene = searchScene();
  const std::vector<const std::vector<Vec3>*> positions{&scene.fluid, &scene.boundary};
  const std::vector<std::vector<bool>> wanted{{true, true}, {false, false}};
  NeighbourSearch search(4.0 * kRadius, 0.4 * kRadius);
  search.update(positions, wanted);
  for (auto _ : state) {
    if (gridSearch) search.invalidate();
    search.update(positions, wanted);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene.fluid.size()));
}

BENCHMARK(BM_SearchFluidFluid)->Apply(threadCounts);
BENCHMARK(BM_SearchFluidBoundary)->Apply(threadCounts);
BENCHMARK(BM_SearchStep)->Apply(threadCounts);
BENCHMARK(BM_SearchSkin)->ArgNames({"threads", "gridSearch"})->ArgsProduct({{1, 2}, {0, 1}})->Apply(timing);

// ---------------------------------------------------------------------------------------------------------
// Densities and the pressure solve

/// A Solver that has taken one step (so pi, velocities and every registered field hold step data), plus
/// the public pieces of a step rebuilt on its particles: a neighbour search, the pair gradients and a
/// StepContext, with densities and predicted densities computed once.
struct PressureScene {
  std::unique_ptr<Solver> solver;
  NeighbourSearch search{4.0 * kRadius};
  PairGradients gradients;
  FluidProperties fluid;
  CubicKernel kernel{4.0 * kRadius};
  std::unique_ptr<StepContext> ctx;
  std::vector<Vec3> v0;  ///< fluid velocities before a solve (solve adds dt a^p to them)
  std::vector<Real> pi0; ///< pi before a solve (the warm start)
  std::size_t fluidCount = 0;

  PressureScene() {
    TimeControl control;
    control.endTime = 1.0;
    control.deltaT = kDeltaT;
    control.writeInterval = 1.0;
    solver = std::make_unique<Solver>(makeScene(), fluid, std::vector<PorousMaterial>{}, SolverSettings{}, control,
                                      RunState{});
    solver->step(kDeltaT);

    ParticleSystem& ps = solver->particles();
    ctx = std::make_unique<StepContext>(
        StepContext{ps, search, gradients, kernel, fluid, kDeltaT, {0}, {1}, {nullptr, nullptr}, {}});
    search.update({&ps[0].x(), &ps[1].x()}, {{true, true}, {false, false}});
    computeDensities(*ctx, gradients);
    PressureSolver(PressureSettings{}).predictDensities(*ctx);
    fluidCount = ps[0].size();
    v0 = ps[0].v();
    pi0 = ps[0].real(field::pi);
  }

  void restore() {
    solver->particles()[0].v() = v0;
    solver->particles()[0].real(field::pi) = pi0;
  }
};

PressureScene& pressureScene() {
  static PressureScene scene;
  return scene;
}

void BM_Densities(benchmark::State& state) {
  parallel::setThreads(static_cast<int>(state.range(0)));
  PressureScene& scene = pressureScene();
  for (auto _ : state) {
    computeDensities(*scene.ctx, scene.gradients);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene.fluidCount));
  state.counters["fluid"] = static_cast<double>(scene.fluidCount);
}

void BM_PredictDensities(benchmark::State& state) {
  parallel::setThreads(static_cast<int>(state.range(0)));
  PressureScene& scene = pressureScene();
  const PressureSolver pressure(PressureSettings{});
  for (auto _ : state) {
    pressure.predictDensities(*scene.ctx);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene.fluidCount));
}

/// PressureSolver::solve with exactly `sweeps` Jacobi sweeps (second argument). One sweep is one
/// pressure-acceleration pass and one residual/update pass over the fluid->fluid list; a solve adds a
/// warm start and a final acceleration and velocity update. time(10) - time(1) over 9 is the marginal
/// cost of a sweep; ms/sweep below is simply time / sweeps.
void BM_PressureSolve(benchmark::State& state) {
  parallel::setThreads(static_cast<int>(state.range(0)));
  const int sweeps = static_cast<int>(state.range(1));
  PressureScene& scene = pressureScene();
  PressureSettings settings;
  settings.minIterations = sweeps;
  settings.maxIterations = sweeps;
  const PressureSolver pressure(settings);
  PressureStats stats;
  for (auto _ : state) {
    state.PauseTiming();
    scene.restore(); // every solve starts from the same v and warm start
    state.ResumeTiming();
    stats = pressure.solve(*scene.ctx);
    benchmark::ClobberMemory();
  }
  scene.restore();
  const auto swept = state.iterations() * static_cast<std::int64_t>(stats.iterations);
  state.SetItemsProcessed(swept * static_cast<std::int64_t>(scene.fluidCount));
  state.counters["sweeps"] = stats.iterations;
  // Rate of sweeps, inverted: seconds per sweep (printed with an SI prefix, e.g. 4.2m = 4.2 ms).
  state.counters["s/sweep"] =
      benchmark::Counter(static_cast<double>(swept), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["error%"] = stats.meanError;
}

/// sum_p c_p a_p b_p^T over 40 pairs, the shape of a diagonal block or a deformation gradient.
struct OuterProductPairs {
  std::vector<Vec3> a, b;
  std::vector<double> c;
  OuterProductPairs() {
    for (std::uint64_t p = 0; p < 40; ++p) {
      const auto u = [&](std::uint64_t k) { return static_cast<double>(splitMix64(6 * p + k) >> 11) * 0x1.0p-53; };
      a.emplace_back(u(0), u(1), u(2));
      b.emplace_back(u(3), u(4), u(5));
      c.push_back(u(0) - 0.5);
    }
  }
};

void BM_OuterProductSum(benchmark::State& state) {
  const OuterProductPairs pairs;
  const bool eigenExpression = state.range(0) == 0;
  for (auto _ : state) {
    Mat3 m = Mat3::Zero();
    for (std::size_t p = 0; p < pairs.a.size(); ++p) {
      if (eigenExpression)
        m += pairs.c[p] * (pairs.a[p] * pairs.b[p].transpose());
      else
        addOuter(m, pairs.c[p] * pairs.a[p], pairs.b[p]);
    }
    benchmark::DoNotOptimize(m);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.a.size()));
  state.SetLabel(eigenExpression ? "m += c * (a * b.transpose())" : "addOuter(m, c * a, b)");
}

/// F = Q (I + eps) for 1024 particles, Q a random rotation and eps a random symmetric strain of 1e-3, each
/// warm-started from Q turned by 1e-4 rad: what Elasticity::prepareBody asks of the extraction in a slow flow.
struct RotationCalls {
  std::vector<Mat3> f, previous;
  RotationCalls() {
    std::uint64_t k = 0;
    const auto u = [&]() { return static_cast<double>(splitMix64(k++) >> 11) * 0x1.0p-53 - 0.5; };
    const auto axis = [&]() { return Vec3(u(), u(), u()).normalized(); };
    for (int p = 0; p < 1024; ++p) {
      const Mat3 q = Eigen::AngleAxisd(6.0 * u(), axis()).toRotationMatrix();
      Mat3 eps;
      eps << u(), u(), u(), u(), u(), u(), u(), u(), u();
      f.push_back(q * (Mat3::Identity() + 1e-3 * (eps + eps.transpose())));
      previous.push_back(Eigen::AngleAxisd(1e-4, axis()).toRotationMatrix() * q);
    }
  }
};

void BM_RotationExtraction(benchmark::State& state) {
  const RotationCalls calls;
  for (auto _ : state)
    for (std::size_t p = 0; p < calls.f.size(); ++p)
      benchmark::DoNotOptimize(extractRotation(calls.f[p], calls.previous[p]));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(calls.f.size()));
}

BENCHMARK(BM_OuterProductSum)->ArgName("addOuter")->Arg(0)->Arg(1);
BENCHMARK(BM_RotationExtraction);
BENCHMARK(BM_Densities)->Apply(threadCounts);
BENCHMARK(BM_PredictDensities)->Apply(threadCounts);
BENCHMARK(BM_PressureSolve)->ArgNames({"threads", "sweeps"})->ArgsProduct({{1, 2}, {1, 10}})->Apply(timing);

} // namespace
