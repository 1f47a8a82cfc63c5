#pragma once
/// The ranks of a parallel run (ARCHITECTURE.md "Decomposed runs"): the only code that includes mpi.h. One object per
/// process, made by `poroSph -parallel` (and the MPI tests) before anything else; a serial run never makes one, so it
/// touches no MPI.

#include <string>
#include <vector>

namespace poro {

class Communicator {
public:
  /// MPI_Init_thread with MPI_THREAD_FUNNELED: OpenMP threads compute, the main thread communicates.
  Communicator(int& argc, char**& argv);
  ~Communicator();
  Communicator(const Communicator&) = delete;
  Communicator& operator=(const Communicator&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Reductions over every rank; every rank gets the result.
  double sum(double value) const;
  double max(double value) const;
  double min(double value) const;
  long long sum(long long value) const;
  long long max(long long value) const;
  /// Element-wise over every rank, in place (the same length on every rank).
  void sum(std::vector<double>& values) const;
  void min(std::vector<double>& values) const;
  void max(std::vector<double>& values) const;
  /// Every rank's `values` (the same length on every rank), concatenated in rank order.
  std::vector<double> allGather(const std::vector<double>& values) const;
  /// Every rank's `values` (any length), concatenated in rank order.
  std::vector<double> allGatherVaried(const std::vector<double>& values) const;
  /// Sends toRank[q] to rank q (toRank has size() entries, its own ignored) and returns, per rank, what that rank sent
  /// here. Empty messages cost no message.
  std::vector<std::vector<char>> exchange(const std::vector<std::vector<char>>& toRank) const;
  /// As exchange(), where every rank knows how many bytes each other rank sends it (`expected`, size() entries), so
  /// no sizes go first; into `received`, whose buffers are reused from call to call (halo refreshes).
  void exchangeKnown(const std::vector<std::vector<char>>& toRank, const std::vector<std::size_t>& expected,
                     std::vector<std::vector<char>>& received) const;
  /// Rank `root`'s `text` on every rank.
  std::string broadcast(const std::string& text, int root = 0) const;
  void barrier() const;
  /// Stops every rank (MPI_Abort): for an error that one rank met and the others cannot learn of.
  [[noreturn]] void abort(int code) const;

private:
  int rank_ = 0;
  int size_ = 1;
};

} // namespace poro
