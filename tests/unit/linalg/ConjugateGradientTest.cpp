// linalg::solveCg (linalg/ConjugateGradient.hpp) on a dense symmetric positive definite matrix over two parts: the
// residual it reports is the true one, it reaches the solution, and the storage the implicit solve shares (z in q's
// place) changes no bit of it.

#include "linalg/ConjugateGradient.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace poro::linalg {
namespace {

/// y = A x for a dense matrix over the blocks of all parts, in order.
class DenseOperator : public BlockOperator {
public:
  explicit DenseOperator(Eigen::MatrixXd a) : a_(std::move(a)) {}
  void apply(const BlockVector& x, const BlockVector& y) const override { scatter(a_ * gather(x), y); }
  static Eigen::VectorXd gather(const BlockVector& x) {
    std::vector<double> flat;
    for (const Vec3Span& part : x)
      for (std::size_t i = 0; i < part.size; ++i)
        for (int c = 0; c < 3; ++c) flat.push_back(part.data[i][c]);
    return Eigen::Map<Eigen::VectorXd>(flat.data(), static_cast<Eigen::Index>(flat.size()));
  }
  static void scatter(const Eigen::VectorXd& flat, const BlockVector& y) {
    Eigen::Index k = 0;
    for (const Vec3Span& part : y)
      for (std::size_t i = 0; i < part.size; ++i)
        for (int c = 0; c < 3; ++c) part.data[i][c] = flat[k++];
  }

private:
  Eigen::MatrixXd a_;
};

/// Storage for one block vector over parts of the given sizes.
struct Storage {
  explicit Storage(const std::vector<std::size_t>& sizes) {
    for (std::size_t n : sizes) parts.emplace_back(n, Vec3::Zero());
  }
  BlockVector view() {
    BlockVector v;
    for (auto& part : parts) v.push_back({part.data(), part.size()});
    return v;
  }
  std::vector<std::vector<Vec3>> parts;
};

class ConjugateGradient : public ::testing::Test {
protected:
  // Two parts, as a fluid and a porous set: 5 + 7 blocks, 36 unknowns.
  const std::vector<std::size_t> sizes{5, 7};
  const Eigen::Index n = 36;

  void SetUp() override {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::MatrixXd b(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j) b(i, j) = uniform(random);
    // B B^T + I: SPD with a condition number of 45 (seed 7), so CG needs many iterations, not one.
    matrix = b * b.transpose() + Eigen::MatrixXd::Identity(n, n);
    solution = Eigen::VectorXd(n);
    for (Eigen::Index i = 0; i < n; ++i) solution[i] = uniform(random);
    // Block Jacobi: the inverted 3x3 diagonal blocks, as ImplicitSolver forms them.
    for (Eigen::Index k = 0; k < n / 3; ++k)
      inverseBlocks.emplace_back(Mat3(matrix.block<3, 3>(3 * k, 3 * k).inverse()));
  }

  BlockPreconditioner preconditioner() const {
    BlockPreconditioner m;
    std::size_t first = 0;
    for (std::size_t size : sizes) {
      m.push_back({inverseBlocks.data() + first, size});
      first += size;
    }
    return m;
  }

  /// Solves from x = 0; with zInQ, z uses q's storage as in ImplicitSolver.
  Eigen::VectorXd solve(bool preconditioned, bool zInQ, CgResult& result) {
    Storage b(sizes), x(sizes), r(sizes), z(sizes), p(sizes), q(sizes);
    DenseOperator::scatter(matrix * solution, b.view());
    const CgWork work{r.view(), zInQ ? q.view() : z.view(), p.view(), q.view()};
    const CgSettings settings{1e-10, 200, {}};
    result = solveCg(DenseOperator(matrix), preconditioned ? preconditioner() : BlockPreconditioner{}, b.view(),
                     x.view(), work, settings);
    return DenseOperator::gather(x.view());
  }

  Eigen::MatrixXd matrix;
  Eigen::VectorXd solution;
  std::vector<SymmetricBlock> inverseBlocks;
};

TEST_F(ConjugateGradient, ReportsTheTrueResidualAndReachesTheSolution) {
  for (bool preconditioned : {false, true}) {
    CgResult result;
    const Eigen::VectorXd x = solve(preconditioned, false, result);
    ASSERT_TRUE(result.converged) << "preconditioned " << preconditioned;
    EXPECT_GT(result.iterations, 5); // a real Krylov solve, not a lucky first step
    const Eigen::VectorXd rhs = matrix * solution;
    const double trueResidual = (rhs - matrix * x).norm() / rhs.norm();
    // The recurrence r -= alpha q drifts from b - A x by round-off only: ~1e-15 per iteration times the matrix's norm.
    EXPECT_NEAR(result.relativeResidual, trueResidual, 1e-12) << "preconditioned " << preconditioned;
    EXPECT_LE(trueResidual, 1e-10 + 1e-12);
    // Error <= condition number x residual: 45 x 1e-10 = 4.5e-9.
    EXPECT_LT((x - solution).norm() / solution.norm(), 1e-8) << "preconditioned " << preconditioned;
  }
}

TEST_F(ConjugateGradient, SharingQsStorageForZChangesNothing) {
  for (bool preconditioned : {false, true}) {
    CgResult separate, shared;
    const Eigen::VectorXd a = solve(preconditioned, false, separate);
    const Eigen::VectorXd b = solve(preconditioned, true, shared);
    EXPECT_EQ(separate.iterations, shared.iterations);
    for (Eigen::Index i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << "unknown " << i;
  }
}

} // namespace
} // namespace poro::linalg
