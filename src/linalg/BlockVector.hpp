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

/// Views over a window of Mat3 blocks per particle set: data[k] is the block of particle first + k (block diagonals,
/// which the implicit solve forms a window at a time).
struct Mat3Span {
  Mat3* data = nullptr;
  std::size_t size = 0;
  std::size_t first = 0;
};
using BlockDiagonal = std::vector<Mat3Span>;

/// A symmetric 3x3 block in single precision: an inverted diagonal block of the CG's preconditioner, which needs no
/// more (24 bytes instead of a Mat3's 72). Assigned from a Mat3, of which it keeps the symmetric part.
class SymmetricBlock {
public:
  SymmetricBlock() = default;
  explicit SymmetricBlock(const Mat3& m)
      : xx_(static_cast<float>(m(0, 0))), yy_(static_cast<float>(m(1, 1))), zz_(static_cast<float>(m(2, 2))),
        xy_(static_cast<float>(0.5 * (m(0, 1) + m(1, 0)))), xz_(static_cast<float>(0.5 * (m(0, 2) + m(2, 0)))),
        yz_(static_cast<float>(0.5 * (m(1, 2) + m(2, 1)))) {}
  Mat3 matrix() const {
    Mat3 m;
    m << xx_, xy_, xz_, xy_, yy_, yz_, xz_, yz_, zz_;
    return m;
  }
  Vec3 operator*(const Vec3& v) const {
    return Vec3(xx_ * v.x() + xy_ * v.y() + xz_ * v.z(), xy_ * v.x() + yy_ * v.y() + yz_ * v.z(),
                xz_ * v.x() + yz_ * v.y() + zz_ * v.z());
  }

private:
  float xx_ = 0.0f, yy_ = 0.0f, zz_ = 0.0f, xy_ = 0.0f, xz_ = 0.0f, yz_ = 0.0f;
};

/// Views over one array of SymmetricBlock per particle set: a block-Jacobi preconditioner.
struct SymmetricBlockSpan {
  const SymmetricBlock* data = nullptr;
  std::size_t size = 0;
};
using BlockPreconditioner = std::vector<SymmetricBlockSpan>;

/// <a, b>, summed part by part with fixed blocking.
double dot(const BlockVector& a, const BlockVector& b);
/// y <- y + s x
void axpy(double s, const BlockVector& x, const BlockVector& y);
/// y <- x + s y
void xpay(const BlockVector& x, double s, const BlockVector& y);
/// y <- x
void copy(const BlockVector& x, const BlockVector& y);
/// y <- M x, block by block.
void multiply(const BlockPreconditioner& m, const BlockVector& x, const BlockVector& y);

} // namespace poro::linalg
