#include "parallel/mpi/RankGhosts.hpp"

#include "parallel/mpi/Migration.hpp"

namespace poro {

void RankGhosts::update(ParticleSystem& particles) {
  halo_.dropGhosts(particles);
  migrated_ = migrate(particles, partition_, comm_);
  halo_.build(particles, reach_, comm_);
}

} // namespace poro
