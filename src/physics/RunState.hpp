#pragma once
/// Where a run stands: what uniform/time stores (METHOD.md §7).

namespace poro {

struct RunState {
  double time = 0.0;
  long long step = 0;
  double nextDeltaT = 0.0; ///< the step size of the coming step [s]
  double lastDeltaT = 0.0; ///< the step size of the step just taken [s], 0 before the first
};

} // namespace poro
