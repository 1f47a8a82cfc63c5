#pragma once
/// A vector of 3-blocks spread over several particle sets: a list of views over particle-set storage
/// (STYLE.md §3: Krylov vectors are views, never copies). Reductions are deterministic (core/Parallel.hpp).

#include "core/Types.hpp"

#include <vector>

namespace poro::linalg {

/// A contiguous run of 3-blocks owned by someone else (one particle set's field).
struct Vec3Span {
  Vec3* data = nullptr;
  std::size_t size = 0;
};

/// Views over one field per particle set; all BlockVectors of one solve have the same part sizes.
using BlockVector = std::vector<Vec3Span>;

/// Views over one Mat3 field per particle set (block diagonals, inverted preconditioner blocks).
struct Mat3Span {
  Mat3* data = nullptr;
  std::size_t size = 0;
};
using BlockDiagonal = std::vector<Mat3Span>;

/// <a, b>, summed part by part with fixed blocking.
double dot(const BlockVector& a, const BlockVector& b);
/// y <- y + s x
void axpy(double s, const BlockVector& x, const BlockVector& y);
/// y <- x + s y
void xpay(const BlockVector& x, double s, const BlockVector& y);
/// y <- x
void copy(const BlockVector& x, const BlockVector& y);
/// y <- D x, block by block.
void multiply(const BlockDiagonal& d, const BlockVector& x, const BlockVector& y);

} // namespace poro::linalg
