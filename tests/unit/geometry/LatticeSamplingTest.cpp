// Block and container sampling on the simple cubic lattice of spacing 2r (METHOD.md §2.3, §12.2).
#include "geometry/LatticeSampling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <vector>

namespace poro {
namespace {

constexpr double kR = 0.01;
constexpr double kSpacing = 2.0 * kR;

/// Lattice index of p relative to the lattice through `anchor` (asserts that p lies on it to round-off).
std::tuple<long long, long long, long long> latticeIndex(const Vec3& p, const Vec3& anchor, double spacing) {
  long long k[3];
  for (int d = 0; d < 3; ++d) {
    const double q = (p[d] - anchor[d]) / spacing;
    k[d] = std::llround(q);
    EXPECT_NEAR(q, static_cast<double>(k[d]), 1e-9) << "off the lattice: " << p.transpose();
  }
  return {k[0], k[1], k[2]};
}

/// Distinct values of coordinate d (merged within `tol`), ascending.
std::vector<double> distinctCoordinates(const std::vector<Vec3>& points, int d, double tol = 1e-9) {
  std::vector<double> v;
  for (const Vec3& p : points) v.push_back(p[d]);
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > tol) out.push_back(x);
  return out;
}

double nearestDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double best = std::numeric_limits<double>::max();
  for (const Vec3& p : a)
    for (const Vec3& q : b) best = std::min(best, (p - q).norm());
  return best;
}

TEST(LatticeCount, ExactMultiples) {
  EXPECT_EQ(latticeCount(0.96, 0.02), 48); // 0.96 / 0.02 = 47.99999999999999 in floating point
  EXPECT_EQ(latticeCount(0.98, 0.02), 49);
  EXPECT_EQ(latticeCount(0.1, 0.02), 5);
  EXPECT_EQ(latticeCount(4.0, 0.02), 200);
  EXPECT_EQ(latticeCount(0.9, 0.05), 18);
  EXPECT_EQ(latticeCount(0.0, 0.02), 0);
}

TEST(LatticeCount, RoundsToNearestAndHalfIntegersUp) {
  EXPECT_EQ(latticeCount(2.4 * 0.02, 0.02), 2);
  EXPECT_EQ(latticeCount(2.6 * 0.02, 0.02), 3);
  EXPECT_EQ(latticeCount(0.01, 0.02), 1);  // 0.5
  EXPECT_EQ(latticeCount(0.05, 0.02), 3);  // 2.5 (2.5000000000000004 or a hair below in floating point)
  EXPECT_EQ(latticeCount(0.97, 0.02), 49); // 48.5
  EXPECT_EQ(latticeCount(2.5, 1.0), 3);
  // Within 1e-9 (relative) below a half-integer still counts as the half-integer and rounds up ...
  EXPECT_EQ(latticeCount(2.5 * (1.0 - 5e-10), 1.0), 3);
  EXPECT_EQ(latticeCount(1000.5 * (1.0 - 5e-10), 1.0), 1001);
  // ... but further below it rounds down as usual.
  EXPECT_EQ(latticeCount(2.5 * (1.0 - 1e-8), 1.0), 2);
  EXPECT_EQ(latticeCount(1000.5 * (1.0 - 1e-8), 1.0), 1000);
}

TEST(SampleBox, BoxOf96CentimetresAtOneCentimetre) {
  // METHOD.md §2.3: 48^3 = 110,592 points tiling the box exactly, spacing 2r, first centre at min + r.
  const Vec3 min(-0.48, 0.035, 1.2), max = min + Vec3::Constant(0.96);
  const std::vector<Vec3> x = sampleBox(min, max, kR);
  ASSERT_EQ(x.size(), 110592u);
  std::set<std::tuple<long long, long long, long long>> indices;
  for (const Vec3& p : x) {
    for (int d = 0; d < 3; ++d) {
      ASSERT_GE(p[d], min[d] + kR - 1e-12);
      ASSERT_LE(p[d], max[d] - kR + 1e-12);
    }
    indices.insert(latticeIndex(p, min + Vec3::Constant(kR), kSpacing));
  }
  EXPECT_EQ(indices.size(), x.size()) << "duplicate points";
  for (int d = 0; d < 3; ++d) {
    const std::vector<double> c = distinctCoordinates(x, d);
    ASSERT_EQ(c.size(), 48u);
    EXPECT_NEAR(c.front(), min[d] + kR, 1e-12);
    EXPECT_NEAR(c.back(), max[d] - kR, 1e-12); // tiles exactly: r from both faces
    for (std::size_t k = 1; k < c.size(); ++k) EXPECT_NEAR(c[k] - c[k - 1], kSpacing, 1e-12);
  }
  // Sampled volume N (2r)^3 equals the box volume, so the sampled mass is rho * volume.
  EXPECT_NEAR(static_cast<double>(x.size()) * std::pow(kSpacing, 3), std::pow(0.96, 3), 1e-12);
}

/// Samples the published centre range [cMin, cMax] as the PoroSPH box [cMin - r, cMax + r] and checks the count
/// per axis and that the first and last centres are the published ones.
void checkPublishedBlock(const Vec3& cMin, const Vec3& cMax, double r, long long nx, long long ny, long long nz) {
  const Vec3 rr = Vec3::Constant(r);
  const std::vector<Vec3> x = sampleBox(cMin - rr, cMax + rr, r);
  const long long n[3] = {nx, ny, nz};
  ASSERT_EQ(static_cast<long long>(x.size()), nx * ny * nz);
  for (int d = 0; d < 3; ++d) {
    const std::vector<double> c = distinctCoordinates(x, d);
    ASSERT_EQ(static_cast<long long>(c.size()), n[d]) << "axis " << d;
    EXPECT_NEAR(c.front(), cMin[d], 1e-12) << "axis " << d;
    EXPECT_NEAR(c.back(), cMax[d], 1e-12) << "axis " << d;
  }
}

TEST(SampleBox, PublishedBlocksOfSection12) {
  // Seep (r = 1 cm): porous and fluid blocks 48 x 49 x 48 = 112,896 each.
  checkPublishedBlock(Vec3(-0.47, 0.045, -0.47), Vec3(0.47, 1.005, 0.47), 0.01, 48, 49, 48);
  checkPublishedBlock(Vec3(-0.47, 1.08, -0.47), Vec3(0.47, 2.04, 0.47), 0.01, 48, 49, 48);
  // Climb (r = 1 cm): two pools 43 x 21 x 47 and a porous block 46 x 49 x 46.
  checkPublishedBlock(Vec3(-1.46, 0.03, -0.46), Vec3(-0.62, 0.43, 0.46), 0.01, 43, 21, 47);
  checkPublishedBlock(Vec3(0.62, 0.03, -0.46), Vec3(1.46, 0.43, 0.46), 0.01, 43, 21, 47);
  checkPublishedBlock(Vec3(-0.45, 0.03, -0.45), Vec3(0.45, 0.99, 0.45), 0.01, 46, 49, 46);
  // Float (r = 2.5 cm): fluid 18 x 19 x 18 and porous 11 x 9 x 11.
  checkPublishedBlock(Vec3(-0.425, 0.11, -0.425), Vec3(0.425, 1.01, 0.425), 0.025, 18, 19, 18);
  checkPublishedBlock(Vec3(-0.25, 1.10, -0.25), Vec3(0.25, 1.50, 0.25), 0.025, 11, 9, 11);
}

/// Container properties that hold for any inner box: walls outside it, `layers` layers per closed face with the
/// first at exactly r behind the face, spaced 2r, nothing beyond an open face.
void checkContainerWalls(const std::vector<Vec3>& walls, const Vec3& min, const Vec3& max, int layers,
                         const FaceFlags& open) {
  const double tol = 1e-12;
  for (const Vec3& p : walls) {
    bool outside = false;
    for (int d = 0; d < 3; ++d) outside = outside || p[d] < min[d] - kR + tol || p[d] > max[d] + kR - tol;
    ASSERT_TRUE(outside) << "wall particle inside the inner box (or closer than r to it): " << p.transpose();
    for (int d = 0; d < 3; ++d) {
      if (open[static_cast<std::size_t>(2 * d)]) {
        ASSERT_GE(p[d], min[d]) << "particle beyond an open face";
      }
      if (open[static_cast<std::size_t>(2 * d + 1)]) {
        ASSERT_LE(p[d], max[d]) << "particle beyond an open face";
      }
    }
  }
  for (int d = 0; d < 3; ++d) {
    // Coordinates behind the min and max faces of axis d: exactly the layers r, 3r, ... from that face.
    std::vector<double> cb, ca;
    for (double c : distinctCoordinates(walls, d)) {
      if (c < min[d]) cb.push_back(min[d] - c);
      if (c > max[d]) ca.push_back(c - max[d]);
    }
    std::sort(cb.begin(), cb.end());
    const std::size_t expectBelow = open[static_cast<std::size_t>(2 * d)] ? 0 : static_cast<std::size_t>(layers);
    const std::size_t expectAbove = open[static_cast<std::size_t>(2 * d + 1)] ? 0 : static_cast<std::size_t>(layers);
    ASSERT_EQ(cb.size(), expectBelow) << "axis " << d;
    ASSERT_EQ(ca.size(), expectAbove) << "axis " << d;
    for (std::size_t l = 0; l < cb.size(); ++l) EXPECT_NEAR(cb[l], kR + kSpacing * l, tol) << "axis " << d;
    for (std::size_t l = 0; l < ca.size(); ++l) EXPECT_NEAR(ca[l], kR + kSpacing * l, tol) << "axis " << d;
  }
}

TEST(SampleContainer, ClosedAndOpenBoxesOnTheLattice) {
  // Inner box a multiple of 2r: 10 x 10 x 6 lattice cells.
  const Vec3 min(-0.1, 0.0, -0.06), max(0.1, 0.2, 0.06);
  const long long n[3] = {10, 10, 6};
  for (int layers : {1, 2, 3}) {
    for (bool openTop : {false, true}) {
      const FaceFlags open = {false, false, false, openTop, false, false};
      const std::vector<Vec3> walls = sampleContainer(min, max, kR, layers, open);
      // Analytic count of the layered shell (edges and corners filled).
      const long long outer = (n[0] + 2 * layers) * (n[1] + (openTop ? 1 : 2) * layers) * (n[2] + 2 * layers);
      ASSERT_EQ(static_cast<long long>(walls.size()), outer - n[0] * n[1] * n[2])
          << layers << " layers, open " << openTop;
      checkContainerWalls(walls, min, max, layers, open);
      // All on the lattice through min + r, no duplicates; the outermost corner is present.
      std::set<std::tuple<long long, long long, long long>> indices;
      for (const Vec3& p : walls) indices.insert(latticeIndex(p, min + Vec3::Constant(kR), kSpacing));
      EXPECT_EQ(indices.size(), walls.size());
      EXPECT_TRUE(indices.count({-layers, -layers, -layers}));
      EXPECT_TRUE(indices.count({n[0] + layers - 1, -layers, n[2] + layers - 1}));
      EXPECT_EQ(indices.count({-layers, n[1] + layers - 1, -layers}), openTop ? 0u : 1u);
      // A fluid block from the container's floor continues the wall lattice: nearest wall particle at 2r.
      const std::vector<Vec3> fluid = sampleBox(min, Vec3(max.x(), min.y() + 0.1, max.z()), kR);
      EXPECT_NEAR(nearestDistance(fluid, walls), kSpacing, 1e-12);
      for (const Vec3& p : fluid) latticeIndex(p, min + Vec3::Constant(kR), kSpacing);
    }
  }
}

TEST(SampleContainer, InnerBoxNotAMultipleOfTheSpacing) {
  // Max side 10.3, 10.7 and 6.5 spacings from min: every wall is placed from its own face, so the max-side walls
  // are r behind the max face, not on the lattice continued from min. Along the faces the inner extent is
  // split into ceil(L/2r) equal steps, so no seam between wall particles is wider than 2r (fluid leaks
  // through a wider one at the container's edges).
  const Vec3 min(-0.1, 0.0, -0.06);
  const Vec3 max = min + kSpacing * Vec3(10.3, 10.7, 6.5);
  const int layers = 2;
  const FaceFlags closed = {false, false, false, false, false, false};
  const std::vector<Vec3> walls = sampleContainer(min, max, kR, layers, closed);
  checkContainerWalls(walls, min, max, layers, closed);
  const long long n[3] = {11, 11, 7};
  EXPECT_EQ(static_cast<long long>(walls.size()),
            (n[0] + 2 * layers) * (n[1] + 2 * layers) * (n[2] + 2 * layers) - n[0] * n[1] * n[2]);
  // The seam check on the first zMin layer: consecutive x coordinates are at most 2r apart.
  std::vector<double> xs;
  for (const Vec3& w : walls)
    if (std::abs(w.z() - (min.z() - kR)) < 1e-12) xs.push_back(w.x());
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }), xs.end());
  for (std::size_t k = 1; k < xs.size(); ++k)
    EXPECT_LE(xs[k] - xs[k - 1], kSpacing * (1.0 + 1e-9)) << "at x = " << xs[k];
  // A fluid block filling a multiple of 2r from min sits 2r from the min-side walls, within the tangential
  // shift of the stretched wall rows (sqrt(4 + 0.07^2) r here).
  const std::vector<Vec3> fluid = sampleBox(min, min + kSpacing * Vec3(6.0, 4.0, 3.0), kR);
  EXPECT_NEAR(nearestDistance(fluid, walls), kSpacing, 2e-3 * kSpacing);
  // A fluid block filling the whole inner box never comes closer than r to a wall (its centres stay inside).
  const std::vector<Vec3> full = sampleBox(min, max, kR);
  EXPECT_EQ(static_cast<long long>(full.size()), 10 * 11 * 7);
  EXPECT_GE(nearestDistance(full, walls), kR * (1.0 - 1e-9));
}

TEST(PointCount, EqualsTheNumberOfSampledPoints) {
  const Vec3 min(-0.1, 0.0, -0.06);
  for (const Vec3& extent : {Vec3(10.3, 10.7, 6.5), Vec3(4.0, 0.4, 2.5), Vec3(1.0, 1.0, 1.0), Vec3(0.2, 3.0, 2.0)}) {
    const Vec3 max = min + kSpacing * extent;
    EXPECT_EQ(boxPointCount(min, max, kR), static_cast<double>(sampleBox(min, max, kR).size())) << extent.transpose();
    for (int layers : {1, 2, 3})
      for (const FaceFlags& open : {FaceFlags{}, FaceFlags{false, false, false, true, false, false},
                                    FaceFlags{true, false, false, true, false, true}})
        EXPECT_EQ(containerPointCount(min, max, kR, layers, open),
                  static_cast<double>(sampleContainer(min, max, kR, layers, open).size()))
            << extent.transpose() << ", " << layers << " layers";
  }
  const FaceFlags allOpen = {true, true, true, true, true, true};
  EXPECT_EQ(containerPointCount(min, min + Vec3::Ones(), kR, 2, allOpen), 0.0);
}

TEST(PointCount, AbsurdRadiiGiveHugeFiniteCountsWithoutSampling) {
  // A metre cube at r = 1 nm: 1.25e26 points, far beyond what a long long counts by lattice rows.
  const Vec3 min = Vec3::Zero(), max = Vec3::Ones();
  EXPECT_NEAR(boxPointCount(min, max, 1e-9) / 1.25e26, 1.0, 1e-9);
  const double walls = containerPointCount(min, max, 1e-9, 2, FaceFlags{});
  EXPECT_NEAR(walls / (6 * 2 * 2.5e17), 1.0, 1e-6); // 2 layers on six faces of 5e8 x 5e8 points
  EXPECT_EQ(boxPointCount(min, Vec3(1e300, 1.0, 1.0), 0.01), 0.5e302 * 50 * 50);
  EXPECT_TRUE(std::isinf(boxPointCount(min, Vec3(1e300, 1e300, 1.0), 1e-9)));
}

} // namespace
} // namespace poro
