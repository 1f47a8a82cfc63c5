// Partitions (parallel/Partition.hpp): the Hilbert index is a face-connected bijection; both methods give every part
// its share of the weight within what whole particles allow, bisection gives disjoint boxes, ownership is a function
// of position that tiles space, and the result is deterministic.

#include "parallel/Partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <set>

namespace poro {
namespace {

TEST(HilbertIndex, VisitsEveryCellOnceMovingOneFaceAtATime) {
  for (int bits = 1; bits <= 4; ++bits) {
    const std::uint32_t side = 1u << bits;
    std::vector<std::array<std::uint32_t, 3>> cellAt(static_cast<std::size_t>(side) * side * side, {side, side, side});
    for (std::uint32_t i = 0; i < side; ++i)
      for (std::uint32_t j = 0; j < side; ++j)
        for (std::uint32_t k = 0; k < side; ++k) {
          const std::uint64_t h = hilbertIndex(i, j, k, bits);
          ASSERT_LT(h, cellAt.size());
          ASSERT_EQ(cellAt[h][0], side) << "index " << h << " given twice at order " << bits;
          cellAt[h] = {i, j, k};
        }
    for (std::size_t h = 1; h < cellAt.size(); ++h) {
      int steps = 0;
      for (int a = 0; a < 3; ++a)
        steps += std::abs(static_cast<int>(cellAt[h][a]) - static_cast<int>(cellAt[h - 1][a]));
      EXPECT_EQ(steps, 1) << "indices " << h - 1 << " and " << h << " at order " << bits;
    }
  }
}

struct Cloud {
  std::vector<Vec3> points;
  std::vector<double> weights;
};

Cloud randomCloud(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(0.0, 2.0), y(0.0, 1.0), z(0.0, 0.5), w(0.25, 2.0);
  Cloud c;
  for (std::size_t i = 0; i < n; ++i) {
    c.points.emplace_back(x(rng), y(rng), z(rng));
    c.weights.push_back(w(rng));
  }
  return c;
}

std::vector<double> partWeights(const Cloud& c, const std::vector<int>& owner, int parts) {
  std::vector<double> w(static_cast<std::size_t>(parts), 0.0);
  for (std::size_t i = 0; i < owner.size(); ++i) {
    EXPECT_GE(owner[i], 0);
    EXPECT_LT(owner[i], parts);
    w[static_cast<std::size_t>(owner[i])] += c.weights[i];
  }
  return w;
}

TEST(Partition, BisectionBalancesWithinWholeParticlesAndCutsDisjointBoxes) {
  const Cloud c = randomCloud(5000, 7);
  const double total = std::accumulate(c.weights.begin(), c.weights.end(), 0.0);
  for (int parts = 1; parts <= 9; ++parts) {
    const std::vector<int> owner =
        Partition::build(c.points, c.weights, parts, PartitionMethod::RecursiveBisection).owners(c.points);
    // Each cut misses its share by at most half the heaviest particle (2.0), and a part lies below at most
    // ceil(log2 parts) cuts, each scaling the misses above it by at most 1.
    const double levels = std::ceil(std::log2(static_cast<double>(parts)));
    const std::vector<double> w = partWeights(c, owner, parts);
    for (int p = 0; p < parts; ++p)
      EXPECT_NEAR(w[static_cast<std::size_t>(p)], total / parts, 1.0 * levels + 1e-9) << parts << " parts, part " << p;
    // Axis-aligned cuts: the bounding boxes of two parts are separated along some axis.
    std::vector<Vec3> lo(static_cast<std::size_t>(parts), Vec3::Constant(INFINITY));
    std::vector<Vec3> hi(static_cast<std::size_t>(parts), Vec3::Constant(-INFINITY));
    for (std::size_t i = 0; i < owner.size(); ++i) {
      lo[static_cast<std::size_t>(owner[i])] = lo[static_cast<std::size_t>(owner[i])].cwiseMin(c.points[i]);
      hi[static_cast<std::size_t>(owner[i])] = hi[static_cast<std::size_t>(owner[i])].cwiseMax(c.points[i]);
    }
    for (std::size_t p = 0; p < lo.size(); ++p)
      for (std::size_t q = p + 1; q < lo.size(); ++q) {
        bool separated = false;
        for (int a = 0; a < 3; ++a) separated = separated || hi[p][a] < lo[q][a] || hi[q][a] < lo[p][a];
        EXPECT_TRUE(separated) << parts << " parts: parts " << p << " and " << q << " overlap";
      }
  }
}

TEST(Partition, HilbertCurveBalancesWithinWholeParticles) {
  const Cloud c = randomCloud(5000, 11);
  const double total = std::accumulate(c.weights.begin(), c.weights.end(), 0.0);
  for (int parts = 1; parts <= 9; ++parts) {
    const std::vector<int> owner =
        Partition::build(c.points, c.weights, parts, PartitionMethod::HilbertCurve).owners(c.points);
    // Each cut lies within half the heaviest particle (1.0) of its share p W / n of the curve's weight (2^63 keys:
    // no two of these points share one), so a part, between two cuts, is within 2 x 1.0 of W / n.
    const std::vector<double> w = partWeights(c, owner, parts);
    for (int p = 0; p < parts; ++p)
      EXPECT_NEAR(w[static_cast<std::size_t>(p)], total / parts, 2.0 + 1e-9) << parts << " parts, part " << p;
  }
}

TEST(Partition, IsDeterministicAndGivesEqualPointsOneEach) {
  const Cloud c = randomCloud(40, 3);
  const std::vector<double> equal(c.points.size(), 1.0);
  for (const PartitionMethod method : {PartitionMethod::RecursiveBisection, PartitionMethod::HilbertCurve}) {
    const auto a = Partition::build(c.points, c.weights, 7, method).owners(c.points);
    EXPECT_EQ(a, Partition::build(c.points, c.weights, 7, method).owners(c.points));
    const auto one = Partition::build(c.points, equal, 40, method).owners(c.points);
    EXPECT_EQ(std::set<int>(one.begin(), one.end()).size(), 40u) << toString(method); // one point each
    for (const int owner : Partition::build(c.points, equal, 50, method).owners(c.points)) {
      EXPECT_GE(owner, 0);
      EXPECT_LT(owner, 50);
    }
    EXPECT_EQ(Partition::build({}, {}, 4, method).ownerOf(Vec3(1, 2, 3)) >= 0, true);
  }
  EXPECT_THROW(Partition::build(c.points, {}, 2, PartitionMethod::HilbertCurve), std::logic_error);
}

TEST(Partition, OwnershipIsAFunctionOfPositionThatTilesSpace) {
  // A lattice of spacing 1: cuts fall midway between layers, so every particle keeps its part while it moves less
  // than half a spacing across a cut, and any position, inside the lattice's box or far outside, has a part.
  std::vector<Vec3> lattice;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) lattice.emplace_back(i, j, k);
  const std::vector<double> weights(lattice.size(), 1.0);
  const Partition bisection = Partition::build(lattice, weights, 4, PartitionMethod::RecursiveBisection);
  const std::vector<int> owner = bisection.owners(lattice);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.49, 0.49), far(-100.0, 100.0);
  for (std::size_t i = 0; i < lattice.size(); ++i)
    EXPECT_EQ(bisection.ownerOf(lattice[i] + Vec3(jitter(rng), jitter(rng), jitter(rng))), owner[i]) << i;
  for (const PartitionMethod method : {PartitionMethod::RecursiveBisection, PartitionMethod::HilbertCurve}) {
    const Partition p = Partition::build(lattice, weights, 4, method);
    for (int k = 0; k < 100; ++k) {
      const int part = p.ownerOf(Vec3(far(rng), far(rng), far(rng)));
      EXPECT_GE(part, 0);
      EXPECT_LT(part, 4);
    }
    EXPECT_GE(p.ownerOf(Vec3::Constant(std::numeric_limits<double>::quiet_NaN())), 0);
  }
}

/// The published Seep set in miniature: a porous block (class 1, weight 1.75) of 8 x 8 x 8 layers under a fluid
/// column (class 0) of 8 x 16 x 8, so the box is tallest along y.
struct Stack {
  std::vector<Vec3> points;
  std::vector<double> weights;
  std::vector<int> classes;
};

Stack blockUnderColumn() {
  Stack s;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 24; ++j)
      for (int k = 0; k < 8; ++k) {
        s.points.emplace_back(i + 0.5, j + 0.5, k + 0.5);
        s.classes.push_back(j < 8 ? 1 : 0);
        s.weights.push_back(j < 8 ? 1.75 : 1.0);
      }
  return s;
}

/// Per part, its share of each class's particles.
std::vector<std::array<double, 2>> classShares(const Stack& s, const std::vector<int>& owner, int parts) {
  std::vector<std::array<double, 2>> share(static_cast<std::size_t>(parts), {0.0, 0.0});
  std::array<double, 2> count{0.0, 0.0};
  for (std::size_t i = 0; i < owner.size(); ++i) {
    share[static_cast<std::size_t>(owner[i])][static_cast<std::size_t>(s.classes[i])] += 1.0;
    count[static_cast<std::size_t>(s.classes[i])] += 1.0;
  }
  for (auto& p : share)
    for (std::size_t c = 0; c < 2; ++c) p[c] /= count[c];
  return share;
}

TEST(Partition, BisectionGivesEachClassItsShareWhereTheLongestSideWouldNot) {
  const Stack s = blockUnderColumn();
  // Without classes the tall side is cut: the block's weight (1.75 x 512) plus the column's lowest 8 layers lie
  // below the weighted median, so one part holds every porous particle.
  const auto plain = Partition::build(s.points, s.weights, 2, PartitionMethod::RecursiveBisection).owners(s.points);
  const auto plainShares = classShares(s, plain, 2);
  EXPECT_TRUE(plainShares[0][1] == 1.0 || plainShares[1][1] == 1.0);
  // With classes each part of 2 and of 4 holds its share of the block and of the column: 8 layers split evenly.
  for (const int parts : {2, 4}) {
    const auto owner = Partition::build(s.points, s.weights, parts, PartitionMethod::RecursiveBisection, {}, s.classes)
                           .owners(s.points);
    const auto shares = classShares(s, owner, parts);
    for (int p = 0; p < parts; ++p)
      for (std::size_t c = 0; c < 2; ++c)
        EXPECT_DOUBLE_EQ(shares[static_cast<std::size_t>(p)][c], 1.0 / parts)
            << parts << " parts, part " << p << ", class " << c;
  }
}

TEST(Partition, OneClassCutsAsWithoutClasses) {
  // The dam break's case: fluid, and walls in no class, cut the longest side.
  const Cloud c = randomCloud(4000, 11);
  std::vector<int> classes(c.points.size(), 0);
  std::vector<double> weights = c.weights;
  for (std::size_t i = 0; i < classes.size(); i += 40) {
    classes[i] = -1;
    weights[i] = 0.05;
  }
  for (const int parts : {2, 3, 5}) {
    const Partition plain = Partition::build(c.points, weights, parts, PartitionMethod::RecursiveBisection);
    const Partition classed =
        Partition::build(c.points, weights, parts, PartitionMethod::RecursiveBisection, {}, classes);
    EXPECT_EQ(plain.text(), classed.text()) << parts << " parts";
  }
}

TEST(Partition, HilbertCurveKeepsPartsCompact) {
  // A 16^3 lattice in 8 parts: a Hilbert curve visits the octants of its box one after another, and the lattice's
  // octants are the grid's (8 of its 16 layers lie in each half), so each part is exactly one 8^3 octant.
  std::vector<Vec3> points;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int k = 0; k < 16; ++k) points.emplace_back(i + 0.5, j + 0.5, k + 0.5);
  const std::vector<double> weights(points.size(), 1.0);
  const auto owner = Partition::build(points, weights, 8, PartitionMethod::HilbertCurve).owners(points);
  std::vector<std::set<int>> octants(8);
  for (std::size_t i = 0; i < points.size(); ++i)
    octants[static_cast<std::size_t>(owner[i])].insert((points[i].x() > 8) + 2 * (points[i].y() > 8) +
                                                       4 * (points[i].z() > 8));
  for (int p = 0; p < 8; ++p) EXPECT_EQ(octants[static_cast<std::size_t>(p)].size(), 1u) << "part " << p;
}

} // namespace
} // namespace poro
