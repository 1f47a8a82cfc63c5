/// Google Benchmark of surface sampling (sampleParticles, `shape: surface`): a closed torus of 3072 triangles
/// (R = 0.3 m, tube radius 0.12 m, enclosing 0.0845 m^3) sampled at r = 2.2 mm into about one million particles.
///   - ReadSurface: reading and checking it from a binary STL (SurfaceFile::read: closedness, self-intersections,
///     orientation);
///   - SampleInside: building its AABB tree (SurfaceMesh) and filling it (sampleInside), the work of a fluid or
///     porous surface region;
///   - SampleWallBody: a container of two layers outside it (sampleWallBody), the work of a boundary region.
/// The OpenMP thread count is the first argument; items_per_second counts particles sampled. Wall time is
/// reported (UseRealTime), since the work runs on OpenMP threads.

#include "core/Parallel.hpp"
#include "geometry/ShapeSampling.hpp"
#include "geometry/SurfaceFile.hpp"
#include "geometry/SurfaceMesh.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

using namespace poro;

namespace {

constexpr double kRadius = 0.0022; ///< particle radius r [m]: (2r)^3 = 8.5e-8 m^3, a million particles in the torus

/// The torus of major radius 0.3 m and tube radius 0.12 m about the z axis, 64 x 24 quads split into triangles.
TriangleMesh torus() {
  const double pi = 3.14159265358979323846, major = 0.3, tube = 0.12;
  const int nMajor = 64, nMinor = 24;
  TriangleMesh m;
  for (int i = 0; i < nMajor; ++i)
    for (int j = 0; j < nMinor; ++j) {
      const double phi = 2.0 * pi * i / nMajor, theta = 2.0 * pi * j / nMinor;
      const double rho = major + tube * std::cos(theta);
      m.vertices.emplace_back(rho * std::cos(phi), rho * std::sin(phi), tube * std::sin(theta));
    }
  const auto index = [&](int i, int j) { return static_cast<std::size_t>((i % nMajor) * nMinor + j % nMinor); };
  for (int i = 0; i < nMajor; ++i)
    for (int j = 0; j < nMinor; ++j) {
      m.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      m.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  return m;
}

/// The torus as a binary STL in the temp directory (written once).
std::string torusFile() {
  static const std::string path = [] {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "porosph-bench-torus.stl";
    const TriangleMesh m = torus();
    std::ofstream out(file, std::ios::binary);
    const char header[80] = "binary STL of the PoroSPH sampling benchmark";
    out.write(header, sizeof header);
    const auto count = static_cast<std::uint32_t>(m.triangles.size());
    out.write(reinterpret_cast<const char*>(&count), 4);
    for (const auto& t : m.triangles) {
      float values[12] = {}; // normal (left 0: readers recompute it), then the three corners
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d) values[3 + 3 * k + d] = static_cast<float>(m.vertices[t[std::size_t(k)]][d]);
      out.write(reinterpret_cast<const char*>(values), sizeof values);
      out.write("\0\0", 2);
    }
    return file.string();
  }();
  return path;
}

void BM_ReadSurface(benchmark::State& state) {
  const std::string path = torusFile();
  std::size_t triangles = 0;
  for (auto _ : state) {
    const SurfaceFile file = SurfaceFile::read(path);
    triangles = file.mesh.triangles.size();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

void BM_SampleInside(benchmark::State& state) {
  parallel::setThreads(static_cast<int>(state.range(0)));
  const TriangleMesh mesh = torus();
  std::size_t particles = 0;
  for (auto _ : state) {
    const SurfaceMesh surface(mesh);
    particles = sampleInside(surface, kRadius).size();
    benchmark::DoNotOptimize(particles);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * particles));
  state.counters["particles"] = static_cast<double>(particles);
}

void BM_SampleWallBody(benchmark::State& state) {
  parallel::setThreads(static_cast<int>(state.range(0)));
  const SurfaceMesh surface(torus());
  std::size_t particles = 0;
  for (auto _ : state) {
    particles = sampleWallBody(surface, kRadius, 2, WallSide::Outside).size();
    benchmark::DoNotOptimize(particles);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * particles));
  state.counters["particles"] = static_cast<double>(particles);
}

} // namespace

BENCHMARK(BM_ReadSurface)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SampleInside)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SampleWallBody)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
