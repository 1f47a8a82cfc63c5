#include "parallel/mpi/HaloExchange.hpp"

#include "parallel/HaloPattern.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <numeric>
#include <stdexcept>

namespace poro {

namespace {

void putCount(std::vector<char>& out, std::uint64_t value) {
  const std::size_t at = out.size();
  out.resize(at + sizeof value);
  std::memcpy(out.data() + at, &value, sizeof value);
}

std::uint64_t takeCount(const std::vector<char>& in, std::size_t& at) {
  std::uint64_t value = 0;
  if (at + sizeof value > in.size()) throw std::logic_error("HaloExchange: a message ends early");
  std::memcpy(&value, in.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

/// Bytes one particle of `set` takes in a message with the fields `names` (all when empty), from the field types.
std::size_t bytesPerParticle(const ParticleSet& set, const std::vector<std::string>& names) {
  std::size_t bytes = 0;
  for (const std::string& name : names.empty() ? set.fieldNames() : names) {
    switch (set.info(name)->type) {
    case FieldType::Real:
      bytes += sizeof(Real);
      break;
    case FieldType::Vec3:
      bytes += sizeof(Vec3);
      break;
    case FieldType::Mat3:
      bytes += sizeof(Mat3);
      break;
    case FieldType::Int:
      bytes += sizeof(std::int64_t);
      break;
    }
  }
  return bytes;
}

/// The fields a particle of `set` is lent with: what a restart reads back (positions, velocities, pi, rotations, ...).
/// The step computes a dynamic particle's other fields from these, and its owner's values of those reach the ghost
/// at the refreshes where a neighbour reads them, as a restart computes them anew. Walls lend every field: their
/// volumes are computed once, not every step.
std::vector<std::string> lentFields(const ParticleSet& set) {
  std::vector<std::string> names;
  for (const ParticleSet::FieldInfo& f : set.fields())
    if (set.kind() == SetKind::Boundary || f.role == Restart) names.push_back(f.name);
  return names;
}

/// The fields of `names` that `set` has (all of its fields when `names` is empty): sets differ (a fluid set has no
/// contact pressure), and every rank's set of one name has the same fields.
std::vector<std::string> fieldsOf(const ParticleSet& set, const std::vector<std::string>& names) {
  if (names.empty()) return set.fieldNames();
  std::vector<std::string> present;
  for (const std::string& name : names)
    if (set.has(name)) present.push_back(name);
  return present;
}

/// Every rank's box from this rank's `mine` (allGather: every rank calls it in the same order).
std::vector<Box> boxesOfRanks(const Box& mine, const Communicator& comm) {
  const std::vector<double> flat =
      comm.allGather({mine.lo.x(), mine.lo.y(), mine.lo.z(), mine.hi.x(), mine.hi.y(), mine.hi.z()});
  std::vector<Box> boxes(static_cast<std::size_t>(comm.size()));
  for (std::size_t q = 0; q < boxes.size(); ++q) {
    boxes[q].lo = Vec3(flat[6 * q], flat[6 * q + 1], flat[6 * q + 2]);
    boxes[q].hi = Vec3(flat[6 * q + 3], flat[6 * q + 4], flat[6 * q + 5]);
  }
  return boxes;
}

} // namespace

std::size_t HaloExchange::ghosts(std::size_t set) const {
  const auto& counts = received_.at(set);
  return std::accumulate(counts.begin(), counts.end(), std::size_t{0});
}

std::size_t HaloExchange::lent(std::size_t set) const {
  std::size_t n = 0;
  for (const auto& slots : lent_.at(set)) n += slots.size();
  return n;
}

void HaloExchange::dropGhosts(ParticleSystem& particles) {
  if (!holdsGhosts_) return; // particles may have changed ranks since: owned_ is not their count any more
  for (std::size_t s = 0; s < owned_.size() && s < particles.size(); ++s) particles[s].resize(owned_[s]);
  holdsGhosts_ = false;
}

bool HaloExchange::restorable(const ParticleSystem& particles) const {
  if (holdsGhosts_ || lent_.empty() || owned_.size() != particles.size()) return false;
  for (std::size_t s = 0; s < particles.size(); ++s)
    if (particles[s].size() != owned_[s]) return false;
  return true;
}

void HaloExchange::restore(ParticleSystem& particles, const Communicator& comm) {
  std::vector<std::vector<std::string>> fields(particles.size());
  for (std::size_t s = 0; s < particles.size(); ++s) {
    particles[s].resize(owned_[s] + ghosts(s));
    fields[s] = lentFields(particles[s]);
  }
  holdsGhosts_ = true;
  refreshFields(particles, fields, comm);
}

void HaloExchange::pack(const ParticleSystem& particles, const std::vector<std::vector<std::string>>& fields,
                        bool withCounts, std::vector<std::vector<char>>& messages) const {
  const std::size_t ranks = lent_.empty() ? 0 : lent_.front().size();
  messages.resize(ranks);
  for (std::size_t q = 0; q < ranks; ++q) {
    messages[q].clear();
    bool any = false;
    for (std::size_t s = 0; s < particles.size(); ++s) any = any || !lent_[s][q].empty();
    if (!any) continue; // no message: the receiver reads an empty one as no ghosts from here
    for (std::size_t s = 0; s < particles.size(); ++s) {
      if (withCounts) {
        putCount(messages[q], lent_[s][q].size());
        putCount(messages[q], bytesPerParticle(particles[s], fields[s]));
      }
      if (!fields[s].empty()) particles[s].pack(lent_[s][q], fields[s], messages[q]); // (empty: all, to pack)
    }
  }
}

void HaloExchange::build(ParticleSystem& particles, double reach, const Communicator& comm, const RestHalo& rest) {
  dropGhosts(particles);
  holdsGhosts_ = true;
  const std::size_t ranks = static_cast<std::size_t>(comm.size());
  owned_.assign(particles.size(), 0);
  std::vector<const std::vector<Vec3>*> positions;
  for (std::size_t s = 0; s < particles.size(); ++s) {
    owned_[s] = particles[s].size();
    positions.push_back(&particles[s].x());
  }
  const std::vector<Box> boxes = boxesOfRanks(boundingBox(positions), comm);
  lent_.assign(particles.size(), {});
  for (std::size_t s = 0; s < particles.size(); ++s) {
    lent_[s] = haloSendLists(particles[s].x(), boxes, comm.rank(), reach);
    const double restReach = s < rest.reach.size() ? rest.reach[s] : 0.0;
    if (restReach <= 0.0) continue;
    const std::vector<Vec3>& restX = particles[s].vec3(rest.field);
    const std::vector<Box> restBoxes = boxesOfRanks(boundingBox({&restX}), comm);
    const std::vector<std::vector<Index>> byRest = haloSendLists(restX, restBoxes, comm.rank(), restReach);
    for (std::size_t q = 0; q < ranks; ++q) { // both ascending: their union is too, each particle once
      std::vector<Index> both;
      std::set_union(lent_[s][q].begin(), lent_[s][q].end(), byRest[q].begin(), byRest[q].end(),
                     std::back_inserter(both));
      lent_[s][q] = std::move(both);
    }
  }

  std::vector<std::vector<std::string>> fields(particles.size());
  for (std::size_t s = 0; s < particles.size(); ++s) fields[s] = lentFields(particles[s]);
  std::vector<std::vector<char>> messages;
  pack(particles, fields, true, messages);
  const std::vector<std::vector<char>> received = comm.exchange(messages);
  received_.assign(particles.size(), std::vector<std::size_t>(ranks, 0));
  std::vector<std::size_t> read(ranks, 0);
  for (std::size_t q = 0; q < ranks; ++q)
    for (std::size_t s = 0; s < particles.size() && !received[q].empty(); ++s) {
      ParticleSet& set = particles[s];
      const std::size_t count = takeCount(received[q], read[q]);
      if (takeCount(received[q], read[q]) != bytesPerParticle(set, fields[s]))
        throw std::logic_error("HaloExchange: set '" + set.name() + "' has other fields on rank " + std::to_string(q));
      const std::size_t first = set.size();
      set.resize(first + count);
      read[q] += set.unpack(received[q].data() + read[q], count, first, fields[s]);
      received_[s][q] = count;
    }
}

void HaloExchange::refresh(ParticleSystem& particles, const std::vector<std::string>& names,
                           const Communicator& comm) const {
  // Pack and unpack name the same fields on every rank: fieldsOf() depends on the set's registry only.
  std::vector<std::vector<std::string>> fields(particles.size());
  for (std::size_t s = 0; s < particles.size(); ++s) fields[s] = fieldsOf(particles[s], names);
  refreshFields(particles, fields, comm);
}

void HaloExchange::refreshFields(ParticleSystem& particles, const std::vector<std::vector<std::string>>& fields,
                                 const Communicator& comm) const {
  std::vector<std::size_t> expected(received_.empty() ? 0 : received_.front().size(), 0);
  for (std::size_t s = 0; s < particles.size(); ++s) {
    const std::size_t bytes = fields[s].empty() ? 0 : bytesPerParticle(particles[s], fields[s]);
    for (std::size_t q = 0; q < expected.size(); ++q) expected[q] += received_[s][q] * bytes;
  }
  pack(particles, fields, false, sendBuffers_);
  comm.exchangeKnown(sendBuffers_, expected, receiveBuffers_);
  std::vector<std::size_t> at(expected.size(), 0); // where the next set's data starts in each rank's message
  for (std::size_t s = 0; s < particles.size(); ++s) {
    std::size_t first = owned_[s];
    for (std::size_t q = 0; q < expected.size(); ++q) {
      const std::size_t count = received_[s][q];
      if (count > 0 && !fields[s].empty())
        at[q] += particles[s].unpack(receiveBuffers_[q].data() + at[q], count, first, fields[s]);
      first += count;
    }
  }
}

} // namespace poro
