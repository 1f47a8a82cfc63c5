#pragma once
/// constant/fluidProperties (METHOD.md §9).

#include "core/Types.hpp"

namespace poro {
class Dictionary;

struct FluidProperties {
  double density = 1000.0;              ///< rest density rho_f^0 [kg/m^3], > 0
  double viscosity = 0.0;               ///< dynamic viscosity mu^vis [Pa s], >= 0 (Eq. 18)
  double boundaryViscosity = 0.0;       ///< wall viscosity mu_b [Pa s], >= 0 (METHOD.md §6.5.3)
  Vec3 gravity = Vec3(0.0, -9.81, 0.0); ///< [m/s^2]

  /// Reads and validates every key; unknown keys are errors.
  static FluidProperties read(const Dictionary& dict);
};

} // namespace poro
