#include "linalg/ConjugateGradient.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

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

/// The squares an iteration needs after its step: r.r (convergence) and r.z (the next direction).
struct ResidualProducts {
  double rr = 0.0;
  double rz = 0.0;
  ResidualProducts& operator+=(const ResidualProducts& other) {
    rr += other.rr;
    rz += other.rz;
    return *this;
  }
};

/// x += alpha p, r -= alpha q, z = M r (or r without a preconditioner), and r.r, r.z: one pass over the vectors
/// where axpy, axpy, dot, multiply, dot made five. The sums keep dot()'s blocking, so every bit is as in five passes.
/// z may share q's storage: element i of q is read before element i of z is written.
ResidualProducts stepAndPrecondition(double alpha, const BlockVector& p, const BlockVector& q, const BlockVector& x,
                                     const BlockVector& r, const BlockPreconditioner& inverseDiagonal,
                                     const BlockVector& z) {
  ResidualProducts total;
  for (std::size_t part = 0; part < x.size(); ++part) {
    const Vec3* ps = p[part].data;
    const Vec3* qs = q[part].data;
    Vec3* xs = x[part].data;
    Vec3* rs = r[part].data;
    Vec3* zs = z[part].data;
    const SymmetricBlock* m = inverseDiagonal.empty() ? nullptr : inverseDiagonal[part].data;
    total += parallel::sum<ResidualProducts>(x[part].size, [&](std::size_t i) {
      xs[i] += alpha * ps[i];
      rs[i] += -alpha * qs[i];
      zs[i] = m ? Vec3(m[i] * rs[i]) : rs[i];
      return ResidualProducts{rs[i].dot(rs[i]), rs[i].dot(zs[i])};
    });
  }
  return total;
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
    ResidualProducts products = stepAndPrecondition(alpha, work.p, work.q, x, work.r, inverseDiagonal, work.z);
    if (settings.sumOverRanks) products = {settings.sumOverRanks(products.rr), settings.sumOverRanks(products.rz)};
    normR = std::sqrt(products.rr);
    result.iterations = it;
    result.relativeResidual = normR / normB;
    if (result.relativeResidual <= settings.tolerance) {
      result.converged = true;
      return result;
    }
    const double rzNew = products.rz;
    xpay(work.z, rzNew / rz, work.p);
    rz = rzNew;
  }
  return result;
}

} // namespace poro::linalg
