// TimeWriter keeps case.pvd in step with the time directories it writes (io/TimeDirectory.hpp).

#include "io/TimeDirectory.hpp"

#include "physics/FieldNames.hpp"
#include "ScratchDirectory.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace poro {
namespace {

using test::ScratchDirectory;

ParticleSystem twoParticles() {
  ParticleSystem ps(0.01);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.resize(2);
  fluid.x()[1] = Vec3(0.02, 0, 0);
  fluid.integer(field::id) = {0, 1};
  return ps;
}

std::vector<std::string> filesIn(const std::filesystem::path& pvd) {
  std::vector<std::string> files;
  const PvdSeries series = PvdSeries::read(pvd);
  for (const auto& entry : series.entries()) files.push_back(entry.file);
  return files;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// What fluidSurface does: a surface file in the time directory and its entry in case.pvd.
void addSurface(const ScratchDirectory& dir, double time, const std::string& name) {
  test::writeAll(dir / (name + "/" + kFluidSurfaceFile), "surface");
  PvdSeries series = PvdSeries::read(dir / "case.pvd");
  series.add(time, "fluidSurface", name + "/" + kFluidSurfaceFile);
  series.write(dir / "case.pvd");
}

TEST(TimeDirectory, ARewrittenTimeDirectoryDropsTheEntriesOfTheFilesItLost) {
  ScratchDirectory dir;
  const ParticleSystem ps = twoParticles();
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  {
    TimeWriter writer(dir.path(), OutputSettings{}, "0");
    writer.write(ps, RunState{0.5, 10, 1e-3});
  }
  addSurface(dir, 0.0, "0");
  addSurface(dir, 0.5, "0.5");

  // A restart from 0.5 writes later times: the surfaces of 0 and 0.5 are still there and stay listed.
  {
    TimeWriter writer(dir.path(), OutputSettings{}, "0.5");
    writer.write(ps, RunState{0.6, 11, 1e-3});
  }
  auto files = filesIn(dir / "case.pvd");
  EXPECT_TRUE(has(files, "0/fluidSurface.vtp"));
  EXPECT_TRUE(has(files, "0.5/fluidSurface.vtp"));

  // A run again from 0 rewrites 0/ at step 0: its surface is gone, and so must be its entry.
  {
    TimeWriter writer(dir.path(), OutputSettings{}, "0");
    writer.write(ps, RunState{0.0, 0, 1e-3});
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "0/fluidSurface.vtp"));
  files = filesIn(dir / "case.pvd");
  EXPECT_FALSE(has(files, "0/fluidSurface.vtp"));
  EXPECT_TRUE(has(files, "0/fluid.vtp"));
}

TEST(TimeDirectory, ASeriesRebuiltFromTheTimeDirectoriesListsParticlesAndSurfaces) {
  // What fluidSurface writes when case.pvd is gone: what poroSph had listed, and the surfaces already made.
  ScratchDirectory dir;
  const ParticleSystem ps = twoParticles();
  TimeWriter::writeAll(dir.path(), ps, RunState{}, true);
  {
    TimeWriter writer(dir.path(), OutputSettings{}, "0");
    writer.write(ps, RunState{0.5, 10, 1e-3});
  }
  test::writeAll(dir / (std::string("0.5/") + kFluidSurfaceFile), "surface");
  std::filesystem::create_directories(dir / "0.7"); // no uniform/time: not a complete time directory
  test::writeAll(dir / "0.7/fluid.vtp", "partial");
  const std::string written = test::readAll(dir / "case.pvd");
  std::filesystem::remove(dir / "case.pvd");

  const PvdSeries series = seriesOfTimeDirectories(dir.path());
  std::vector<std::string> files;
  for (const auto& entry : series.entries()) files.push_back(entry.file);
  EXPECT_EQ(files, (std::vector<std::string>{"0/fluid.vtp", "0.5/fluid.vtp", "0.5/fluidSurface.vtp"}));
  EXPECT_EQ(series.entries()[1].time, 0.5);
  EXPECT_EQ(series.entries()[2].part, "fluidSurface");
  // Without the surface, the same file as poroSph wrote.
  PvdSeries particlesOnly;
  for (const auto& entry : series.entries())
    if (entry.part != "fluidSurface") particlesOnly.add(entry.time, entry.part, entry.file);
  particlesOnly.write(dir / "case.pvd");
  EXPECT_EQ(test::readAll(dir / "case.pvd"), written);
}

} // namespace
} // namespace poro
