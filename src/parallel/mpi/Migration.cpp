#include "parallel/mpi/Migration.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace poro {

Reductions reductionsOver(const Communicator& comm) {
  Reductions r;
  r.sum = [&comm](std::vector<double>& v) { comm.sum(v); };
  r.min = [&comm](std::vector<double>& v) { comm.min(v); };
  r.max = [&comm](std::vector<double>& v) { comm.max(v); };
  return r;
}

std::size_t migrate(ParticleSystem& particles, const Partition& partition, const Communicator& comm) {
  const std::size_t ranks = static_cast<std::size_t>(comm.size());
  const int self = comm.rank();
  // leaving[s][q]: slots of set s that go to rank q.
  std::vector<std::vector<std::vector<Index>>> leaving(particles.size(), std::vector<std::vector<Index>>(ranks));
  std::size_t left = 0;
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const auto& x = particles[s].x();
    for (std::size_t i = 0; i < x.size(); ++i) {
      const int owner = partition.ownerOf(x[i]);
      if (owner == self) continue;
      if (owner < 0 || owner >= comm.size())
        throw std::logic_error("migrate: the partition has more parts than there are ranks");
      leaving[s][static_cast<std::size_t>(owner)].push_back(static_cast<Index>(i));
      ++left;
    }
  }
  std::vector<std::vector<char>> messages(ranks);
  for (std::size_t q = 0; q < ranks; ++q) {
    bool any = false;
    for (std::size_t s = 0; s < particles.size(); ++s) any = any || !leaving[s][q].empty();
    if (!any) continue;
    for (std::size_t s = 0; s < particles.size(); ++s) {
      const std::uint64_t count = leaving[s][q].size();
      const std::size_t at = messages[q].size();
      messages[q].resize(at + sizeof count);
      std::memcpy(messages[q].data() + at, &count, sizeof count);
      particles[s].pack(leaving[s][q], {}, messages[q]);
    }
  }
  const std::vector<std::vector<char>> received = comm.exchange(messages);
  for (std::size_t s = 0; s < particles.size(); ++s) { // the leavers go first, so received slots follow the stayers
    std::vector<std::size_t> gone;
    for (const auto& slots : leaving[s])
      for (const Index i : slots) gone.push_back(static_cast<std::size_t>(i));
    std::sort(gone.begin(), gone.end());
    particles[s].remove(gone);
  }
  for (std::size_t q = 0; q < ranks; ++q) {
    std::size_t at = 0;
    for (std::size_t s = 0; s < particles.size() && !received[q].empty(); ++s) {
      std::uint64_t count = 0;
      if (at + sizeof count > received[q].size()) throw std::logic_error("migrate: a message ends early");
      std::memcpy(&count, received[q].data() + at, sizeof count);
      at += sizeof count;
      ParticleSet& set = particles[s];
      const std::size_t first = set.size();
      set.resize(first + count);
      at += set.unpack(received[q].data() + at, count, first, {});
    }
    if (at != received[q].size())
      throw std::logic_error("migrate: a message from rank " + std::to_string(q) +
                             " has other sets or fields than this rank");
  }
  return left;
}

} // namespace poro
