#pragma once
/// Preconditioned conjugate gradients on a matrix-free symmetric positive definite block operator
/// (METHOD.md §6.5.8).

#include "linalg/BlockVector.hpp"

#include <functional>

namespace poro::linalg {

/// y = A x for a matrix-free operator; must overwrite y.
class BlockOperator {
public:
  virtual ~BlockOperator() = default;
  virtual void apply(const BlockVector& x, const BlockVector& y) const = 0;
};

struct CgSettings {
  double tolerance = 1e-4; ///< relative residual ||b - A x|| <= tolerance ||b||
  int maxIterations = 100;
  /// Completes a dot product over every rank of a parallel run (the vectors hold this rank's rows); serially none.
  std::function<double(double)> sumOverRanks;
};

struct CgResult {
  int iterations = 0;
  double relativeResidual = 0.0;
  bool converged = false;
};

/// Work vectors the caller provides (views over scratch fields of the particle sets). z may share q's storage
/// (z = M^-1 r is dead once it has entered p, before q = A p is formed; the pass that forms z reads each element of
/// q before it writes that element of z), and r may share b's (b is read once, into r; it is overwritten then).
struct CgWork {
  BlockVector r, z, p, q;
};

/// Solves A x = b starting from the given x. `inverseDiagonal` holds the inverted 3x3 diagonal blocks
/// (block-Jacobi preconditioner, in single precision) or is empty for no preconditioning. Throws NumericalError if
/// p^T A p <= 0 (the operator is not positive definite).
CgResult solveCg(const BlockOperator& a, const BlockPreconditioner& inverseDiagonal, const BlockVector& b,
                 const BlockVector& x, const CgWork& work, const CgSettings& settings);

} // namespace poro::linalg
