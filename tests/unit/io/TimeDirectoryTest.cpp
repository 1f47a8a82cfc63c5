// TimeWriter keeps case.pvd in step with the time directories it writes (io/TimeDirectory.hpp).

#include "io/TimeDirectory.hpp"

#include "physics/FieldNames.hpp"
#include "ScratchDirectory.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

TEST(RigidBodyRows, TheQuaternionKeepsTheSignOfTheRowBefore) {
  // A body turned 230 then 250 degrees about z: the matrix-to-quaternion conversion gives w < 0 at 230 and w > 0 at
  // 250, a jump in every column of a plot though q and -q are one rotation. The row after keeps the sign nearest the
  // row before, also when it is appended by a later run (a restart reads the row from the file).
  ScratchDirectory dir;
  RunState state;
  state.rigidBodies.push_back({});
  state.rigidBodies[0].name = "box";
  const auto quaternionAt = [&](double time, double degrees) {
    state.time = time;
    state.rigidBodies[0].rotation = Eigen::AngleAxisd(degrees * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
    appendRigidBodyRows(dir.path(), state);
    const std::string text = test::readAll(dir / "postProcessing/rigidBodies/box.csv");
    const std::string last = text.substr(text.rfind('\n', text.size() - 2) + 1);
    double v[8];
    const char* at = last.c_str();
    for (double& value : v) {
      char* end = nullptr;
      value = std::strtod(at, &end);
      at = end + 1;
    }
    return Eigen::Vector4d(v[4], v[5], v[6], v[7]);
  };
  const Eigen::Vector4d before = quaternionAt(0.1, 230.0);
  const Eigen::Vector4d after = quaternionAt(0.2, 250.0);
  EXPECT_GT(before.dot(after), 0.9) << before.transpose() << " then " << after.transpose();
  EXPECT_NEAR(std::abs(after[0]), std::abs(std::cos(125.0 * M_PI / 180.0)), 1e-9); // |w| = |cos(theta / 2)|
}

} // namespace
} // namespace poro
