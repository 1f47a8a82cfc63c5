#pragma once
/// constant/porosityProperties: the porous materials of a case, by name (METHOD.md §3.1, §9).
///   sand:
///     porosity: 0.4
///     solidDensity: 2650        # or bulkDensity: 1590 (exactly one of the two)
///     compressible: false
///     dragViscosity: 10
///     fixedBox: {min: [..], max: [..]}

#include "core/Types.hpp"

#include <optional>
#include <string>
#include <vector>

namespace poro {
class Dictionary;

inline constexpr double kMaxYoungsModulus = 1e13;   ///< [Pa], above any solid's (diamond 1.2e12)
inline constexpr double kMaxHourglassControl = 1e3; ///< 1 removes the zero-energy modes (porosityProperties)

struct PorousMaterial {
  std::string name;
  double porosity = 0.0;      ///< phi, 0 <= phi < 1
  double solidDensity = 0.0;  ///< rho_s^0, density of the solid phase [kg/m^3]
  double bulkDensity = 0.0;   ///< rho_b = (1 - phi) rho_s^0 [kg/m^3]
  bool compressible = false;  ///< pores may close (rho^max = rho_s^0) or keep their volume (rho^max = rho_b)
  double dragViscosity = 0.0; ///< mu_por [Pa s] (Eq. 16)
  // Keys of the elastic and capillary terms (METHOD.md §6.5.4, §6.5.6) and of solid damping (§6.5.3).
  double youngsModulus = 0.0;            ///< E [Pa]
  double poissonsRatio = 0.3;            ///< nu_P, -1 < nu_P < 0.5
  double hourglassControl = 0.0;         ///< zero-energy-mode control, times mu (HourglassControl.hpp); 0: off
  double capillaryStrength = 0.0;        ///< C^cap,0 [N/m]
  double capillaryFalloff = 0.0;         ///< eta_cap in [0, 1]
  double bloating = 0.0;                 ///< eta_bloat [Pa]
  double shearSoftening = 0.0;           ///< eta_m
  double volumeSoftening = 0.0;          ///< eta_l
  double dampingViscosity = 0.0;         ///< mu_d [Pa s]
  double boundaryDampingViscosity = 0.0; ///< mu_d,b [Pa s]
  /// Particles whose initial position lies strictly inside are Fixed (METHOD.md §4.2).
  std::optional<std::pair<Vec3, Vec3>> fixedBox;

  /// rho^max: the largest density the pressure solve admits (METHOD.md §3.1).
  double maxDensity() const { return compressible ? solidDensity : bulkDensity; }
  /// Lame parameters of the skeleton: mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)) [Pa].
  double shearModulus() const { return youngsModulus / (2.0 * (1.0 + poissonsRatio)); }
  double lameLambda() const {
    return youngsModulus * poissonsRatio / ((1.0 + poissonsRatio) * (1.0 - 2.0 * poissonsRatio));
  }
  /// c_s = rho_b / rho^max: the own-body volume factor (1 incompressible, 1 - phi compressible).
  double ownFactor() const { return bulkDensity / maxDensity(); }

  /// Reads every material of constant/porosityProperties (file order) and validates every key; unknown
  /// keys are errors with a hint.
  static std::vector<PorousMaterial> readAll(const Dictionary& dict);
};

} // namespace poro
