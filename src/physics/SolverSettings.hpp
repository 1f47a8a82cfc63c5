#pragma once
/// system/solverDict (METHOD.md §9): pressure solve, implicit solve, neighbour search, threads.

namespace poro {
class Dictionary;

struct PressureSettings {
  double maxDensityError = 0.01; ///< mean compression per set [% of rho^max], > 0
  int minIterations = 2;
  int maxIterations = 100;
  double relaxation = 0.5; ///< Jacobi relaxation omega, (0, 1]
  double warmStart = 0.5;  ///< warm-start factor, [0, 1]
};

struct ImplicitSettings {
  double tolerance = 1e-4; ///< relative CG residual, (0, 1)
  int maxIterations = 100;
  bool preconditioner = true; ///< blockJacobi (true) or none
};

struct SolverSettings {
  PressureSettings pressure;
  ImplicitSettings implicit;
  int sortInterval = 500; ///< Morton reorder period in steps, 0 = never
  int threads = 0;        ///< OpenMP threads, 0 = the OpenMP default

  /// Reads and validates every key; unknown keys are errors.
  static SolverSettings read(const Dictionary& dict);
};

} // namespace poro
