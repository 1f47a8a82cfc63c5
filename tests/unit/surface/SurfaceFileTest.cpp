// A surface written as .vtp reads back as it was (to Float32), so tests can measure what fluidSurface wrote.

#include "surface/SurfaceFile.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace poro {
namespace {

namespace fs = std::filesystem;

TEST(SurfaceFile, WrittenSurfaceReadsBack) {
  const fs::path dir = fs::temp_directory_path() / ("porosph-surfaceFile-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  TriangleSurface tetra;
  tetra.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  tetra.fields.push_back({"v", 3, std::vector<double>(12, 0.5)});
  tetra.fields.push_back({"saturation", 1, {0.0, 0.25, 0.5, 1.0}});
  writeSurface(tetra, dir / "tetra.vtp");
  const TriangleSurface read = readSurface(dir / "tetra.vtp");
  EXPECT_EQ(read.points, tetra.points);
  EXPECT_EQ(read.triangles, tetra.triangles);
  ASSERT_NE(read.field("saturation"), nullptr);
  EXPECT_EQ(read.field("saturation")->values, tetra.fields[1].values);
  ASSERT_NE(read.field("v"), nullptr);
  EXPECT_EQ(read.field("v")->components, 3);
  EXPECT_TRUE(read.defects().none());
  EXPECT_DOUBLE_EQ(read.enclosedVolume(), 1.0 / 6.0);

  std::ofstream(dir / "garbage.vtp") << "not a VTK file";
  EXPECT_THROW(readSurface(dir / "garbage.vtp"), InputError);
  EXPECT_THROW(readSurface(dir / "missing.vtp"), InputError);
  fs::remove_all(dir);
}

} // namespace
} // namespace poro
