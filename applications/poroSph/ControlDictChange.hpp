#pragma once
/// runTimeModifiable in both kinds of run: a changed system/controlDict takes effect after the step that saw it.

#include "io/ControlDictWatcher.hpp"
#include "io/TimeDirectory.hpp"
#include "physics/Solver.hpp"

namespace poro {

/// Logs what changed from `current` to `changed`, then makes it the settings of the solver and the writer.
void applyControlDictChange(ControlSettings& current, const ControlSettings& changed, Solver& solver,
                            TimeWriter& writer);

} // namespace poro
