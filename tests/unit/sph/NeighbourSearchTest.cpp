// Neighbour search (METHOD.md §6.1): lists equal a brute-force O(N^2) search for any thread count, Morton
// sorting permutes every registered field and changes nothing else.
#include "sph/NeighbourSearch.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "sph/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

namespace poro {
namespace {

using Positions = std::vector<Vec3>;
using Lists = std::vector<std::vector<Index>>; // neighbours of every particle, in list order

/// Every b of xb with ||xa_i - xb_b|| < H (same floating-point predicate as the contract: squared
/// distance < H^2), excluding b = i when the sets are the same.
Lists bruteForce(const Positions& xa, const Positions& xb, double h, bool self) {
  Lists result(xa.size());
  for (std::size_t i = 0; i < xa.size(); ++i)
    for (std::size_t j = 0; j < xb.size(); ++j)
      if (!(self && i == j) && (xa[i] - xb[j]).squaredNorm() < h * h) result[i].push_back(static_cast<Index>(j));
  return result;
}

Lists toLists(const NeighbourList& list) {
  Lists result(list.particles());
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < list.particles(); ++i) {
    EXPECT_EQ(list.offset(i), pairs) << "per-pair data of particle " << i << " starts after the pairs before it";
    for (Index j : list.of(i)) result[i].push_back(j);
    pairs += list.of(i).size();
  }
  EXPECT_EQ(list.totalPairs(), pairs);
  return result;
}

/// Same neighbour sets per particle (the order of a list is the search's own, fixed order).
void expectSameSets(Lists found, Lists expected, const char* what) {
  ASSERT_EQ(found.size(), expected.size()) << what;
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < found.size(); ++i) {
    std::sort(found[i].begin(), found[i].end());
    ASSERT_TRUE(std::adjacent_find(found[i].begin(), found[i].end()) == found[i].end())
        << what << ": duplicate in " << i;
    std::sort(expected[i].begin(), expected[i].end());
    if (found[i] != expected[i] && ++mismatches <= 5)
      ADD_FAILURE() << what << ": particle " << i << " has " << found[i].size() << " neighbours, brute force "
                    << expected[i].size();
  }
  EXPECT_EQ(mismatches, 0u) << what;
}

/// Restores the thread count a test changed.
class ThreadGuard {
public:
  ThreadGuard() : threads_(parallel::threads()) {}
  ~ThreadGuard() { parallel::setThreads(threads_); }

private:
  int threads_;
};

/// Searches all wanted pairs with 1 and with 2 threads; checks both against brute force and against each other
/// (identical lists in identical order).
void checkAgainstBruteForce(const std::vector<const Positions*>& sets, const std::vector<std::vector<bool>>& wanted,
                            double h) {
  ThreadGuard guard;
  std::vector<Lists> byThreads[2];
  for (int t = 1; t <= 2; ++t) {
    parallel::setThreads(t);
    NeighbourSearch search(h);
    search.update(sets, wanted);
    for (std::size_t a = 0; a < sets.size(); ++a)
      for (std::size_t b = 0; b < sets.size(); ++b) {
        const NeighbourList& list = search.list(a, b);
        if (!wanted[a][b]) {
          EXPECT_EQ(list.totalPairs(), 0u) << a << "->" << b << " was not requested";
          EXPECT_EQ(list.particles(), 0u) << a << "->" << b << " was not requested";
          byThreads[t - 1].push_back({});
          continue;
        }
        ASSERT_EQ(list.particles(), sets[a]->size());
        const Lists found = toLists(list);
        const std::string what = std::to_string(a) + "->" + std::to_string(b) + ", " + std::to_string(t) + " thread(s)";
        expectSameSets(found, bruteForce(*sets[a], *sets[b], h, a == b), what.c_str());
        byThreads[t - 1].push_back(found);
      }
  }
  EXPECT_TRUE(byThreads[0] == byThreads[1]) << "lists differ between 1 and 2 threads";
}

Positions randomPoints(std::size_t n, const Vec3& lo, const Vec3& hi, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Positions x(n);
  for (auto& p : x) p = lo + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(hi - lo);
  return x;
}

TEST(NeighbourSearch, RandomPointsOneSet) {
  const double h = 0.04;
  // ~30 neighbours per particle, several chunks of the parallel build.
  Positions x = randomPoints(3000, Vec3::Zero(), Vec3(0.3, 0.3, 0.3), 1);
  // Pin the grid origin to 0 (the lower corner of the bounding box) and put points exactly on cell faces,
  // edges and corners k H, plus pairs at (nearly, in floating point) distance H across them.
  x.emplace_back(0.0, 0.0, 0.0);
  for (int k = 1; k <= 6; ++k) {
    x.emplace_back(k * h, 0.1, 0.1);
    x.emplace_back(k * h, k * h, 0.2);
    x.emplace_back(k * h, k * h, k * h);
    x.emplace_back(k * h + h, k * h, k * h);
    x.emplace_back(0.05, k * h, 0.05 + h);
  }
  checkAgainstBruteForce({&x}, {{true}}, h);
}

// Lists hold indices in 3 bytes up to 2^24 particles and in 4 beyond. Runs of indices are written by different
// threads in any order: each must leave the bytes after its last index alone (stored here back to front).
TEST(PackedIndices, ThreeBytesUpTo2To24ParticlesFourBeyondAndRunsLeaveTheirNeighboursAlone) {
  for (const std::size_t particles : {std::size_t{1} << 24, (std::size_t{1} << 24) + 1}) {
    const Index largest = static_cast<Index>(particles - 1);
    const std::vector<Index> values{0, 1, 255, 256, 65535, 0x00ab'cdef & largest, 65536, largest, 7, largest};
    PackedIndices packed;
    packed.setWidthFor(particles);
    EXPECT_EQ(packed.width(), particles <= (std::size_t{1} << 24) ? 3u : 4u);
    packed.resize(values.size());
    const std::size_t half = values.size() / 2;
    packed.store(half, values.data() + half, values.data() + values.size());
    packed.store(0, values.data(), values.data() + half);
    for (std::size_t k = 0; k < values.size(); ++k)
      EXPECT_EQ(*packed.at(k), values[k]) << particles << " particles, index " << k;
  }
}

// 20,000 particles are 40 chunks of the list build, assembled in rounds (three with one thread, two with two):
// each round's pairs must land at the offsets the rounds before it left, with and without the skin.
TEST(NeighbourSearch, ListsOfManyChunksAreAssembledInRounds) {
  ThreadGuard guard;
  const double h = 0.04;
  const Positions x = randomPoints(20000, Vec3::Zero(), Vec3(0.6, 0.6, 0.6), 5); // about 25 neighbours each
  std::vector<Lists> byRun;
  for (int t = 1; t <= 2; ++t)
    for (const double skin : {0.0, 0.1 * h}) {
      parallel::setThreads(t);
      NeighbourSearch search(h, skin);
      search.update({&x}, {{true}});
      const Lists found = toLists(search.list(0, 0));
      ASSERT_EQ(found.size(), x.size());
      for (std::size_t i = 0; i < x.size(); i += 97) { // a sample, against brute force for that particle
        Positions one{x[i]};
        Lists expected = bruteForce(one, x, h, false);
        expected[0].erase(std::remove(expected[0].begin(), expected[0].end(), static_cast<Index>(i)),
                          expected[0].end());
        expectSameSets({found[i]}, expected, ("particle " + std::to_string(i)).c_str());
      }
      std::size_t pairs = 0;
      for (const auto& l : found) pairs += l.size();
      EXPECT_EQ(pairs, search.list(0, 0).totalPairs());
      byRun.push_back(found);
    }
  EXPECT_TRUE(byRun[0] == byRun[2]) << "lists at H differ between 1 and 2 threads";
  EXPECT_TRUE(byRun[1] == byRun[3]) << "lists with the skin differ between 1 and 2 threads";
}

// A dense clump: rows of the grid search hold hundreds of candidates, so the distance tests run in several
// blocks of 64 (and remainders that are not whole vectors of four), with and without the skin.
TEST(NeighbourSearch, DenseClumpEqualsBruteForce) {
  const double h = 0.04;
  Positions clump = randomPoints(2500, Vec3::Zero(), Vec3(0.1, 0.05, 0.05), 21);
  const Positions sparse = randomPoints(300, Vec3(-0.1, -0.1, -0.1), Vec3(0.2, 0.15, 0.15), 22);
  checkAgainstBruteForce({&clump, &sparse}, {{true, true}, {true, true}}, h);
  NeighbourSearch search(h, 0.1 * h);
  search.update({&clump, &sparse}, {{true, true}, {true, true}});
  expectSameSets(toLists(search.list(0, 0)), bruteForce(clump, clump, h, true), "skin, clump->clump");
  expectSameSets(toLists(search.list(1, 0)), bruteForce(sparse, clump, h, false), "skin, sparse->clump");
}

TEST(NeighbourSearch, PairsAtExactlyHAreExcluded) {
  // Dyadic coordinates and H = 1/4: every difference and squared distance is exact, so pairs at exactly H
  // are exactly H apart and must be missing, while pairs a hair closer are present.
  const double h = 0.25;
  Positions x;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i) x.emplace_back(0.125 * i, 0.125 * j, 0.25 * k); // H/2 and H spacings
  x.emplace_back(0.25 - 1.0 / 1024, 0.0, 0.5);                                    // just inside H of (0, 0, 0.5)
  checkAgainstBruteForce({&x}, {{true}}, h);
  NeighbourSearch search(h);
  search.update({&x}, {{true}});
  const auto& list = search.list(0, 0);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (Index j : list.of(i)) ASSERT_LT((x[i] - x[static_cast<std::size_t>(j)]).norm(), h);
  // (0,0,0): 6 x 6 points of spacing H/2 in its plane and in the planes at +-H: only (H/2,0,0), (0,H/2,0),
  // (H/2,H/2,0) are strictly inside.
  EXPECT_EQ(list.of(0).size(), 3u);
}

TEST(NeighbourSearch, PairsWithinRoundOffOfHAcrossCells) {
  // Coordinates accumulated as h + h + ... (not k h) along one axis from 0: some consecutive pairs are one ulp
  // closer than H in floating point (so they are neighbours), yet their coordinates divided by H round into
  // cells two apart (e.g. 0.7999999999999999 and 0.8999999999999999 for H = 0.1: cells 7 and 9). A grid whose
  // cells are exactly H wide misses such pairs.
  int straddling = 0;
  for (double h : {0.1, 0.05}) {
    Positions row;
    double acc = 0.0;
    for (int k = 0; k <= 40; ++k, acc += h) row.push_back(Vec3(acc, 0.0, 0.0));
    for (std::size_t k = 0; k + 1 < row.size(); ++k)
      if ((row[k + 1] - row[k]).squaredNorm() < h * h &&
          std::floor(row[k + 1].x() * (1.0 / h)) - std::floor(row[k].x() * (1.0 / h)) >= 2.0)
        ++straddling; // cell index as x * (1/H), the usual way a grid computes it
    for (int axis = 0; axis < 3; ++axis) {
      Positions x;
      for (const Vec3& p : row) {
        Vec3 q = Vec3::Zero();
        q[axis] = p.x();
        x.push_back(q);
      }
      checkAgainstBruteForce({&x}, {{true}}, h);
    }
  }
  EXPECT_GT(straddling, 0) << "the input no longer contains the round-off case it is meant to test";
}

TEST(NeighbourSearch, LatticeInput) {
  const double r = 0.01, h = 4.0 * r, spacing = 2.0 * r;
  Positions x;
  for (int k = 0; k < 12; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) x.emplace_back(0.31 + spacing * i, -0.07 + spacing * j, 1.3 + spacing * k);
  checkAgainstBruteForce({&x}, {{true}}, h);
}

TEST(NeighbourSearch, TwoSetsAndAnUnwantedPair) {
  const double h = 0.04;
  const Positions a = randomPoints(2000, Vec3::Zero(), Vec3(0.25, 0.25, 0.25), 2);
  const Positions b = randomPoints(1500, Vec3(0.1, 0.05, 0.1), Vec3(0.4, 0.3, 0.3), 3); // partial overlap
  // a->a, a->b, b->a wanted; b->b is not and must stay empty.
  checkAgainstBruteForce({&a, &b}, {{true, true}, {true, false}}, h);
  // A lattice set together with a random one.
  Positions lattice;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) lattice.emplace_back(0.01 + 0.02 * i, 0.01 + 0.02 * j, -0.01 - 0.02 * k);
  checkAgainstBruteForce({&lattice, &a}, {{true, true}, {true, true}}, h);
}

TEST(NeighbourSearch, EmptySets) {
  const double h = 0.04;
  const Positions empty;
  const Positions some = randomPoints(100, Vec3::Zero(), Vec3(0.1, 0.1, 0.1), 4);
  NeighbourSearch search(h);
  search.update({&empty}, {{true}});
  EXPECT_EQ(search.list(0, 0).particles(), 0u);
  EXPECT_EQ(search.list(0, 0).totalPairs(), 0u);
  search.update({&empty, &some}, {{true, true}, {true, true}});
  EXPECT_EQ(search.list(0, 1).particles(), 0u);
  EXPECT_EQ(search.list(1, 0).particles(), some.size());
  EXPECT_EQ(search.list(1, 0).totalPairs(), 0u);
  EXPECT_GT(search.list(1, 1).totalPairs(), 0u);
  checkAgainstBruteForce({&empty, &some}, {{true, true}, {true, true}}, h);
  EXPECT_TRUE(search.mortonOrder(empty).empty());
}

TEST(NeighbourSearch, NonFinitePositionThrows) {
  NeighbourSearch search(0.04);
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (double v : bad) {
    Positions x = randomPoints(50, Vec3::Zero(), Vec3(0.1, 0.1, 0.1), 5);
    const Positions fine = x;
    x[17].y() = v;
    EXPECT_THROW(search.update({&x}, {{true}}), NumericalError);
    EXPECT_THROW(search.update({&fine, &x}, {{true, false}, {false, false}}), NumericalError); // even if unsearched
    EXPECT_THROW(search.mortonOrder(x), NumericalError);
  }
}

// With the skin, a position that turns non-finite after the grid search stops the run as the grid search does,
// instead of dropping out of every list.
TEST(NeighbourSearch, NonFinitePositionThrowsWithTheSkinToo) {
  for (double v : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    NeighbourSearch search(0.04, 0.004);
    Positions x = randomPoints(500, Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 6);
    search.update({&x}, {{true}});
    x[17].y() = v;
    EXPECT_THROW(search.update({&x}, {{true}}), NumericalError);
  }
}

/// Cell of p in a grid of cell size h anchored at lo (independent of the search's internals).
std::array<long long, 3> cellOf(const Vec3& p, const Vec3& lo, double h) {
  return {static_cast<long long>(std::floor((p.x() - lo.x()) / h)),
          static_cast<long long>(std::floor((p.y() - lo.y()) / h)),
          static_cast<long long>(std::floor((p.z() - lo.z()) / h))};
}

TEST(NeighbourSearch, MortonOrderIsAPermutationGroupingCells) {
  const double h = 0.04;
  // Coordinates at cell centres + jitter well away from cell faces, so the test's own cell assignment cannot
  // disagree with the search's by round-off.
  std::mt19937_64 rng(6);
  std::uniform_int_distribution<int> cell(0, 9);
  std::uniform_real_distribution<double> jitter(0.1 * h, 0.9 * h);
  Positions x(4000);
  for (auto& p : x) p = Vec3(cell(rng) * h + jitter(rng), cell(rng) * h + jitter(rng), cell(rng) * h + jitter(rng));
  x[0] = Vec3::Zero(); // fixes the grid origin
  const NeighbourSearch search(h);
  const std::vector<Index> order = search.mortonOrder(x);
  ASSERT_EQ(order.size(), x.size());
  std::vector<Index> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Index> identity(x.size());
  std::iota(identity.begin(), identity.end(), Index{0});
  ASSERT_EQ(sorted, identity);
  // Particles of one cell are consecutive, and keep their original order (stable).
  std::map<std::array<long long, 3>, std::pair<std::size_t, Index>> last; // cell -> (position in order, index)
  for (std::size_t n = 0; n < order.size(); ++n) {
    const auto c = cellOf(x[static_cast<std::size_t>(order[n])], Vec3::Zero(), h);
    const auto it = last.find(c);
    if (it != last.end()) {
      EXPECT_EQ(it->second.first, n - 1) << "cell split in the Morton order";
      EXPECT_LT(it->second.second, order[n]) << "not stable";
    }
    last[c] = {n, order[n]};
  }
  // Morton order of the 2 x 2 x 2 block of cells at the origin: x fastest, then y, then z.
  const std::array<long long, 3> zOrder[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                              {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  std::vector<std::array<long long, 3>> seen;
  for (Index i : order) {
    const auto c = cellOf(x[static_cast<std::size_t>(i)], Vec3::Zero(), h);
    if (c[0] < 2 && c[1] < 2 && c[2] < 2 && (seen.empty() || seen.back() != c)) seen.push_back(c);
  }
  ASSERT_EQ(seen.size(), 8u);
  for (int n = 0; n < 8; ++n) EXPECT_EQ(seen[static_cast<std::size_t>(n)], zOrder[n]) << n;
}

// With a skin the Morton order groups the grid search's cells, H + skin wide on multiples of their width
// (the lower corner of the particles need not be on one): each cell of the grid search is then a run of
// consecutive indices, and its candidates come out as a few ascending runs.
TEST(NeighbourSearch, MortonOrderWithASkinGroupsTheGridSearchsCells) {
  const double h = 0.04;
  const double skin = 0.1 * h;
  const double cell = h + skin; // the grid's widening (1e-6) is far below the jitter's margin
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> index(0, 7);
  std::uniform_real_distribution<double> jitter(0.1 * cell, 0.9 * cell);
  Positions x(3000);
  for (auto& p : x)
    p = Vec3((index(rng) + 3) * cell + jitter(rng), (index(rng) - 5) * cell + jitter(rng),
             index(rng) * cell + jitter(rng));
  const std::vector<Index> order = NeighbourSearch(h, skin).mortonOrder(x);
  std::map<std::array<long long, 3>, std::size_t> lastSeen; // cell -> position in the order
  for (std::size_t n = 0; n < order.size(); ++n) {
    const auto c = cellOf(x[static_cast<std::size_t>(order[n])], Vec3::Zero(), cell);
    const auto it = lastSeen.find(c);
    if (it != lastSeen.end()) {
      EXPECT_EQ(it->second, n - 1) << "cell split in the Morton order";
    }
    lastSeen[c] = n;
  }
  EXPECT_GT(lastSeen.size(), 400u); // most of the 512 cells hold particles: the check above had work to do
}

TEST(NeighbourSearch, PermuteMovesEveryFieldTogether) {
  const double h = 0.04;
  const std::size_t n = 1500;
  ParticleSet set("porous", SetKind::Porous);
  set.particleVolume = 8e-6;
  set.mass = 0.016;
  set.restDensity = 2000.0;
  auto& p = set.addReal("p", Output);
  auto& F = set.addMat3("F", Restart);
  auto& state = set.addInt("state", Restart);
  auto& scratch = set.addVec3("scratch");
  set.resize(n);
  const Positions x0 = randomPoints(n, Vec3(-0.2, 0.0, 0.1), Vec3(0.2, 0.3, 0.3), 8);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    set.integer(field::id)[i] = static_cast<std::int64_t>(1000 + 3 * i); // unique ids, not equal to the slot
    set.integer(field::objectId)[i] = static_cast<std::int64_t>(i % 3);
    set.x()[i] = x0[i];
    set.v()[i] = Vec3(u(rng), u(rng), u(rng));
    p[i] = u(rng);
    F[i] = Mat3::Random();
    state[i] = static_cast<std::int64_t>(i % 2);
    scratch[i] = Vec3(u(rng), u(rng), u(rng));
  }
  // Snapshot keyed by id: every field of every particle.
  using Row = std::tuple<std::int64_t, Vec3, Vec3, double, Mat3, std::int64_t, Vec3>;
  auto snapshot = [&]() {
    std::map<std::int64_t, Row> rows;
    for (std::size_t i = 0; i < set.size(); ++i)
      rows[set.integer(field::id)[i]] = {set.integer(field::objectId)[i],
                                         set.x()[i],
                                         set.v()[i],
                                         set.real("p")[i],
                                         set.mat3("F")[i],
                                         set.integer("state")[i],
                                         set.vec3("scratch")[i]};
    return rows;
  };
  const auto before = snapshot();
  ASSERT_EQ(before.size(), n);
  const auto fieldsBefore = set.fields();
  const std::vector<std::int64_t> idsBefore = set.integer(field::id);
  const auto* pAddress = &p;

  const std::vector<Index> order = NeighbourSearch(h).mortonOrder(set.x());
  set.permute(order);

  // New slot i holds old slot order[i], for every field.
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(set.integer(field::id)[i], idsBefore[static_cast<std::size_t>(order[i])]);
  EXPECT_NE(set.integer(field::id), idsBefore) << "the Morton order of random points is not the identity";
  // Same multiset of (id, all values): nothing changed but the slots.
  const auto after = snapshot();
  ASSERT_EQ(after.size(), n);
  for (const auto& [id, row] : before) {
    const auto it = after.find(id);
    ASSERT_TRUE(it != after.end()) << "id " << id << " lost";
    EXPECT_TRUE(it->second == row) << "id " << id << " changed its values";
  }
  // Registry, set constants and field references are unchanged.
  EXPECT_EQ(set.size(), n);
  const auto fieldsAfter = set.fields();
  ASSERT_EQ(fieldsAfter.size(), fieldsBefore.size());
  for (std::size_t f = 0; f < fieldsAfter.size(); ++f) {
    EXPECT_EQ(fieldsAfter[f].name, fieldsBefore[f].name);
    EXPECT_EQ(fieldsAfter[f].type, fieldsBefore[f].type);
    EXPECT_EQ(fieldsAfter[f].role, fieldsBefore[f].role);
  }
  EXPECT_EQ(set.particleVolume, 8e-6);
  EXPECT_EQ(set.mass, 0.016);
  EXPECT_EQ(set.restDensity, 2000.0);
  EXPECT_EQ(&set.real("p"), pAddress);
  // Sorting twice is idempotent: the sorted set is already in Morton order.
  const std::vector<Index> again = NeighbourSearch(h).mortonOrder(set.x());
  std::vector<Index> identity(n);
  std::iota(identity.begin(), identity.end(), Index{0});
  EXPECT_EQ(again, identity);
  // A wrong-length order is a logic error and leaves the set alone.
  EXPECT_THROW(set.permute(std::vector<Index>(n - 1, 0)), std::logic_error);
  EXPECT_EQ(set.size(), n);
}

TEST(NeighbourSearch, ListsFollowAPermutation) {
  // Searching after sorting gives the same neighbour pairs, renamed by the permutation.
  const double h = 0.04;
  const Positions x = randomPoints(2500, Vec3::Zero(), Vec3(0.3, 0.2, 0.3), 10);
  NeighbourSearch search(h);
  const std::vector<Index> order = search.mortonOrder(x);
  Positions sorted(x.size());
  std::vector<Index> newSlot(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    sorted[i] = x[static_cast<std::size_t>(order[i])];
    newSlot[static_cast<std::size_t>(order[i])] = static_cast<Index>(i);
  }
  search.update({&x}, {{true}});
  Lists original = toLists(search.list(0, 0));
  search.update({&sorted}, {{true}});
  const Lists renamed = toLists(search.list(0, 0));
  Lists expected(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (Index j : original[static_cast<std::size_t>(order[i])])
      expected[i].push_back(newSlot[static_cast<std::size_t>(j)]);
  expectSameSets(renamed, expected, "sorted");
}

// Verlet lists: with a skin, every update's lists equal the brute-force search at H while the particles move,
// whether the update reused the candidates or searched the grid again.
TEST(NeighbourSearch, SkinListsEqualBruteForceWhileParticlesMove) {
  const double h = 0.04;
  const double skin = 0.2 * h;
  Positions fluid = randomPoints(2000, Vec3::Zero(), Vec3(0.25, 0.25, 0.25), 7);
  const Positions wall = randomPoints(800, Vec3(-0.05, -0.05, -0.05), Vec3(0.3, 0.0, 0.3), 8);
  const std::vector<const Positions*> sets{&fluid, &wall};
  const std::vector<std::vector<bool>> wanted{{true, true}, {false, false}};
  NeighbourSearch search(h, skin);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int updates = 30;
  for (int step = 0; step < updates; ++step) {
    search.update(sets, wanted);
    const std::string what = "update " + std::to_string(step);
    expectSameSets(toLists(search.list(0, 0)), bruteForce(fluid, fluid, h, true), (what + ", fluid->fluid").c_str());
    expectSameSets(toLists(search.list(0, 1)), bruteForce(fluid, wall, h, false), (what + ", fluid->wall").c_str());
    // Even and odd particles move apart at 0.3 skin per update (plus noise): the candidates last a few
    // updates, and pairs cross from beyond H + skin into H within the run.
    for (std::size_t i = 0; i < fluid.size(); ++i)
      fluid[i] += 0.15 * skin * Vec3(i % 2 == 0 ? 1.0 : -1.0, 0.0, 0.0) + 0.02 * skin * Vec3(u(rng), u(rng), u(rng));
    // Now and then one particle jumps a whole H: its old candidates cannot hold its new neighbours.
    if (step % 7 == 3) fluid[static_cast<std::size_t>(step)] += Vec3(h, 0.0, 0.0);
  }
  EXPECT_EQ(search.updates(), static_cast<std::size_t>(updates));
  EXPECT_GT(search.gridSearches(), 4u) << "the jumps must force grid searches";
  EXPECT_LT(search.gridSearches(), search.updates()) << "the candidates were never reused";
}

// The candidates are kept as 16-bit steps between ascending indices, a step of 2^16 or more as an escape and the
// index in full. Neighbours whose indices lie further apart than that (a large wall set, any order) must come
// back exactly: a first candidate beyond 2^16, steps of 2^16 - 1 (the largest step in one code), 2^16 and more.
TEST(NeighbourSearch, CandidatesFarApartInIndexKeepTheirLists) {
  const double h = 0.04;
  const double skin = 0.1 * h;
  const std::size_t n = 200000;
  Positions wall = randomPoints(n, Vec3(1.0, 1.0, 1.0), Vec3(1.3, 1.3, 1.3), 21); // far from the fluid
  const Vec3 first(0.1, 0.1, 0.1), second(0.5, 0.5, 0.5);
  const std::vector<std::size_t> nearFirst{0, 1, 65536, 131072, 131073, n - 1}; // steps 65535, 65536, 68926
  const std::vector<std::size_t> nearSecond{70000, 140000, 140001};             // the first beyond 2^16
  for (std::size_t k = 0; k < nearFirst.size(); ++k) wall[nearFirst[k]] = first + Vec3(0.003 * k, 0.0, 0.0);
  for (std::size_t k = 0; k < nearSecond.size(); ++k) wall[nearSecond[k]] = second + Vec3(0.0, 0.003 * k, 0.0);
  Positions fluid{first + Vec3(0.0, 0.01, 0.0), second + Vec3(0.01, 0.0, 0.0), Vec3(0.3, 0.3, 0.3)};
  const std::vector<const Positions*> sets{&fluid, &wall};
  const std::vector<std::vector<bool>> wanted{{true, true}, {false, false}};
  NeighbourSearch search(h, skin);
  for (int step = 0; step < 3; ++step) { // the grid search, then lists from its candidates
    search.update(sets, wanted);
    const Lists found = toLists(search.list(0, 1));
    ASSERT_EQ(found.size(), 3u);
    const std::vector<Index> firstExpected(nearFirst.begin(), nearFirst.end());
    const std::vector<Index> secondExpected(nearSecond.begin(), nearSecond.end());
    EXPECT_EQ(found[0], firstExpected) << "update " << step;
    EXPECT_EQ(found[1], secondExpected) << "update " << step;
    EXPECT_TRUE(found[2].empty()) << "update " << step;
    for (Vec3& p : fluid) p += Vec3(0.1 * skin, 0.0, 0.0);
  }
  EXPECT_EQ(search.gridSearches(), 1u) << "the lists after the first must come from the candidates";
}

// Where particles stood at the grid search is kept in single precision. Two particles that each moved just over
// skin / 2 towards each other, whose rounded start positions make each move look shorter than skin / 2, must still
// be searched afresh: their pair, beyond H + skin then, is within H now. At 1000 m a float is 2^-14 m coarse.
TEST(NeighbourSearch, MoversAreFoundThoughTheirStartPositionsAreRounded) {
  const double u = std::ldexp(1.0, -14);
  const double h = 720.9 * u / 1.1 - 1e-9; // H + skin a hair below 720.9 u
  const double skin = 0.1 * h;
  Positions x = randomPoints(200, Vec3(1000.5, 1000.5, 1000.5), Vec3(1001.0, 1001.0, 1001.0), 5);
  const Vec3 a(1000.0 + 100.55 * u, 1000.25, 1000.25); // rounds up by 0.45 u
  const Vec3 b(1000.0 + 821.45 * u, 1000.25, 1000.25); // 720.9 u further: rounds down by 0.45 u
  x.push_back(a);
  x.push_back(b);
  const std::vector<const Positions*> sets{&x};
  NeighbourSearch search(h, skin);
  search.update(sets, {{true}});
  ASSERT_TRUE(toLists(search.list(0, 0))[200].empty());
  const double step = 0.5 * skin + 1e-5; // over skin / 2, but under it by the rounded start (0.45 u = 2.7e-5)
  x[200] += Vec3(step, 0.0, 0.0);
  x[201] -= Vec3(step, 0.0, 0.0);
  ASSERT_LT((x[200] - x[201]).norm(), h);
  search.update(sets, {{true}});
  EXPECT_EQ(search.gridSearches(), 1u) << "two movers among 202 particles use the candidates";
  expectSameSets(toLists(search.list(0, 0)), bruteForce(x, x, h, true), "after the two moved");
}

// The grid search tests the candidates in float, relative to the grid's origin, so a pair a hair closer than H + skin
// may round to beyond it. Pairs there whose particles then each move just under skin / 2 towards the other (not
// movers) must be in the lists: the float test keeps a margin for the rounding. A particle 100 m away puts the pairs
// 100 m from the origin, where a float is 2^-17 m (7.6 um) coarse, while their own coordinates stay small, so that
// the movers' test (start positions rounded by 2^-24 of them) finds no movers.
TEST(NeighbourSearch, CandidatesTestedInFloatKeepPairsAHairWithinHPlusSkin) {
  const double h = 0.04, skin = 0.1 * h;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Positions x{Vec3(-100.0, 0.0, 0.0)};
  std::vector<Vec3> towards;
  for (int k = 0; k < 100; ++k) {
    const Vec3 centre = Vec3(0.05, 0.05, 0.05) + 0.4 * Vec3(unit(rng), unit(rng), unit(rng));
    const Vec3 e = Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized();
    const double apart = h + skin - (5e-7 + 1.5e-5 * unit(rng));
    x.push_back(centre - 0.5 * apart * e);
    x.push_back(centre + 0.5 * apart * e);
    towards.push_back(e * (0.5 * (apart - h) + 5e-9)); // then 1e-8 within H
  }
  const std::vector<const Positions*> sets{&x};
  NeighbourSearch search(h, skin);
  search.update(sets, {{true}});
  for (std::size_t k = 0; k < towards.size(); ++k) {
    x[1 + 2 * k] += towards[k];
    x[2 + 2 * k] -= towards[k];
  }
  search.update(sets, {{true}});
  ASSERT_EQ(search.gridSearches(), 1u) << "no movers: the lists come from the candidates";
  expectSameSets(toLists(search.list(0, 0)), bruteForce(x, x, h, true), "pairs a hair within H + skin at 100 m");
}

// With the skin a list is a function of the positions alone: a search with a history and a fresh one list
// the same neighbours in the same (ascending) order. This is what lets a run restarted at any step (a
// signal, a NaN between writes) continue bit for bit.
TEST(NeighbourSearch, SkinListsDoNotDependOnTheSearchHistory) {
  const double h = 0.04;
  Positions x = randomPoints(1500, Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 11);
  const std::vector<const Positions*> sets{&x};
  const std::vector<std::vector<bool>> wanted{{true}};
  NeighbourSearch used(h, 0.1 * h);
  for (int step = 0; step < 6; ++step) {
    used.update(sets, wanted);
    NeighbourSearch fresh(h, 0.1 * h);
    fresh.update(sets, wanted);
    const Lists lists = toLists(used.list(0, 0));
    EXPECT_TRUE(lists == toLists(fresh.list(0, 0))) << "step " << step;
    for (const auto& l : lists) EXPECT_TRUE(std::is_sorted(l.begin(), l.end()));
    NeighbourSearch direct(h);
    direct.update(sets, wanted);
    expectSameSets(lists, toLists(direct.list(0, 0)), ("step " + std::to_string(step)).c_str());
    for (auto& p : x) p += Vec3(0.0007, -0.0004, 0.0005); // 0.024 H a step: candidates last two steps
  }
  EXPECT_LT(used.gridSearches(), used.updates()) << "the candidates were never reused";
}

// Particles that swing back and forth (never far enough to be movers) make pairs cross H both ways again and
// again within one set of candidates: every update's lists must be those of a fresh search, in the same ascending
// order, for a set with itself and with another.
TEST(NeighbourSearch, PairsCrossingHBothWaysKeepTheListsOfAFreshSearch) {
  const double h = 0.04, skin = 0.1 * h;
  const Positions rest = randomPoints(1500, Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 13);
  const Positions wall = randomPoints(600, Vec3(-0.02, -0.02, -0.02), Vec3(0.22, 0.0, 0.22), 14);
  Positions x = rest;
  const std::vector<const Positions*> sets{&x, &wall};
  const std::vector<std::vector<bool>> wanted{{true, true}, {false, false}};
  NeighbourSearch used(h, skin);
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> direction(x.size());
  for (Vec3& d : direction) d = Vec3(u(rng), u(rng), u(rng)).normalized();
  std::size_t changed = 0;
  Lists before;
  for (int step = 0; step < 12; ++step) {
    for (std::size_t i = 0; i < x.size(); ++i) // within skin / 4 of the rest position: never a mover
      x[i] = rest[i] + 0.24 * skin * std::sin(1.3 * step + static_cast<double>(i)) * direction[i];
    used.update(sets, wanted);
    NeighbourSearch fresh(h, skin);
    fresh.update(sets, wanted);
    for (std::size_t b = 0; b < 2; ++b) {
      const Lists lists = toLists(used.list(0, b));
      EXPECT_TRUE(lists == toLists(fresh.list(0, b))) << "step " << step << ", list 0->" << b;
      if (b == 0 && step > 0) changed += lists != before;
      if (b == 0) before = lists;
    }
  }
  EXPECT_EQ(used.gridSearches(), 1u) << "the candidates served every update";
  EXPECT_GT(changed, 5u) << "pairs crossed H between updates";
}

// A set that changed size (particles removed by the health checks) is searched again, never filtered
// with stale indices.
TEST(NeighbourSearch, SkinSearchRebuildsWhenASetChangesSize) {
  const double h = 0.04;
  Positions x = randomPoints(1000, Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 12);
  const std::vector<const Positions*> sets{&x};
  const std::vector<std::vector<bool>> wanted{{true}};
  NeighbourSearch search(h, 0.1 * h);
  search.update(sets, wanted);
  x.erase(x.begin() + 10, x.begin() + 20);
  search.update(sets, wanted);
  EXPECT_EQ(search.gridSearches(), 2u);
  expectSameSets(toLists(search.list(0, 0)), bruteForce(x, x, h, true), "after removal");
}

// A flow whose largest step would cross the skin within two updates is searched at H at every update, in
// the stencil order of a search without a skin, and stays exact.
TEST(NeighbourSearch, SkinSearchOfAFastFlowSearchesAtHEveryUpdate) {
  const double h = 0.04;
  const double skin = 0.1 * h;
  Positions x = randomPoints(1000, Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 13);
  const std::vector<const Positions*> sets{&x};
  const std::vector<std::vector<bool>> wanted{{true}};
  NeighbourSearch search(h, skin);
  const double step = 0.3 * skin;
  for (int n = 0; n < 10; ++n) {
    search.update(sets, wanted, step);
    NeighbourSearch direct(h);
    direct.update(sets, wanted);
    EXPECT_TRUE(toLists(search.list(0, 0)) == toLists(direct.list(0, 0))) << "update " << n;
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += step * Vec3(i % 2 == 0 ? 1.0 : -1.0, 0.0, 0.0);
  }
  EXPECT_EQ(search.gridSearches(), search.updates());
}

// A few particles that outrun the skin (a jet, a splash: "movers") are searched afresh at every update and
// added to the lists of the particles they come near; the others keep their candidates. The lists stay exact
// and ascending, the same as a fresh search's, while the movers leave the grid of the last grid search on
// every side, and only a crowd of movers makes the search run the grid again.
TEST(NeighbourSearch, AFewMoversDoNotForceGridSearches) {
  ThreadGuard guard;
  parallel::setThreads(2);
  const double h = 0.04;
  const double skin = 0.1 * h;
  Positions fluid = randomPoints(3000, Vec3::Zero(), Vec3(0.25, 0.25, 0.25), 21);
  Positions soil = randomPoints(1500, Vec3(0.0, -0.05, 0.0), Vec3(0.25, 0.05, 0.25), 22);
  Positions wall = randomPoints(800, Vec3(-0.05, -0.1, -0.05), Vec3(0.3, -0.05, 0.3), 23);
  const Positions none;
  // The wall is searched but gets no lists (a moving wall body), `none` is an empty set searched from the fluid.
  const std::vector<const Positions*> sets{&fluid, &soil, &wall, &none};
  const std::vector<std::vector<bool>> wanted{
      {true, true, true, true}, {true, true, true, false}, {false, false, false, false}, {false, false, false, false}};
  const std::vector<std::size_t> listed{2800, 1500, 800, 0}; // the last 200 fluid particles are ghosts
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // 24 fluid movers (some of them ghosts), 6 soil and 4 wall movers, 0.6 H an update, out of the box on every side.
  std::vector<std::pair<std::size_t, std::size_t>> movers;
  for (std::size_t i = 0; i < 24; ++i) movers.emplace_back(0, (137 * i + 11) % 3000);
  for (std::size_t i = 0; i < 6; ++i) movers.emplace_back(1, 211 * i + 5);
  for (std::size_t i = 0; i < 4; ++i) movers.emplace_back(2, 97 * i + 3);
  std::vector<Vec3> heading;
  for (std::size_t k = 0; k < movers.size(); ++k) {
    Vec3 d = Vec3::Zero();
    d[k % 3] = k % 2 == 0 ? 1.0 : -1.0;
    heading.push_back(0.6 * h * d);
  }
  // Two fluid movers and a soil mover that travel together within H of each other: pairs of movers.
  const std::array<std::pair<std::size_t, std::size_t>, 3> group{{{0, 1000}, {0, 1001}, {1, 700}}};
  const Vec3 groupStart = fluid[1000];
  fluid[1001] = groupStart + Vec3(0.3 * h, 0.0, 0.0);
  soil[700] = groupStart + Vec3(0.0, 0.3 * h, 0.0);
  auto at = [&](std::size_t set, std::size_t i) -> Vec3& { return set == 0 ? fluid[i] : set == 1 ? soil[i] : wall[i]; };
  auto expectExact = [&](const NeighbourSearch& search, const std::string& what) {
    NeighbourSearch fresh(h, skin);
    fresh.update(sets, wanted, 0.0, listed);
    for (std::size_t a = 0; a < 2; ++a)
      for (std::size_t b = 0; b < 4; ++b) {
        if (!wanted[a][b]) continue;
        const Lists got = toLists(search.list(a, b));
        EXPECT_TRUE(got == toLists(fresh.list(a, b)))
            << what << ", " << a << "->" << b << " differs from a fresh search";
        const Lists all = bruteForce(*sets[a], *sets[b], h, a == b);
        ASSERT_EQ(got.size(), all.size());
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < got.size(); ++i) wrong += got[i] != (i < listed[a] ? all[i] : std::vector<Index>{});
        EXPECT_EQ(wrong, 0u) << what << ", " << a << "->" << b << ": lists not the ascending brute-force ones";
      }
    const auto& together = search.list(0, 0).of(1000);
    EXPECT_TRUE(std::find(together.begin(), together.end(), Index(1001)) != together.end()) << what;
    const auto& across = search.list(1, 0).of(700);
    EXPECT_TRUE(std::find(across.begin(), across.end(), Index(1000)) != across.end()) << what;
  };
  NeighbourSearch search(h, skin);
  const int updates = 40;
  for (int step = 0; step < updates; ++step) {
    search.update(sets, wanted, 0.0, listed);
    expectExact(search, "update " + std::to_string(step));
    // Everyone drifts 0.01 skin an update (0.4 skin in all, below the half skin that makes a mover) ...
    const Vec3 drift = 0.01 * skin * Vec3(0.6, -0.8, 0.0);
    for (auto& p : fluid) p += drift;
    for (auto& p : soil) p += drift;
    // ... and the movers cross a cell of H + skin every two updates.
    for (std::size_t k = 0; k < movers.size(); ++k)
      at(movers[k].first, movers[k].second) += heading[k] + 0.1 * h * Vec3(u(rng), u(rng), u(rng));
    for (const auto& [set, i] : group) at(set, i) += Vec3(0.0, 0.02, 0.01);
    // One particle jumps away and comes back: a mover for one update, then one no more.
    fluid[2000] += (step == 5 ? 1.0 : step == 6 ? -1.0 : 0.0) * Vec3(0.7 * h, 0.0, 0.0);
  }
  EXPECT_EQ(search.gridSearches(), 1u) << "37 movers among 4,300 listed particles forced grid searches";
  // A crowd of movers (one particle in ten jumps half an H) makes the search run the grid again.
  for (std::size_t i = 0; i < fluid.size(); i += 10) fluid[i] += 0.5 * h * Vec3(u(rng), u(rng), u(rng)).normalized();
  search.update(sets, wanted, 0.0, listed);
  expectExact(search, "after the crowd moved");
  EXPECT_EQ(search.gridSearches(), 2u);
}

// A parallel run's ghosts (the last particles of a set) get empty lists but are found as neighbours of the others;
// the others' lists are those of a search of everything, in the same order, with and without the skin.
TEST(NeighbourSearch, ParticlesBeyondListedAreNeighboursWithoutListsOfTheirOwn) {
  const double h = 0.04;
  Positions fluid = randomPoints(1200, Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 14);
  const Positions wall = randomPoints(400, Vec3(-0.05, -0.05, -0.05), Vec3(0.25, 0.0, 0.25), 15);
  const std::vector<const Positions*> sets{&fluid, &wall};
  const std::vector<std::vector<bool>> wanted{{true, true}, {false, false}};
  const std::vector<std::size_t> listed{900, 400};
  for (const double skin : {0.0, 0.1 * h}) {
    NeighbourSearch some(h, skin);
    for (int step = 0; step < 3; ++step) {
      some.update(sets, wanted, 0.0, listed);
      NeighbourSearch all(h, skin);
      all.update(sets, wanted);
      for (std::size_t b = 0; b < 2; ++b) {
        const Lists got = toLists(some.list(0, b));
        const Lists full = toLists(all.list(0, b));
        ASSERT_EQ(got.size(), fluid.size());
        for (std::size_t i = 0; i < fluid.size(); ++i)
          if (i < listed[0])
            EXPECT_EQ(got[i], full[i]) << "skin " << skin << ", step " << step << ", particle " << i;
          else
            EXPECT_TRUE(got[i].empty()) << "skin " << skin << ", step " << step << ", particle " << i;
      }
      for (auto& p : fluid) p += Vec3(0.0007, -0.0004, 0.0005);
    }
  }
}

} // namespace
} // namespace poro
