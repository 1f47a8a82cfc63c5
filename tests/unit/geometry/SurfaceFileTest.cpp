// Reading closed surfaces from STL (ASCII, binary), OBJ, OFF and PLY: the same surface in every format samples to
// the same particles; each kind of broken file gets its own message naming the file, what and where.
#include "geometry/SurfaceFile.hpp"
#include "../io/ScratchDirectory.hpp"
#include "TestSurfaces.hpp"
#include "core/Error.hpp"
#include "geometry/ShapeSampling.hpp"
#include "geometry/SurfaceMesh.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <vector>

namespace poro {
namespace {

using test::contains;
using test::ScratchDirectory;

/// The InputError SurfaceFile::read throws for `path`, or "" if it reads.
std::string readError(const std::filesystem::path& path, bool repair = false) {
  try {
    SurfaceFile::read(path.string(), repair);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::vector<Vec3> sampleFile(const std::filesystem::path& path, double r) {
  return sampleInside(SurfaceMesh(SurfaceFile::read(path.string()).mesh), r);
}

TEST(SurfaceFile, FiveFormatsGiveTheSameParticles) {
  ScratchDirectory dir;
  const TriangleMesh torus = test::roundedToFloat(test::torusMesh(Vec3(0.01, 0.02, 0.03), 0.2, 0.08, 40, 20));
  test::writeAsciiStl(dir / "torus.stl", torus);
  test::writeBinaryStl(dir / "torusBinary.stl", torus);
  test::writeObj(dir / "torus.obj", torus);
  test::writeOff(dir / "torus.off", torus);
  test::writePly(dir / "torus.ply", torus);
  const std::vector<Vec3> reference = sampleInside(SurfaceMesh(torus), 0.008);
  ASSERT_GT(reference.size(), 5000u);
  for (const char* name : {"torus.stl", "torusBinary.stl", "torus.obj", "torus.off", "torus.ply"}) {
    const SurfaceFile file = SurfaceFile::read((dir / name).string());
    EXPECT_EQ(file.mesh.triangles.size(), torus.triangles.size()) << name;
    EXPECT_TRUE(file.notes.empty()) << name << ": " << file.notes.front();
    EXPECT_EQ(sampleInside(SurfaceMesh(file.mesh), 0.008), reference) << name;
  }
}

TEST(SurfaceFile, InwardAndInconsistentFacesAreReversedWithANote) {
  ScratchDirectory dir;
  TriangleMesh inward = test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.2));
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  test::writeObj(dir / "inward.obj", inward);
  const SurfaceFile in = SurfaceFile::read((dir / "inward.obj").string());
  ASSERT_EQ(in.notes.size(), 1u);
  EXPECT_TRUE(contains(in.notes[0], "12 faces pointed into the body; reversed them"));
  EXPECT_GT(test::meshVolume(in.mesh), 0.0);

  TriangleMesh mixed = test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.2));
  std::swap(mixed.triangles[3][1], mixed.triangles[3][2]);
  test::writeObj(dir / "mixed.obj", mixed);
  const SurfaceFile m = SurfaceFile::read((dir / "mixed.obj").string());
  ASSERT_FALSE(m.notes.empty());
  EXPECT_TRUE(contains(m.notes[0], "oriented against their neighbours; reversed them"));
  EXPECT_NEAR(test::meshVolume(m.mesh), 0.008, 1e-15);
  EXPECT_EQ(sampleFile(dir / "mixed.obj", 0.01).size(), 1000u);
}

TEST(SurfaceFile, OpenSurface) {
  ScratchDirectory dir;
  TriangleMesh open = test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.2));
  open.triangles.pop_back(); // a triangle of the face z = 0.2 is missing: its three edges are open
  test::writeAsciiStl(dir / "open.stl", open);
  const std::string message = readError(dir / "open.stl");
  EXPECT_TRUE(contains(message, (dir / "open.stl").string() + ": the surface is not closed: 3 open boundary edges "
                                                              "(edges of only one face), e.g. from ("));
  EXPECT_TRUE(contains(message, "0.2)")) << "the edge named lies in the plane z = 0.2";
}

TEST(SurfaceFile, SelfIntersectingSurface) {
  // Two cubes in one file, overlapping in [0.1, 0.2] x [0.1, 0.2] x [0, 0.2].
  ScratchDirectory dir;
  TriangleMesh both = test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.2));
  const TriangleMesh second = test::cubeMesh(Vec3(0.1, 0.1, 0.0), Vec3(0.3, 0.3, 0.2));
  for (const auto& t : second.triangles) both.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  both.vertices.insert(both.vertices.end(), second.vertices.begin(), second.vertices.end());
  test::writeOff(dir / "twoCubes.off", both);
  const std::string message = readError(dir / "twoCubes.off");
  EXPECT_TRUE(contains(message, (dir / "twoCubes.off").string() + ": the surface intersects itself: "));
  EXPECT_TRUE(contains(message, " pairs of faces intersect, e.g. at ("));
}

TEST(SurfaceFile, GarbageFiles) {
  ScratchDirectory dir;
  std::string bytes;
  for (int k = 0; k < 1000; ++k) bytes.push_back(static_cast<char>((k * 7919 + 13) % 256));
  for (const char* name : {"garbage.stl", "garbage.obj", "garbage.off", "garbage.ply"}) {
    test::writeAll(dir / name, bytes);
    std::string format = std::string(name).substr(8);
    for (char& c : format) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_TRUE(contains(readError(dir / name), (dir / name).string() + ": cannot read it as " + format +
                                                    ": the file is damaged, empty or not " + format));
  }
  test::writeAll(dir / "text.stl", "This is not a surface.\n");
  EXPECT_TRUE(contains(readError(dir / "text.stl"), ": holds no faces; expected a closed surface of triangles in STL"));
  test::writeAll(dir / "empty.obj", "# nothing\n");
  EXPECT_TRUE(contains(readError(dir / "empty.obj"), ": cannot read it as OBJ: the file is damaged, empty or not OBJ"));
}

TEST(SurfaceFile, UnknownFormatAndMissingFile) {
  ScratchDirectory dir;
  test::writeAll(dir / "cube.vtk", "");
  EXPECT_TRUE(contains(readError(dir / "cube.vtk"),
                       ": unknown surface format '.vtk'; expected .stl (ASCII or binary), .obj, .off or .ply"));
  EXPECT_TRUE(contains(readError(dir / "missing.stl"), "missing.stl: cannot open file (No such file or directory)"));
}

TEST(SurfaceFile, QuadsNeedRepair) {
  ScratchDirectory dir;
  test::writeAll(dir / "quads.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                                    "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n");
  EXPECT_TRUE(contains(readError(dir / "quads.obj"),
                       ": 6 of 6 faces are not triangles, e.g. face 1 with 4 corners at (0, 0, 0), ...; export the "
                       "surface triangulated, or set repair: true on the region to triangulate them"));
  const SurfaceFile repaired = SurfaceFile::read((dir / "quads.obj").string(), true);
  EXPECT_EQ(repaired.mesh.triangles.size(), 12u);
  ASSERT_EQ(repaired.notes.size(), 1u);
  EXPECT_TRUE(contains(repaired.notes[0], "triangulated 6 faces with more than three corners (repair: true)"));
  EXPECT_NEAR(test::meshVolume(repaired.mesh), 1.0, 1e-14);
}

TEST(SurfaceFile, DegenerateAndNonManifoldSurfaces) {
  ScratchDirectory dir;
  // A cube whose face x = 0 is split through its centre into four triangles, one of them given as two
  // triangles meeting at a point on its edge: a face with collinear corners.
  TriangleMesh sliver = test::cubeMesh(Vec3::Zero(), Vec3::Constant(1.0));
  sliver.vertices.emplace_back(0.0, 0.5, 0.0); // on the edge from corner 0 to corner 2
  sliver.triangles[0] = {0, 4, 6};
  sliver.triangles[1] = {0, 6, 8};
  sliver.triangles.push_back({8, 6, 2});
  sliver.triangles.push_back({0, 8, 2}); // collinear: 0, 8 and 2 lie on one edge
  test::writeObj(dir / "sliver.obj", sliver);
  EXPECT_TRUE(contains(readError(dir / "sliver.obj"), ": 1 degenerate face (corners that coincide or lie on one "
                                                      "line), e.g. face 14 at (0, 0, 0)"));
  // Two cubes sharing an edge: four faces on each of its two triangle edges.
  TriangleMesh touching = test::cubeMesh(Vec3::Zero(), Vec3::Constant(1.0));
  const TriangleMesh other = test::cubeMesh(Vec3(1.0, 1.0, 0.0), Vec3(2.0, 2.0, 1.0));
  for (const auto& t : other.triangles) touching.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  touching.vertices.insert(touching.vertices.end(), other.vertices.begin(), other.vertices.end());
  test::writeAsciiStl(dir / "touching.stl", touching);
  EXPECT_TRUE(contains(readError(dir / "touching.stl"), ": the surface is not a manifold: 1 edge shared by more "
                                                        "than two faces, e.g. from (1, 1, 0) to (1, 1, 1)"));
}

} // namespace
} // namespace poro
