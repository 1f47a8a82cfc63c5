#pragma once
/// The only place with `#pragma omp` (STYLE.md §4). Loops are in gather form: iteration i writes slot i only.
/// Reductions use a fixed blocking independent of the thread count, so results are bit-reproducible
/// for any number of threads (METHOD.md §1).

#include <cstddef>
#include <vector>

namespace poro::parallel {

/// Sets the number of OpenMP threads (n >= 1).
void setThreads(int n);
/// Number of threads a parallel loop uses.
int threads();

/// Calls body(i) for i in [0, n) in parallel; body must write only slot i.
template <class Body>
void forEach(std::size_t n, const Body& body) {
  const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
}

/// Index of the calling thread within a parallel region (0 outside one).
int threadIndex();

/// Calls body(i) for i in [0, n) in parallel, each thread one contiguous range of about equal work, where
/// workBefore(i) is the work of items [0, i) (nondecreasing in i): for pair loops whose particles have very different
/// neighbour counts (pore water beside water above the block), which equal halves by count leave one thread waiting
/// for. The ranges are the same in every pass over the same lists, as static halves are.
template <class Body, class WorkBefore>
void forEachBalanced(std::size_t n, const WorkBefore& workBefore, const Body& body) {
  const double total = static_cast<double>(workBefore(n));
  const int count = threads();
  // First item of share k: the least i with workBefore(i) >= k / count of the total.
  const auto shareStart = [&](int k) -> std::size_t {
    if (k <= 0) return 0;
    if (k >= count) return n;
    const double target = total * k / count;
    std::size_t low = 0, high = n;
    while (low < high) {
      const std::size_t middle = low + (high - low) / 2;
      if (static_cast<double>(workBefore(middle)) < target)
        low = middle + 1;
      else
        high = middle;
    }
    return low;
  };
#pragma omp parallel num_threads(count)
  {
    const int k = threadIndex();
    const std::size_t end = shareStart(k + 1);
    for (std::size_t i = shareStart(k); i < end; ++i) body(i);
  }
}

/// Calls body(t) for t in [0, n) handing out one task at a time: for a few large tasks (chunks of
/// particles) that must spread over all threads.
template <class Body>
void forEachTask(std::size_t n, const Body& body) {
  const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(dynamic, 1)
  for (long long t = 0; t < count; ++t) body(static_cast<std::size_t>(t));
}

/// Block size of deterministic reductions.
inline constexpr std::size_t kReduceBlock = 4096;

/// Deterministic reduction: sum of value(i) for i in [0, n) with a blocking that does not depend on the
/// thread count. T needs T{} as zero and operator+=. Whole blocks go to the threads, so a set of a few blocks
/// divides unevenly: costly per-particle work belongs in a forEach that stores what is summed here.
template <class T, class Value>
T sum(std::size_t n, const Value& value) {
  const std::size_t blocks = (n + kReduceBlock - 1) / kReduceBlock;
  std::vector<T> partial(blocks, T{});
  const long long nb = static_cast<long long>(blocks);
#pragma omp parallel for schedule(static)
  for (long long b = 0; b < nb; ++b) {
    T acc{};
    const std::size_t begin = static_cast<std::size_t>(b) * kReduceBlock;
    const std::size_t end = begin + kReduceBlock < n ? begin + kReduceBlock : n;
    for (std::size_t i = begin; i < end; ++i) acc += value(i);
    partial[static_cast<std::size_t>(b)] = acc;
  }
  T total{};
  for (const T& p : partial) total += p;
  return total;
}

/// Deterministic maximum of value(i) (returns lowest if n == 0). Max is order-independent.
template <class Value>
double max(std::size_t n, double lowest, const Value& value) {
  double result = lowest;
  const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(static) reduction(max : result)
  for (long long i = 0; i < count; ++i) {
    const double v = value(static_cast<std::size_t>(i));
    if (v > result) result = v;
  }
  return result;
}

} // namespace poro::parallel
