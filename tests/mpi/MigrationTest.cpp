// A partition cut from particles spread over ranks equals the one cut from all of them in one process, and
// migration then leaves each rank exactly the particles its part holds, every field intact.

#include "parallel/mpi/Migration.hpp"
#include "MpiTestMain.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace poro::test {
namespace {

struct Cloud {
  std::vector<Vec3> x;
  std::vector<double> weight; // 1, 1.5 or 2: sums are exact in any order, so every rank count cuts alike
};

Cloud cloud() {
  Cloud c;
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < 4000; ++i) {
    c.x.emplace_back(u(rng), 0.6 * u(rng), 0.3 * u(rng));
    c.weight.push_back(1.0 + 0.5 * static_cast<double>(i % 3));
  }
  return c;
}

/// Particle i of the cloud is dealt to rank i mod size: scattered, nothing like a partition.
ParticleSystem dealt(const Cloud& c, const Communicator& comm) {
  ParticleSystem particles(0.01);
  ParticleSet& fluid = particles.add("fluid", SetKind::Fluid);
  ParticleSet& walls = particles.add("boundary", SetKind::Boundary);
  for (ParticleSet* set : {&fluid, &walls}) set->addMat3("rotation", Restart);
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    if (static_cast<int>(i % static_cast<std::size_t>(comm.size())) != comm.rank()) continue;
    ParticleSet& set = i % 4 == 0 ? walls : fluid;
    const std::size_t k = set.size();
    set.resize(k + 1);
    set.integer(field::id)[k] = static_cast<std::int64_t>(i);
    set.x()[k] = c.x[i];
    set.v()[k] = Vec3(0.0, static_cast<double>(i), 0.0);
    set.mat3("rotation")[k] = Mat3::Identity() * (1.0 + static_cast<double>(i));
  }
  return particles;
}

TEST(Migration, PartitionOfSpreadParticlesEqualsTheSerialOneAndMigrationDealsThemOut) {
  const Communicator& comm = mpiTestCommunicator();
  const Cloud c = cloud();
  for (const PartitionMethod method : {PartitionMethod::RecursiveBisection, PartitionMethod::HilbertCurve}) {
    ParticleSystem particles = dealt(c, comm);
    std::vector<Vec3> mine;
    std::vector<double> weights;
    for (std::size_t s = 0; s < particles.size(); ++s)
      for (std::size_t k = 0; k < particles[s].size(); ++k) {
        mine.push_back(particles[s].x()[k]);
        weights.push_back(c.weight[static_cast<std::size_t>(particles[s].integer(field::id)[k])]);
      }
    const Partition spread = Partition::build(mine, weights, comm.size(), method, reductionsOver(comm));
    const Partition whole = Partition::build(c.x, c.weight, comm.size(), method);
    EXPECT_EQ(spread.owners(c.x), whole.owners(c.x)) << toString(method);

    const long long before = comm.sum(static_cast<long long>(particles[0].size() + particles[1].size()));
    const std::size_t left = migrate(particles, spread, comm);
    EXPECT_EQ(comm.sum(static_cast<long long>(particles[0].size() + particles[1].size())), before);
    EXPECT_GT(comm.sum(static_cast<long long>(left)), 0);
    std::set<std::int64_t> held;
    for (std::size_t s = 0; s < particles.size(); ++s)
      for (std::size_t k = 0; k < particles[s].size(); ++k) {
        const std::int64_t id = particles[s].integer(field::id)[k];
        const std::size_t i = static_cast<std::size_t>(id);
        held.insert(id);
        EXPECT_EQ(whole.ownerOf(c.x[i]), comm.rank());
        EXPECT_EQ(particles[s].x()[k], c.x[i]);
        EXPECT_EQ(particles[s].v()[k], Vec3(0.0, static_cast<double>(i), 0.0));
        EXPECT_EQ(particles[s].mat3("rotation")[k], Mat3::Identity() * (1.0 + static_cast<double>(i)));
        EXPECT_EQ(s == 1, i % 4 == 0) << "particle " << i << " changed sets";
      }
    std::size_t expected = 0;
    for (const Vec3& x : c.x) expected += whole.ownerOf(x) == comm.rank() ? 1 : 0;
    EXPECT_EQ(held.size(), expected);
    EXPECT_EQ(migrate(particles, spread, comm), 0u); // everybody is home
    // The weights the ranks now hold are their shares of the total, within two of the heaviest particles.
    double weight = 0.0;
    for (const std::int64_t id : held) weight += c.weight[static_cast<std::size_t>(id)];
    double total = 0.0;
    for (const double w : c.weight) total += w;
    EXPECT_NEAR(weight, total / comm.size(), 2.0 * std::ceil(std::log2(comm.size())) * 2.0 + 1e-9);
  }
}

} // namespace
} // namespace poro::test
