// The hash-grid search for close pairs of particles of regions that must keep apart (utilities/sampleParticles,
// used by the overlap check of sampleParticles): equal to the brute-force N^2 search.
#include "ClosePairs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace poro {
namespace {

/// count and closest distance per label pair, by brute force.
std::map<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, double>>
bruteForce(const std::vector<Vec3>& x, const std::vector<std::int64_t>& label, double distance,
           const std::vector<std::vector<bool>>& apart) {
  std::map<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, double>> result;
  for (std::size_t p = 0; p < x.size(); ++p)
    for (std::size_t q = p + 1; q < x.size(); ++q) {
      const auto a = static_cast<std::size_t>(label[p]), b = static_cast<std::size_t>(label[q]);
      const double d = (x[p] - x[q]).norm();
      if (!apart[a][b] || !(d < distance)) continue;
      auto& entry = result[{std::min(a, b), std::max(a, b)}];
      entry.second = entry.first++ == 0 ? d : std::min(entry.second, d);
    }
  return result;
}

void expectBruteForce(const std::vector<Vec3>& x, const std::vector<std::int64_t>& label, double distance,
                      const std::vector<std::vector<bool>>& apart) {
  // Split over two point sets, as sampleParticles passes one per particle set.
  const std::size_t half = x.size() / 2;
  const std::vector<Vec3> x1(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(half)),
      x2(x.begin() + static_cast<std::ptrdiff_t>(half), x.end());
  const std::vector<std::int64_t> l1(label.begin(), label.begin() + static_cast<std::ptrdiff_t>(half)),
      l2(label.begin() + static_cast<std::ptrdiff_t>(half), label.end());
  const std::vector<ClosePairs> found = findClosePairs({{&x1, &l1}, {&x2, &l2}}, distance, apart);
  const auto expected = bruteForce(x, label, distance, apart);
  ASSERT_EQ(found.size(), expected.size());
  std::size_t k = 0;
  for (const auto& [labels, entry] : expected) {
    const ClosePairs& f = found[k++];
    EXPECT_EQ(f.a, labels.first);
    EXPECT_EQ(f.b, labels.second);
    EXPECT_EQ(f.count, entry.first);
    EXPECT_DOUBLE_EQ(f.closest, entry.second);
    EXPECT_DOUBLE_EQ((f.pointA - f.pointB).norm(), f.closest);
  }
}

TEST(ClosePairs, EqualsBruteForceOnRandomPoints) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.3, 0.5);
  std::uniform_int_distribution<int> labels(0, 3);
  std::vector<Vec3> x;
  std::vector<std::int64_t> label;
  for (int i = 0; i < 10000; ++i) { // more occupied cells than one parallel task of the search takes
    x.emplace_back(coordinate(random), coordinate(random), coordinate(random));
    label.push_back(labels(random));
  }
  // 0 and 1 apart from each other and from 3; 2 apart from nothing (as fluid and porous regions).
  const std::vector<std::vector<bool>> apart = {
      {false, true, false, true}, {true, false, false, true}, {false, false, false, false}, {true, true, false, false}};
  expectBruteForce(x, label, 0.03, apart);
  x.resize(2000);
  label.resize(2000);
  expectBruteForce(x, label, 0.1, apart);
}

TEST(ClosePairs, EqualsBruteForceOnLatticesThatCoincideOrTouch) {
  // Three lattices of spacing 0.02: label 1 overlaps label 0 point on point, label 2 touches label 0 at 2r.
  std::vector<Vec3> x;
  std::vector<std::int64_t> label;
  const auto box = [&](const Vec3& origin, int n, std::int64_t l) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          x.push_back(origin + 0.02 * Vec3(i, j, k));
          label.push_back(l);
        }
  };
  box(Vec3::Zero(), 8, 0);
  box(Vec3(0.06, 0.06, 0.06), 4, 1);
  box(Vec3(0.16, 0, 0), 3, 2);
  const std::vector<std::vector<bool>> apart(3, {true, true, true});
  std::vector<std::vector<bool>> distinct = apart;
  for (std::size_t a = 0; a < 3; ++a) distinct[a][a] = false;
  expectBruteForce(x, label, 0.0173, distinct);
  const std::vector<ClosePairs> found = findClosePairs({{&x, &label}}, 0.0173, distinct);
  ASSERT_EQ(found.size(), 1u); // only the coincident lattices; touching ones are 2r apart
  EXPECT_EQ(found[0].count, 64u);
  EXPECT_EQ(found[0].closest, 0.0);
}

TEST(ClosePairs, NamesTheFirstOfTiedPairsWhateverTheRoundingOfTheirDistances) {
  // Two pairs 0.05 apart in exact arithmetic; computed, 0.14 - 0.09 is 0.05000000000000002 and 0.85 - 0.8 is
  // 0.04999999999999993. The message must not depend on that (a build with fused multiply-adds rounds otherwise):
  // the pair that comes first in x, y, z is named, in either order of the points.
  const std::vector<std::vector<bool>> apart = {{false, true}, {true, false}};
  for (const bool reversed : {false, true}) {
    std::vector<Vec3> x = {Vec3(0.09, 0, 0), Vec3(0.8, 0, 0), Vec3(0.14, 0, 0), Vec3(0.85, 0, 0)};
    std::vector<std::int64_t> label = {0, 0, 1, 1};
    if (reversed) {
      std::reverse(x.begin(), x.end());
      std::reverse(label.begin(), label.end());
    }
    const std::vector<ClosePairs> found = findClosePairs({{&x, &label}}, 0.1, apart);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].count, 2u);
    EXPECT_EQ(found[0].pointA, Vec3(0.09, 0, 0)) << reversed;
    EXPECT_EQ(found[0].pointB, Vec3(0.14, 0, 0)) << reversed;
    EXPECT_NEAR(found[0].closest, 0.05, 1e-15);
  }
}

TEST(ClosePairs, FarApartPointsGrowTheCellsInsteadOfTheGrid) {
  // 10^9 cells of the distance apart: the keys hold 2^21 per axis, so the cells grow; the pairs are still found.
  std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(0.005, 0, 0), Vec3(1e7, 0, 0), Vec3(1e7, 0.009, 0), Vec3(1e7, 0, 1e7)};
  std::vector<std::int64_t> label = {0, 1, 0, 1, 1};
  const std::vector<std::vector<bool>> apart = {{false, true}, {true, false}};
  expectBruteForce(x, label, 0.01, apart);
}

TEST(ClosePairs, NoPointsNoPairs) {
  const std::vector<Vec3> x;
  const std::vector<std::int64_t> label;
  EXPECT_TRUE(findClosePairs({{&x, &label}}, 0.01, {{false}}).empty());
}

} // namespace
} // namespace poro
