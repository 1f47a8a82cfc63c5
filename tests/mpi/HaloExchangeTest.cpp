// HaloExchange on real ranks: every rank receives exactly the other ranks' particles within the reach of its
// subdomain box, hence every neighbour (within the reach) of each of its own particles, with every field bit for bit,
// in rank order; refresh() updates only the fields it is given; a rebuild after motion drops the old ghosts.

#include "parallel/mpi/HaloExchange.hpp"
#include "MpiTestMain.hpp"
#include "parallel/HaloPattern.hpp"
#include "parallel/Partition.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace poro::test {
namespace {

constexpr double kReach = 0.08;

struct Global {
  std::vector<Vec3> x;
  std::vector<int> owner;
  std::vector<std::size_t> setOf; ///< 0 fluid, 1 boundary
};

Global globalCloud(int ranks) {
  Global g;
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < 3000; ++i) {
    g.x.emplace_back(u(rng), 0.5 * u(rng), 0.5 * u(rng));
    g.setOf.push_back(i < 2000 ? 0 : 1);
  }
  g.owner = Partition::build(g.x, std::vector<double>(g.x.size(), 1.0), ranks, PartitionMethod::RecursiveBisection)
                .owners(g.x);
  return g;
}

Mat3 tag(std::int64_t id) { return Mat3::Identity() * static_cast<double>(id) + Mat3::Ones(); }

/// This rank's particles of the global cloud, with fields derived from the id.
ParticleSystem ownShare(const Global& g, int rank) {
  ParticleSystem particles(0.01);
  ParticleSet* sets[2] = {&particles.add("fluid", SetKind::Fluid), &particles.add("boundary", SetKind::Boundary)};
  for (ParticleSet* set : sets) {
    set->addMat3("stress", Restart);
    set->addReal("pressure", Output);
  }
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    if (g.owner[i] != rank) continue;
    ParticleSet& set = *sets[g.setOf[i]];
    const std::size_t k = set.size();
    set.resize(k + 1);
    set.integer(field::id)[k] = static_cast<std::int64_t>(i);
    set.x()[k] = g.x[i];
    set.v()[k] = Vec3(static_cast<double>(i), -1.0, 0.5);
    set.mat3("stress")[k] = tag(static_cast<std::int64_t>(i));
  }
  return particles;
}

TEST(HaloExchange, GhostsAreTheOtherRanksParticlesWithinReachWithEveryField) {
  const Communicator& comm = mpiTestCommunicator();
  const Global g = globalCloud(comm.size());
  ParticleSystem particles = ownShare(g, comm.rank());
  HaloExchange halo;
  halo.build(particles, kReach, comm);

  Box mine;
  for (std::size_t i = 0; i < g.x.size(); ++i)
    if (g.owner[i] == comm.rank()) mine.add(g.x[i]);
  for (std::size_t s = 0; s < 2; ++s) {
    const ParticleSet& set = particles[s];
    ASSERT_EQ(set.size(), halo.owned(s) + halo.ghosts(s));
    std::set<std::int64_t> expected, needed, got;
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      if (g.setOf[i] != s || g.owner[i] == comm.rank()) continue;
      if (mine.distance(g.x[i]) <= kReach) expected.insert(static_cast<std::int64_t>(i));
      for (std::size_t k = 0; k < halo.owned(s) && needed.count(static_cast<std::int64_t>(i)) == 0; ++k)
        if ((set.x()[k] - g.x[i]).norm() < kReach) needed.insert(static_cast<std::int64_t>(i));
    }
    int lastOwner = -1;
    for (std::size_t k = halo.owned(s); k < set.size(); ++k) {
      const std::int64_t id = set.integer(field::id)[k];
      got.insert(id);
      const std::size_t i = static_cast<std::size_t>(id);
      EXPECT_NE(g.owner[i], comm.rank());
      EXPECT_GE(g.owner[i], lastOwner) << "ghosts in rank order";
      lastOwner = g.owner[i];
      EXPECT_EQ(set.x()[k], g.x[i]);
      EXPECT_EQ(set.v()[k], Vec3(static_cast<double>(i), -1.0, 0.5));
      EXPECT_EQ(set.mat3("stress")[k], tag(id));
    }
    EXPECT_EQ(got.size(), halo.ghosts(s)) << "a ghost received twice";
    EXPECT_EQ(got, expected) << "set " << s << " on rank " << comm.rank();
    for (const std::int64_t id : needed) EXPECT_EQ(got.count(id), 1u) << "neighbour " << id << " missing";
    if (comm.size() > 1) {
      EXPECT_GT(halo.ghosts(s), 0u);
    }
    // What this rank lent is what the others received from it.
    const long long lent = comm.sum(static_cast<long long>(halo.lent(s)));
    EXPECT_EQ(lent, comm.sum(static_cast<long long>(halo.ghosts(s))));
  }
}

TEST(HaloExchange, RefreshUpdatesTheNamedFieldsOnlyAndRebuildDropsOldGhosts) {
  const Communicator& comm = mpiTestCommunicator();
  const Global g = globalCloud(comm.size());
  ParticleSystem particles = ownShare(g, comm.rank());
  HaloExchange halo;
  halo.build(particles, kReach, comm);
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t k = 0; k < halo.owned(s); ++k) {
      const double id = static_cast<double>(particles[s].integer(field::id)[k]);
      particles[s].real("pressure")[k] = 1000.0 + id;
      particles[s].v()[k] = Vec3::Constant(-7.0); // changed, but not refreshed
    }
  halo.refresh(particles, {"pressure"}, comm);
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t k = halo.owned(s); k < particles[s].size(); ++k) {
      const std::int64_t id = particles[s].integer(field::id)[k];
      EXPECT_EQ(particles[s].real("pressure")[k], 1000.0 + static_cast<double>(id));
      EXPECT_EQ(particles[s].v()[k], Vec3(static_cast<double>(id), -1.0, 0.5));
    }

  // Everybody moves 0.3 along x: the ghosts of a rebuild are those within reach of the moved boxes.
  halo.dropGhosts(particles);
  for (std::size_t s = 0; s < 2; ++s)
    for (Vec3& x : particles[s].x()) x.x() += 0.3;
  halo.build(particles, kReach, comm);
  std::size_t ghosts = 0;
  for (std::size_t s = 0; s < 2; ++s) {
    std::set<std::int64_t> ids;
    for (std::size_t k = halo.owned(s); k < particles[s].size(); ++k) {
      ids.insert(particles[s].integer(field::id)[k]);
      EXPECT_EQ(particles[s].x()[k].x(), g.x[static_cast<std::size_t>(particles[s].integer(field::id)[k])].x() + 0.3);
    }
    EXPECT_EQ(ids.size(), halo.ghosts(s));
    ghosts += halo.ghosts(s);
  }
  EXPECT_EQ(comm.sum(static_cast<long long>(ghosts)) > 0, comm.size() > 1);
}

} // namespace
} // namespace poro::test
