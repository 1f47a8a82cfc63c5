#include "core/Timer.hpp"

namespace poro {

void PhaseTimes::add(const std::string& phase, double seconds) {
  for (auto& [name, value] : phases_) {
    if (name == phase) {
      value += seconds;
      return;
    }
  }
  phases_.emplace_back(phase, seconds);
}

double PhaseTimes::total() const {
  double sum = 0.0;
  for (const auto& entry : phases_) sum += entry.second;
  return sum;
}

} // namespace poro
