#include "linalg/BlockVector.hpp"

#include "core/Parallel.hpp"

namespace poro::linalg {

double dot(const BlockVector& a, const BlockVector& b) {
  double total = 0.0;
  for (std::size_t p = 0; p < a.size(); ++p) {
    const Vec3* x = a[p].data;
    const Vec3* y = b[p].data;
    total += parallel::sum<double>(a[p].size, [&](std::size_t i) { return x[i].dot(y[i]); });
  }
  return total;
}

void axpy(double s, const BlockVector& x, const BlockVector& y) {
  for (std::size_t p = 0; p < x.size(); ++p) {
    const Vec3* xs = x[p].data;
    Vec3* ys = y[p].data;
    parallel::forEach(x[p].size, [&](std::size_t i) { ys[i] += s * xs[i]; });
  }
}

void xpay(const BlockVector& x, double s, const BlockVector& y) {
  for (std::size_t p = 0; p < x.size(); ++p) {
    const Vec3* xs = x[p].data;
    Vec3* ys = y[p].data;
    parallel::forEach(x[p].size, [&](std::size_t i) { ys[i] = xs[i] + s * ys[i]; });
  }
}

void copy(const BlockVector& x, const BlockVector& y) {
  for (std::size_t p = 0; p < x.size(); ++p) {
    const Vec3* xs = x[p].data;
    Vec3* ys = y[p].data;
    parallel::forEach(x[p].size, [&](std::size_t i) { ys[i] = xs[i]; });
  }
}

void multiply(const BlockPreconditioner& m, const BlockVector& x, const BlockVector& y) {
  for (std::size_t p = 0; p < x.size(); ++p) {
    const SymmetricBlock* ds = m[p].data;
    const Vec3* xs = x[p].data;
    Vec3* ys = y[p].data;
    parallel::forEach(x[p].size, [&](std::size_t i) { ys[i] = ds[i] * xs[i]; });
  }
}

} // namespace poro::linalg
