#pragma once
/// The state of the moving particle sets before a step: every output field (restart fields included) and the
/// run state. A step that ends in NaN is undone with it, so the last finite state can be written and a run
/// restarted from it (solverDict health.nonFinite stop).

#include "physics/RunState.hpp"
#include "sph/ParticleSystem.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace poro {

class StateSnapshot {
public:
  /// Copies the output fields of `sets`; storage is reused from step to step. `keptInPlace` names fields whose
  /// order the coming step keeps (no reordering, no removal) and which it does not write, or writes from the
  /// positions at its start only: they are not copied, and restore() leaves them as they are (fitting the restored
  /// positions). `formedAgain` names fields the caller forms again from the others after
  /// restore(): they are not copied either.
  void take(const ParticleSystem& particles, const std::vector<std::size_t>& sets, const RunState& state,
            const std::vector<std::string>& keptInPlace = {}, const std::vector<std::string>& formedAgain = {});
  /// Puts the copied fields (and particle counts) back.
  void restore(ParticleSystem& particles, RunState& state) const;
  /// Frees the copies (the next take() allocates them again): a step found healthy needs them no more.
  void release() { sets_.clear(); }

  const RunState& state() const { return state_; }
  /// Where the particle with persistent id `id`, now at `index` of set `set`, was when the snapshot was taken
  /// (found by its id where the ids were copied, else at the same index).
  std::optional<Vec3> positionOf(std::size_t set, std::size_t index, std::int64_t id) const;

private:
  using Data = std::variant<std::vector<Real>, std::vector<Vec3>, std::vector<Mat3>, std::vector<std::int64_t>>;
  struct Field {
    std::string name;
    Data data;
  };
  struct Set {
    std::size_t index = 0;
    std::size_t size = 0;
    std::vector<Field> fields;
  };
  std::vector<Set> sets_;
  RunState state_;
};

} // namespace poro
