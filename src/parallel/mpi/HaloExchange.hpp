#pragma once
/// Ghost particles of a parallel run (ARCHITECTURE.md "Decomposed runs"): each rank's sets hold its own particles
/// first, then copies of the particles other ranks lend it, which the neighbour search sees as ordinary read-only
/// particles. build() lends every particle within the reach (support radius plus skin) of another subdomain
/// (parallel/HaloPattern.hpp) with the fields a restart reads back (walls: all); refresh() then updates chosen fields
/// of the same ghosts at the fixed points of a step where their owners changed them. Sets whose particles are linked
/// by their rest positions (elastic bodies: each particle's rest neighbours, METHOD.md §4.1) can lend by those too
/// (RestHalo).

#include "parallel/mpi/Communicator.hpp"
#include "sph/ParticleSystem.hpp"

#include <string>
#include <vector>

namespace poro {

/// Lending by rest position: set s also lends every particle whose `field` lies within reach[s] (0: none) of the box
/// of the rest positions of that set's particles on the other rank. Two support radii give every rest neighbour of
/// an own particle and every rest neighbour of those ghosts, so per-particle sums over rest neighbours are whole for
/// every ghost an own particle reads, however the body has deformed since.
struct RestHalo {
  std::string field;
  std::vector<double> reach; ///< per set
};

class HaloExchange {
public:
  /// Drops the ghosts of the last build, then exchanges the particles within `reach` of each other's subdomain box and
  /// appends those received to their sets: in rank order, each rank's in its slot order. Every rank must hold the
  /// same sets with the same fields, and the same `rest`.
  void build(ParticleSystem& particles, double reach, const Communicator& comm, const RestHalo& rest = {});
  /// Copies the fields `names` (all fields when empty) of the lent particles into their ghosts on every rank.
  void refresh(ParticleSystem& particles, const std::vector<std::string>& names, const Communicator& comm) const;
  /// Removes the ghosts of the last build, once (before migration, output or a rebuild); then nothing until the next.
  void dropGhosts(ParticleSystem& particles);
  /// Whether this rank's sets hold exactly the own particles of the last build, without its ghosts (dropped).
  bool restorable(const ParticleSystem& particles) const;
  /// Appends the ghosts of the last build again, in the same slots, with the fields they are lent with from their
  /// owners, as build() (every rank restorable: no migration, reordering or removal since the build).
  void restore(ParticleSystem& particles, const Communicator& comm);

  /// Set s holds its own particles in slots [0, owned(s)) and ghosts in [owned(s), owned(s) + ghosts(s)).
  std::size_t owned(std::size_t set) const { return owned_.at(set); }
  std::size_t ghosts(std::size_t set) const;
  /// Particles of set s lent to other ranks, over all of them.
  std::size_t lent(std::size_t set) const;

private:
  /// Into `messages`, one per rank: per set s, the particles lent to that rank (fields[s]); `withCounts` puts the
  /// particle count and bytes per particle ahead of each set's data. The buffers keep their memory.
  /// refresh() with the fields of each set given: fields[s], none where it is empty.
  void refreshFields(ParticleSystem& particles, const std::vector<std::vector<std::string>>& fields,
                     const Communicator& comm) const;
  void pack(const ParticleSystem& particles, const std::vector<std::vector<std::string>>& fields, bool withCounts,
            std::vector<std::vector<char>>& messages) const;
  std::vector<std::size_t> owned_;                    ///< per set
  std::vector<std::vector<std::vector<Index>>> lent_; ///< [set][rank]: slots lent to that rank
  std::vector<std::vector<std::size_t>> received_;    ///< [set][rank]: ghosts from that rank
  bool holdsGhosts_ = false;                          ///< the sets hold this build's ghosts
  /// A refresh's messages, kept from one to the next (a step refreshes a dozen times or more).
  mutable std::vector<std::vector<char>> sendBuffers_, receiveBuffers_;
};

} // namespace poro
