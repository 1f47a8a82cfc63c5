#pragma once
/// Particles change ranks (ARCHITECTURE.md "Decomposed runs"): after they move, or after a re-partition, every
/// particle goes to the rank whose part of the Partition holds its position, with every field of the registry.

#include "parallel/Partition.hpp"
#include "parallel/mpi/Communicator.hpp"
#include "sph/ParticleSystem.hpp"

namespace poro {

/// The reductions Partition::build needs, over every rank of `comm`: build then cuts the particles of all ranks.
Reductions reductionsOver(const Communicator& comm);

/// Sends each particle whose position `partition` gives to another rank to that rank and appends the particles
/// received (in rank order, each rank's in its slot order); the others keep their order. Every rank must hold the
/// same sets with the same fields, and no ghosts (HaloExchange::dropGhosts). Returns the particles that left.
std::size_t migrate(ParticleSystem& particles, const Partition& partition, const Communicator& comm);

} // namespace poro
