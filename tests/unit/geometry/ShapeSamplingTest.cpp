// Lattice sampling of closed surfaces (METHOD.md §2.3): the lattice of the bounding box, points strictly inside
// by row parity; wall bodies of `layers` layers on either side. References are exact and independent of the
// sampler's parity rule: analytic inside tests, the winding number, brute force over the same lattice.
#include "geometry/ShapeSampling.hpp"
#include "TestSurfaces.hpp"
#include "core/Parallel.hpp"
#include "geometry/LatticeSampling.hpp"
#include "geometry/Sphere.hpp"
#include "geometry/SurfaceMesh.hpp"
#include "geometry/SurfaceTransform.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

namespace poro {
namespace {

using test::kPi;

/// The lattice points `keep` accepts, in lattice order: the brute-force reference of the row samplers.
std::vector<Vec3> bruteForce(const BoxLattice& lattice, const std::function<bool(const Vec3&)>& keep) {
  std::vector<Vec3> out;
  for (long long k = lattice.first; k < lattice.first + lattice.count[2]; ++k)
    for (long long j = lattice.first; j < lattice.first + lattice.count[1]; ++j)
      for (long long i = lattice.first; i < lattice.first + lattice.count[0]; ++i) {
        const Vec3 p(lattice.coordinate(0, i), lattice.coordinate(1, j), lattice.coordinate(2, k));
        if (keep(p)) out.push_back(p);
      }
  return out;
}

/// Count within `tolerance` (relative) of volume / (2r)^3, the count a lattice of spacing 2r gives a body.
void expectCountNearVolume(std::size_t count, double volume, double r, double tolerance) {
  const double expected = volume / std::pow(2.0 * r, 3);
  EXPECT_NEAR(static_cast<double>(count) / expected, 1.0, tolerance)
      << count << " particles for volume / (2r)^3 = " << expected;
  std::cout << "[          ] " << count << " particles, volume / (2r)^3 = " << expected << " ("
            << 100.0 * (static_cast<double>(count) / expected - 1.0) << " %)\n";
}

/// The tolerance: a body a few tens of spacings across samples to within 3 % of its volume.
constexpr double kCountTolerance = 0.03;

TEST(SampleInside, CubeMeshEqualsTheBoxLattice) {
  // Edges a multiple of 2r: every point of sampleBox lies r inside the faces. Rows with y = z run exactly
  // through the diagonals splitting the faces x = min and x = max, and must count one crossing each.
  const Vec3 min(-0.1, 0.0, 0.0), max(0.1, 0.2, 0.2);
  const SurfaceMesh cube(test::cubeMesh(min, max));
  const std::vector<Vec3> points = sampleInside(cube, 0.01);
  EXPECT_EQ(points, sampleBox(min, max, 0.01));
  expectCountNearVolume(points.size(), 0.008, 0.01, 1e-12);
}

TEST(SampleInside, PointsOnTheSurfaceAreNotInside) {
  // An edge of 2.5 spacings: sampleBox places its last layer on the faces x, y, z = max; strictly inside are 2^3.
  const Vec3 min(0.0, 0.0, 0.0), max(0.05, 0.05, 0.05);
  const std::vector<Vec3> points = sampleInside(SurfaceMesh(test::cubeMesh(min, max)), 0.01);
  ASSERT_EQ(sampleBox(min, max, 0.01).size(), 27u);
  ASSERT_EQ(points.size(), 8u);
  for (const Vec3& p : points)
    for (int d = 0; d < 3; ++d) EXPECT_LT(p[d], 0.04);
}

TEST(SampleInside, OctahedronWithRowsThroughItsVerticesAndEdges) {
  // Dyadic numbers, exact in floating point: rows at 1/8 + k/8 pass exactly through the vertices at y, z = 1/2
  // and along the edges in the planes y = 1/2 and z = 1/2. No lattice point lies on the surface (|x - c|_1 is a
  // multiple of 1/8, h = 7/16), so the exact answer is |x - c|_1 < h: 63 points.
  const Vec3 c(0.5, 0.5, 0.5);
  const double h = 7.0 / 16.0, r = 1.0 / 16.0;
  const SurfaceMesh octahedron(test::octahedronMesh(c, h));
  const std::vector<Vec3> points = sampleInside(octahedron, r);
  const BoxLattice lattice = boxLattice(octahedron.boxMin(), octahedron.boxMax(), r);
  EXPECT_EQ(points, bruteForce(lattice, [&](const Vec3& p) { return (p - c).lpNorm<1>() < h; }));
  EXPECT_EQ(points.size(), 63u);
}

TEST(SampleInside, SphereIsAnalyticAndWithinThreePercent) {
  const Vec3 c(0.3, -0.2, 0.1);
  const double radius = 0.15, r = 0.005; // 15 spacings in radius
  const Sphere sphere(c, radius);
  const std::vector<Vec3> points = sampleInside(sphere, r);
  const BoxLattice lattice = boxLattice(sphere.boxMin(), sphere.boxMax(), r);
  EXPECT_EQ(points, bruteForce(lattice, [&](const Vec3& p) { return (p - c).norm() < radius; }));
  expectCountNearVolume(points.size(), 4.0 / 3.0 * kPi * radius * radius * radius, r, kCountTolerance);
}

TEST(SampleInside, SphereMeshIsInsideAndWithinThreePercent) {
  const Vec3 c(0.3, -0.2, 0.1);
  const double radius = 0.15, r = 0.005;
  const TriangleMesh mesh = test::icosphereMesh(c, radius, 3); // 1280 faces, inscribed in the sphere
  const SurfaceMesh sphere(mesh);
  const std::vector<Vec3> points = sampleInside(sphere, r);
  for (const Vec3& p : points) ASSERT_LT((p - c).norm(), radius) << p.transpose();
  // Exactly the lattice points inside every face plane (the mesh is convex; none lies within round-off of a face).
  const BoxLattice lattice = boxLattice(sphere.boxMin(), sphere.boxMax(), r);
  EXPECT_EQ(points, bruteForce(lattice, [&](const Vec3& p) { return test::insideConvex(mesh, p); }));
  expectCountNearVolume(points.size(), test::meshVolume(mesh), r, kCountTolerance);
  expectCountNearVolume(points.size(), 4.0 / 3.0 * kPi * radius * radius * radius, r, kCountTolerance);
}

TEST(SampleInside, TorusIsInsideAndWithinThreePercent) {
  const double R = 0.2, a = 0.08, r = 0.008; // tube radius 5 spacings
  const TriangleMesh mesh = test::torusMesh(Vec3(0.1, 0.2, -0.3), R, a, 48, 24);
  const SurfaceMesh torus(mesh);
  const std::vector<Vec3> points = sampleInside(torus, r);
  for (const Vec3& p : points) ASSERT_GT(test::windingNumber(mesh, p), 0.5) << p.transpose();
  expectCountNearVolume(points.size(), test::meshVolume(mesh), r, kCountTolerance);
  expectCountNearVolume(points.size(), 2.0 * kPi * kPi * R * a * a, r, kCountTolerance);
}

TEST(SampleInside, SameForOneAndTwoThreads) {
  const SurfaceMesh torus(test::torusMesh(Vec3::Zero(), 0.2, 0.08, 48, 24));
  const int threads = parallel::threads();
  parallel::setThreads(1);
  const std::vector<Vec3> serial = sampleInside(torus, 0.003);
  const std::vector<Vec3> serialWall = sampleWallBody(torus, 0.003, 2, WallSide::Outside);
  parallel::setThreads(2);
  const std::vector<Vec3> parallel = sampleInside(torus, 0.003);
  const std::vector<Vec3> parallelWall = sampleWallBody(torus, 0.003, 2, WallSide::Outside);
  parallel::setThreads(threads);
  ASSERT_GT(serial.size(), 100000u);
  EXPECT_EQ(serial, parallel);
  EXPECT_EQ(serialWall, parallelWall);
}

TEST(SampleInside, TransformedCubeLandsWhereTheTransformSays) {
  // Scale [2, 1, 1], then 90 degrees about z, then translate: [0, 0.1]^3 -> [0, 0.2] x [0, 0.1] x [0, 0.1]
  // -> [-0.1, 0] x [0, 0.2] x [0, 0.1] -> [0.4, 0.5] x [0, 0.2] x [0, 0.1]. Another order would give another box.
  TriangleMesh mesh = test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.1));
  SurfaceTransform transform;
  transform.scale = Vec3(2.0, 1.0, 1.0);
  transform.rotationAxis = Vec3(0.0, 0.0, 3.0);
  transform.rotationDegrees = 90.0;
  transform.translation = Vec3(0.5, 0.0, 0.0);
  transform.applyTo(mesh);
  const std::vector<Vec3> points = sampleInside(SurfaceMesh(mesh), 0.01);
  const std::vector<Vec3> expected = sampleBox(Vec3(0.4, 0.0, 0.0), Vec3(0.5, 0.2, 0.1), 0.01);
  ASSERT_EQ(points.size(), expected.size());
  for (std::size_t k = 0; k < points.size(); ++k) ASSERT_LT((points[k] - expected[k]).norm(), 1e-12) << k;
}

TEST(SampleWallBody, CubeInsideIsTwoLayersBehindEachFace) {
  // The points within 2 * 2r inside the faces: 10^3 - 6^3.
  const SurfaceMesh cube(test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.2)));
  const std::vector<Vec3> walls = sampleWallBody(cube, 0.01, 2, WallSide::Inside);
  EXPECT_EQ(walls.size(), 1000u - 216u);
  for (const Vec3& p : walls) {
    const double depth = std::min(p.minCoeff(), 0.2 - p.maxCoeff());
    EXPECT_TRUE(std::abs(depth - 0.01) < 1e-12 || std::abs(depth - 0.03) < 1e-12) << p.transpose();
  }
}

TEST(SampleWallBody, CubeOutsideIsAContainerWithRoundedEdges) {
  // Points at r and 3r behind each face (6 x 10^2 x 2), then along the 12 edges the offsets (a, b) in {r, 3r}^2
  // closer than 4r: (r, r), (r, 3r), (3r, r) (12 x 10 x 3), and at the 8 corners (r, r, r) and the three
  // permutations of (r, r, 3r) (8 x 4).
  const SurfaceMesh cube(test::cubeMesh(Vec3::Zero(), Vec3::Constant(0.2)));
  const std::vector<Vec3> walls = sampleWallBody(cube, 0.01, 2, WallSide::Outside);
  EXPECT_EQ(walls.size(), 1200u + 360u + 32u);
  for (const Vec3& p : walls) {
    const Vec3 outside = (-p).cwiseMax(p - Vec3::Constant(0.2)).cwiseMax(Vec3::Zero());
    EXPECT_GT(outside.norm(), 0.0);
    EXPECT_LT(outside.norm(), 0.04);
  }
}

TEST(SampleWallBody, SphereEqualsBruteForceOnBothSides) {
  const Vec3 c(0.0, 0.1, 0.0);
  const double radius = 0.1, r = 0.004;
  const Sphere sphere(c, radius);
  for (int layers : {1, 2, 3}) {
    const double thickness = layers * 2.0 * r;
    const std::vector<Vec3> inside = sampleWallBody(sphere, r, layers, WallSide::Inside);
    ASSERT_FALSE(inside.empty());
    EXPECT_EQ(inside, bruteForce(boxLattice(sphere.boxMin(), sphere.boxMax(), r),
                                 [&](const Vec3& p) {
                                   const double d = (p - c).norm();
                                   return d < radius && radius - d < thickness;
                                 }))
        << layers << " layers";
    const std::vector<Vec3> outside = sampleWallBody(sphere, r, layers, WallSide::Outside);
    ASSERT_FALSE(outside.empty());
    EXPECT_EQ(outside, bruteForce(boxLattice(sphere.boxMin(), sphere.boxMax(), r, layers),
                                  [&](const Vec3& p) {
                                    const double d = (p - c).norm();
                                    return d > radius && d - radius < thickness;
                                  }))
        << layers << " layers";
  }
}

TEST(SampleWallBody, MeshWallsMatchTheirDistanceDefinition) {
  // Torus walls: on the right side by the winding number, closer than layers * 2r to the analytic torus up to
  // the faceting of the mesh: sagittas a (1 - cos(pi / 24)) + (R + a) (1 - cos(pi / 48)) = 0.128 r < 0.13 r.
  const double R = 0.2, a = 0.08, r = 0.01;
  const TriangleMesh mesh = test::torusMesh(Vec3::Zero(), R, a, 48, 24);
  const SurfaceMesh torus(mesh);
  const auto torusDistance = [&](const Vec3& p) {
    return std::abs(Vec3(std::hypot(p.x(), p.y()) - R, p.z(), 0).norm() - a);
  };
  for (WallSide side : {WallSide::Inside, WallSide::Outside}) {
    const std::vector<Vec3> walls = sampleWallBody(torus, r, 2, side);
    ASSERT_FALSE(walls.empty());
    for (const Vec3& p : walls) {
      EXPECT_EQ(test::windingNumber(mesh, p) > 0.5, side == WallSide::Inside) << p.transpose();
      EXPECT_LT(torusDistance(p), 4.0 * r + 0.13 * r) << p.transpose();
    }
  }
}

} // namespace
} // namespace poro
