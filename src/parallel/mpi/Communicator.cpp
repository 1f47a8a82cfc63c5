#include "parallel/mpi/Communicator.hpp"

#include <mpi.h>

#include <climits>
#include <cstdint>
#include <stdexcept>

namespace poro {

namespace {

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI error in ") + what);
}

template <class T> T reduce(T value, MPI_Datatype type, MPI_Op op) {
  T result{};
  check(MPI_Allreduce(&value, &result, 1, type, op, MPI_COMM_WORLD), "MPI_Allreduce");
  return result;
}

} // namespace

Communicator::Communicator(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  if (provided < MPI_THREAD_FUNNELED) throw std::runtime_error("the MPI library does not support threads");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Communicator::~Communicator() { MPI_Finalize(); }

double Communicator::sum(double value) const { return reduce(value, MPI_DOUBLE, MPI_SUM); }
double Communicator::max(double value) const { return reduce(value, MPI_DOUBLE, MPI_MAX); }
double Communicator::min(double value) const { return reduce(value, MPI_DOUBLE, MPI_MIN); }
long long Communicator::sum(long long value) const { return reduce(value, MPI_LONG_LONG, MPI_SUM); }
long long Communicator::max(long long value) const { return reduce(value, MPI_LONG_LONG, MPI_MAX); }

namespace {
void reduceInPlace(std::vector<double>& values, MPI_Op op) {
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, op, MPI_COMM_WORLD),
        "MPI_Allreduce");
}
} // namespace

void Communicator::sum(std::vector<double>& values) const { reduceInPlace(values, MPI_SUM); }
void Communicator::min(std::vector<double>& values) const { reduceInPlace(values, MPI_MIN); }
void Communicator::max(std::vector<double>& values) const { reduceInPlace(values, MPI_MAX); }

std::vector<double> Communicator::allGather(const std::vector<double>& values) const {
  std::vector<double> all(values.size() * static_cast<std::size_t>(size_));
  check(MPI_Allgather(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(),
                      static_cast<int>(values.size()), MPI_DOUBLE, MPI_COMM_WORLD),
        "MPI_Allgather");
  return all;
}

std::vector<double> Communicator::allGatherVaried(const std::vector<double>& values) const {
  if (values.size() > INT_MAX) throw std::runtime_error("a gather above 2^31 values");
  const std::vector<double> counts = allGather({static_cast<double>(values.size())});
  std::vector<int> sizes(counts.size()), offsets(counts.size(), 0);
  for (std::size_t q = 0; q < counts.size(); ++q) {
    sizes[q] = static_cast<int>(counts[q]);
    if (q > 0) offsets[q] = offsets[q - 1] + sizes[q - 1];
  }
  std::vector<double> all(static_cast<std::size_t>(offsets.back() + sizes.back()));
  check(MPI_Allgatherv(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(), sizes.data(),
                       offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD),
        "MPI_Allgatherv");
  return all;
}

std::string Communicator::broadcast(const std::string& text, int root) const {
  long long size = rank_ == root ? static_cast<long long>(text.size()) : 0;
  check(MPI_Bcast(&size, 1, MPI_LONG_LONG, root, MPI_COMM_WORLD), "MPI_Bcast");
  if (size > INT_MAX) throw std::runtime_error("a broadcast above 2 GB");
  std::string result = rank_ == root ? text : std::string(static_cast<std::size_t>(size), '\0');
  check(MPI_Bcast(result.data(), static_cast<int>(size), MPI_CHAR, root, MPI_COMM_WORLD), "MPI_Bcast");
  return result;
}

std::vector<std::vector<char>> Communicator::exchange(const std::vector<std::vector<char>>& toRank) const {
  if (toRank.size() != static_cast<std::size_t>(size_)) throw std::logic_error("Communicator::exchange: one per rank");
  std::vector<std::int64_t> sendCounts(toRank.size()), receiveCounts(toRank.size());
  for (std::size_t q = 0; q < toRank.size(); ++q) {
    sendCounts[q] = static_cast<int>(q) == rank_ ? 0 : static_cast<std::int64_t>(toRank[q].size());
    if (sendCounts[q] > INT_MAX) throw std::runtime_error("a halo message above 2 GB");
  }
  check(MPI_Alltoall(sendCounts.data(), 1, MPI_INT64_T, receiveCounts.data(), 1, MPI_INT64_T, MPI_COMM_WORLD),
        "MPI_Alltoall");
  std::vector<std::vector<char>> received(toRank.size());
  std::vector<MPI_Request> requests;
  for (std::size_t q = 0; q < toRank.size(); ++q) {
    if (receiveCounts[q] == 0) continue;
    received[q].resize(static_cast<std::size_t>(receiveCounts[q]));
    requests.emplace_back();
    check(MPI_Irecv(received[q].data(), static_cast<int>(receiveCounts[q]), MPI_CHAR, static_cast<int>(q), 0,
                    MPI_COMM_WORLD, &requests.back()),
          "MPI_Irecv");
  }
  for (std::size_t q = 0; q < toRank.size(); ++q) {
    if (sendCounts[q] == 0) continue;
    requests.emplace_back();
    check(MPI_Isend(toRank[q].data(), static_cast<int>(sendCounts[q]), MPI_CHAR, static_cast<int>(q), 0, MPI_COMM_WORLD,
                    &requests.back()),
          "MPI_Isend");
  }
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  return received;
}

void Communicator::exchangeKnown(const std::vector<std::vector<char>>& toRank, const std::vector<std::size_t>& expected,
                                 std::vector<std::vector<char>>& received) const {
  if (toRank.size() != static_cast<std::size_t>(size_) || expected.size() != toRank.size())
    throw std::logic_error("Communicator::exchangeKnown: one per rank");
  received.resize(toRank.size());
  std::vector<MPI_Request> requests;
  requests.reserve(2 * toRank.size());
  for (std::size_t q = 0; q < toRank.size(); ++q) {
    if (static_cast<int>(q) == rank_ || expected[q] == 0) continue;
    if (expected[q] > INT_MAX || toRank[q].size() > INT_MAX) throw std::runtime_error("a halo message above 2 GB");
    received[q].resize(expected[q]); // the same size as the last time: no allocation, no clearing
    requests.emplace_back();
    check(MPI_Irecv(received[q].data(), static_cast<int>(expected[q]), MPI_CHAR, static_cast<int>(q), 0, MPI_COMM_WORLD,
                    &requests.back()),
          "MPI_Irecv");
  }
  for (std::size_t q = 0; q < toRank.size(); ++q) {
    if (static_cast<int>(q) == rank_ || toRank[q].empty()) continue;
    requests.emplace_back();
    check(MPI_Isend(toRank[q].data(), static_cast<int>(toRank[q].size()), MPI_CHAR, static_cast<int>(q), 0,
                    MPI_COMM_WORLD, &requests.back()),
          "MPI_Isend");
  }
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
}

void Communicator::barrier() const { check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier"); }

void Communicator::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();
}

} // namespace poro
