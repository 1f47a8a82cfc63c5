#pragma once
/// The seam between a time step and the ranks of a parallel run (ARCHITECTURE.md "Decomposed runs"). A serial run
/// has none. In a parallel run each set holds this rank's own particles first, then ghosts: copies of other ranks'
/// particles within reach, which the neighbour search sees as ordinary particles. The step computes its own
/// particles, refreshes the ghosts at the fixed points where a later loop reads a neighbour's new value, and reduces
/// what is global. Physics terms stay unaware of ranks (src/parallel/mpi implements this).

#include "sph/ParticleSystem.hpp"

#include <string>
#include <vector>

namespace poro {

class GhostExchange {
public:
  virtual ~GhostExchange() = default;
  /// Sends each own particle whose position another rank now owns there, then fetches the ghosts anew.
  virtual void update(ParticleSystem& particles) = 0;
  /// Removes the ghosts: the sets hold this rank's own particles only (output, health checks, the next update).
  virtual void drop(ParticleSystem& particles) = 0;
  /// Ghosts again without migrating: where every rank still holds its own particles as at the last update, the same
  /// ghosts in the same slots with their state from their owners (true); otherwise ghosts anew by the current
  /// positions (false). Every rank gets the same answer.
  virtual bool reattach(ParticleSystem& particles) = 0;
  /// Set s's own particles are slots [0, owned(s)); the ghosts follow (after update, until drop).
  virtual std::size_t owned(std::size_t set) const = 0;
  /// Copies the fields `names` (every field when empty) of the own particles into their ghosts on other ranks.
  virtual void refresh(ParticleSystem& particles, const std::vector<std::string>& names) const = 0;
  /// Over every rank.
  virtual double sum(double value) const = 0;
  /// Element-wise over every rank, in place (the same length on every rank): one reduction for many sums.
  virtual void sum(std::vector<double>& values) const = 0;
  /// Every rank's `values` (any length), concatenated in rank order.
  virtual std::vector<double> gather(const std::vector<double>& values) const = 0;
  virtual double max(double value) const = 0;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;

  /// This rank's load as of the last update, what the exchanges have cost it so far, and the balance over the run.
  struct Load {
    std::size_t particles = 0;     ///< own, every set
    std::size_t ghosts = 0;        ///< every set
    double imbalance = 0.0;        ///< the heaviest rank's weight over the mean, minus 1
    double seconds = 0.0;          ///< wall time in update, reattach, refresh and the reductions since the start [s]
    double migrationSeconds = 0.0; ///< the part of it in update: migration, new cuts and new halos [s]
    double meanImbalance = 0.0;    ///< over every update (migration) so far
    double largestImbalance = 0.0; ///< over every update (migration) so far
    std::size_t repartitions = 0;  ///< new cuts so far
  };
  virtual Load load() const = 0;
};

} // namespace poro
