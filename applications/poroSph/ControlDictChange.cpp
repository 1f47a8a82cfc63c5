#include "ControlDictChange.hpp"

#include "core/Log.hpp"

namespace poro {

void applyControlDictChange(ControlSettings& current, const ControlSettings& changed, Solver& solver,
                            TimeWriter& writer) {
  const std::string changes = describeChanges(current, changed);
  if (!changes.empty()) log::info("system/controlDict changed (runTimeModifiable):\n" + changes);
  current = changed;
  solver.setTimeControl(current.control);
  writer.setSettings(current.output);
}

} // namespace poro
