// Communicator: reductions, gathers and the pairwise exchange give every rank the same, exact answers.

#include "MpiTestMain.hpp"

#include <gtest/gtest.h>

namespace poro::test {
namespace {

TEST(Communicator, ReductionsAndGathersAgreeOnEveryRank) {
  const Communicator& comm = mpiTestCommunicator();
  const int n = comm.size();
  const int r = comm.rank();
  EXPECT_EQ(comm.sum(static_cast<double>(r + 1)), n * (n + 1) / 2.0);
  EXPECT_EQ(comm.max(static_cast<double>(r)), n - 1.0);
  EXPECT_EQ(comm.min(static_cast<double>(r) - 0.5), -0.5);
  EXPECT_EQ(comm.sum(static_cast<long long>(r)), static_cast<long long>(n) * (n - 1) / 2);
  EXPECT_EQ(comm.max(static_cast<long long>(10 * r)), 10LL * (n - 1));
  const std::vector<double> all = comm.allGather({static_cast<double>(r), -static_cast<double>(r)});
  ASSERT_EQ(all.size(), 2u * static_cast<std::size_t>(n));
  for (int q = 0; q < n; ++q) {
    EXPECT_EQ(all[2 * static_cast<std::size_t>(q)], q);
    EXPECT_EQ(all[2 * static_cast<std::size_t>(q) + 1], -q);
  }
}

TEST(Communicator, ExchangeDeliversEachMessageToItsRank) {
  const Communicator& comm = mpiTestCommunicator();
  std::vector<std::vector<char>> out(static_cast<std::size_t>(comm.size()));
  // Rank r sends rank q a message of r + q bytes, each byte 16 r + q; the message to itself is never delivered.
  for (int q = 0; q < comm.size(); ++q)
    out[static_cast<std::size_t>(q)].assign(static_cast<std::size_t>(comm.rank() + q),
                                            static_cast<char>(16 * comm.rank() + q));
  const auto in = comm.exchange(out);
  ASSERT_EQ(in.size(), out.size());
  for (int q = 0; q < comm.size(); ++q) {
    const auto& message = in[static_cast<std::size_t>(q)];
    if (q == comm.rank()) {
      EXPECT_TRUE(message.empty());
      continue;
    }
    ASSERT_EQ(message.size(), static_cast<std::size_t>(q + comm.rank())) << "from rank " << q;
    for (const char c : message) EXPECT_EQ(c, static_cast<char>(16 * q + comm.rank()));
  }
}

} // namespace
} // namespace poro::test
