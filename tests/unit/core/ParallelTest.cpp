// parallel::forEachBalanced (core/Parallel.hpp): every item once, each thread one contiguous range of about equal work.

#include "core/Parallel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace poro {
namespace {

/// Runs forEachBalanced over items of the given work with `threads` threads; returns the thread of each item.
std::vector<int> ownersOf(const std::vector<std::size_t>& work, int threads) {
  std::vector<std::size_t> before(work.size() + 1, 0);
  for (std::size_t i = 0; i < work.size(); ++i) before[i + 1] = before[i] + work[i];
  std::vector<int> owner(work.size(), -1), visits(work.size(), 0);
  const int saved = parallel::threads();
  parallel::setThreads(threads);
  parallel::forEachBalanced(
      work.size(), [&](std::size_t i) { return before[i]; },
      [&](std::size_t i) {
        owner[i] = parallel::threadIndex();
        ++visits[i];
      });
  parallel::setThreads(saved);
  for (std::size_t i = 0; i < work.size(); ++i) EXPECT_EQ(visits[i], 1) << "item " << i;
  return owner;
}

TEST(ForEachBalanced, SplitsByWorkNotByCount) {
  // The first quarter of the items carries three quarters of the work (pore water beside dry fluid above): halves
  // by count would give one thread 5/6 of it.
  std::vector<std::size_t> work(4000, 1);
  std::fill(work.begin(), work.begin() + 1000, 9);
  const std::vector<int> owner = ownersOf(work, 2);
  std::size_t total = 0, first = 0;
  for (std::size_t i = 0; i < work.size(); ++i) {
    total += work[i];
    if (owner[i] == 0) first += work[i];
    if (i > 0) {
      EXPECT_GE(owner[i], owner[i - 1]) << "ranges are contiguous and in thread order, item " << i;
    }
  }
  // Each thread's share is the half to within one item's work.
  EXPECT_LE(first, total / 2 + 9);
  EXPECT_GE(first, total / 2 - 9);
}

TEST(ForEachBalanced, VisitsEveryItemOnceForAnyWorkAndThreadCount) {
  for (int threads : {1, 2, 3, 5})
    for (std::size_t n : {0u, 1u, 2u, 7u, 1000u}) {
      SCOPED_TRACE(::testing::Message() << threads << " threads, " << n << " items");
      ownersOf(std::vector<std::size_t>(n, 0), threads); // no work at all
      std::vector<std::size_t> one(n, 0);                // all of it in one item
      if (n > 0) one[n / 2] = 100;
      ownersOf(one, threads);
      std::vector<std::size_t> rising(n);
      for (std::size_t i = 0; i < n; ++i) rising[i] = i;
      ownersOf(rising, threads);
    }
}

} // namespace
} // namespace poro
