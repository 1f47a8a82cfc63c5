#include "linalg/ConjugateGradient.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <sstream>

namespace poro::linalg {

namespace {
bool sameStorage(const BlockVector& a, const BlockVector& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t p = 0; p < a.size(); ++p)
    if (a[p].data != b[p].data) return false;
  return true;
}
} // namespace

CgResult solveCg(const BlockOperator& a, const BlockPreconditioner& inverseDiagonal, const BlockVector& b,
                 const BlockVector& x, const CgWork& work, const CgSettings& settings) {
  CgResult result;
  const auto dot = [&](const BlockVector& u, const BlockVector& v) {
    const double local = linalg::dot(u, v);
    return settings.sumOverRanks ? settings.sumOverRanks(local) : local;
  };
  const double normB = std::sqrt(dot(b, b));
  if (normB == 0.0) {
    for (const Vec3Span& part : x)
      for (std::size_t i = 0; i < part.size; ++i) part.data[i].setZero();
    result.converged = true;
    return result;
  }
  auto precondition = [&](const BlockVector& from, const BlockVector& to) {
    if (inverseDiagonal.empty())
      copy(from, to);
    else
      multiply(inverseDiagonal, from, to);
  };

  a.apply(x, work.q);
  if (!sameStorage(b, work.r)) copy(b, work.r);
  axpy(-1.0, work.q, work.r);
  double normR = std::sqrt(dot(work.r, work.r));
  result.relativeResidual = normR / normB;
  if (result.relativeResidual <= settings.tolerance) {
    result.converged = true;
    return result;
  }
  precondition(work.r, work.z);
  copy(work.z, work.p);
  double rz = dot(work.r, work.z);
  for (int it = 1; it <= settings.maxIterations; ++it) {
    a.apply(work.p, work.q);
    const double pq = dot(work.p, work.q);
    if (!(pq > 0.0)) {
      std::ostringstream msg;
      msg << "implicit solve: p^T A p = " << pq << " <= 0 at CG iteration " << it
          << "; the momentum operator is not positive definite (check for NaN velocities or negative coefficients)";
      throw NumericalError(msg.str());
    }
    const double alpha = rz / pq;
    axpy(alpha, work.p, x);
    axpy(-alpha, work.q, work.r);
    normR = std::sqrt(dot(work.r, work.r));
    result.iterations = it;
    result.relativeResidual = normR / normB;
    if (result.relativeResidual <= settings.tolerance) {
      result.converged = true;
      return result;
    }
    precondition(work.r, work.z);
    const double rzNew = dot(work.r, work.z);
    xpay(work.z, rzNew / rz, work.p);
    rz = rzNew;
  }
  return result;
}

} // namespace poro::linalg
