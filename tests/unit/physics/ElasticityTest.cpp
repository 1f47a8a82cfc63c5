// Corotated elasticity with porous effects (METHOD.md §4.1, §6.5.2, §6.5.4, §6.5.8; Eq. 19-21).

#include "physics/Elasticity.hpp"
#include "PorousTestSystems.hpp"
#include "physics/RotationExtraction.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace poro {
namespace {

using namespace test;

const char* const kU = "testU";
const char* const kAu = "testAu";
const char* const kW = "testW";
const char* const kAw = "testAw";
const char* const kB = "testB";
constexpr double kDt = 1e-3;

PorousMaterial rubber(double youngs = 2.5e5, double poisson = 0.33) {
  PorousMaterial m = material("rubber", 0.6, 2500.0, false);
  m.youngsModulus = youngs;
  m.poissonsRatio = poisson;
  return m;
}

Mat3 rotationAbout(const Vec3& axis, double angle) {
  return Mat3(Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix());
}

/// A block of elastic porous particles (no fluid, no walls, no gravity) whose positions can be deformed
/// after the rest state X was taken; an optional second block is another object of the same material.
class ElasticBlock : public ::testing::Test {
protected:
  void build(const PorousMaterial& m, bool secondObject = false, bool jitter = false,
             const Vec3& size = Vec3(0.12, 0.1, 0.08)) {
    std::vector<Vec3> x = sampleBox(Vec3::Zero(), size, kR);
    if (jitter) {
      std::mt19937 rng(5);
      std::uniform_real_distribution<double> d(-0.2 * kR, 0.2 * kR);
      for (Vec3& p : x) p += Vec3(d(rng), d(rng), d(rng));
    }
    ParticleSystem ps(kR);
    ParticleSet& set = addSet(ps, m.name, SetKind::Porous, x, 0);
    if (secondObject) appendObject(set, sampleBox(Vec3(0.12, 0, 0), Vec3(0.2, 0.1, 0.08), kR), 1);
    solver_ = std::make_unique<Solver>(std::move(ps), weightless(), std::vector<PorousMaterial>{m}, SolverSettings{},
                                       fixedStep(kDt), RunState{});
  }
  ParticleSet& set() { return solver_->particles()[0]; }
  /// x = map(X) for every particle; the rotation warm start is set to `warm`.
  template <class Map> void deform(const Map& map, const Mat3& warm = Mat3::Identity()) {
    auto& x = set().x();
    const auto& rest = set().vec3(field::restPosition);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = map(rest[i]);
    for (Mat3& r : set().mat3(field::rotation)) r = warm;
  }
  void begin() {
    ctx_ = std::make_unique<StepContext>(solver_->beginStep(kDt));
    for (const char* name : {kU, kAu, kW, kAw, kB}) set().addVec3(name);
  }
  linalg::BlockVector view(const char* name) const { return ImplicitSolver::view(*ctx_, name); }
  void randomise(const char* name, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (auto& part : view(name))
      for (std::size_t i = 0; i < part.size; ++i) part.data[i] = Vec3(value(rng), value(rng), value(rng));
  }
  /// Elastic forces of the position part (rhs minus momentum, over dt), with the term prepared on ctx_.
  std::vector<Vec3> positionForces(Elasticity& term) {
    term.prepare(*ctx_);
    const auto b = view(kB);
    for (std::size_t i = 0; i < b[0].size; ++i) b[0].data[i].setZero();
    term.addRhs(b);
    std::vector<Vec3> f(b[0].size);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] = b[0].data[i] / kDt;
    return f;
  }
  /// At a rigidly rotated rest pose the position-part force is linear in x to first order (the rotation's change is
  /// skew and drops out of sym): [F^x(x + h w) - F^x(x - h w)] / 2h = F^u(w) / dt.
  void checkVelocityPartLinearisesPositionPart(const PorousMaterial& m);
  /// Scale of one particle's elastic force for a strain of 1: E V0 / H.
  double forceScale(const PorousMaterial& m) const { return m.youngsModulus * std::pow(2 * kR, 3) / (4 * kR); }

  std::unique_ptr<Solver> solver_;
  std::unique_ptr<StepContext> ctx_;
};

TEST_F(ElasticBlock, CorrectedGradientReproducesIdentityEverywhere) {
  // sum_{t in N0(s)} V0_t (X_t - X_s) (x) L_s gradW(X_s - X_t) = I, surfaces and corners included (§4.1).
  build(rubber(), true, true);
  begin();
  Elasticity term;
  term.prepare(*ctx_);
  const ElasticRestState& rest = term.restState(0);
  const auto& X = set().vec3(field::restPosition);
  const auto& object = set().integer(field::objectId);
  ASSERT_EQ(rest.size(), set().size());
  for (std::size_t s = 0; s < rest.size(); ++s) {
    Mat3 sum = Mat3::Zero();
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
      ASSERT_EQ(object[t], object[s]) << "elastic links never span objects";
      sum += (X[t] - X[s]) * (rest.correction(s) * rest.weightedGradient(pair)).transpose();
    }
    EXPECT_LT((sum - Mat3::Identity()).norm(), 1e-12) << "particle " << s;
  }
}

// Rounded rest gradients gradW(X_s - X_t), as every elastic term reads them: shared through a table of their
// distinct values on a lattice (a few dozen: one per offset within H), kept per pair where they are too many;
// either way the same bits as computed from the rest positions.
void expectRestGradientsAsComputed(const ElasticRestState& rest, const std::vector<Vec3>& restX,
                                   const CubicKernel& kernel) {
  std::size_t wrong = 0;
  for (std::size_t s = 0; s < rest.size(); ++s)
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const Vec3 g = kernel.grad(restX[s] - restX[static_cast<std::size_t>(rest.neighbour(pair))]);
      const Vec3 read = rest.gradient(pair);
      for (int d = 0; d < 3; ++d) wrong += read[d] != static_cast<double>(static_cast<float>(g[d]));
    }
  EXPECT_EQ(wrong, 0u);
}

TEST_F(ElasticBlock, RestGradientsOfALatticeShareTheirDistinctValues) {
  build(rubber());
  begin();
  Elasticity term;
  term.prepare(*ctx_);
  const ElasticRestState& rest = term.restState(0);
  // 26 lattice offsets within H = 2 spacings (|o|^2 = 1, 2, 3 spacings^2); round-off in X_s - X_t may split one
  // into neighbouring floats (30 values here).
  EXPECT_GE(rest.sharedGradients(), 26u);
  EXPECT_LE(rest.sharedGradients(), 4 * 26u);
  expectRestGradientsAsComputed(rest, set().vec3(field::restPosition), ctx_->kernel);
}

/// The rest state of one rubber body at positions x, as elasticity prepares it for the first step.
class RestStateOf {
public:
  explicit RestStateOf(const std::vector<Vec3>& x) {
    ParticleSystem ps(kR);
    addSet(ps, "rubber", SetKind::Porous, x, 0);
    solver_ = std::make_unique<Solver>(std::move(ps), weightless(), std::vector<PorousMaterial>{rubber()},
                                       SolverSettings{}, fixedStep(kDt), RunState{});
    const StepContext ctx = solver_->beginStep(kDt);
    term_.prepare(ctx);
    kernel_ = &ctx.kernel; // the solver's own
  }
  const ElasticRestState& rest() const { return term_.restState(0); }
  /// Fails the test unless every pair reads the gradient computed from the rest positions.
  void expectGradientsAsComputed() const {
    expectRestGradientsAsComputed(rest(), solver_->particles()[0].vec3(field::restPosition), *kernel_);
  }

private:
  std::unique_ptr<Solver> solver_;
  Elasticity term_;
  const CubicKernel* kernel_ = nullptr;
};

TEST(ElasticRestState, RestGradientsOfAnIrregularBodyAreKeptPerPairWhenTooManyToShare) {
  // A jittered 15^3 block: every pair its own value (the two directions of a pair opposite), about 90,000 of
  // them, more than the 2^16 codes.
  std::vector<Vec3> x = sampleBox(Vec3::Zero(), Vec3(0.3, 0.3, 0.3), kR);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-0.2 * kR, 0.2 * kR);
  for (Vec3& p : x) p += Vec3(d(rng), d(rng), d(rng));
  const RestStateOf body(x);
  ASSERT_GT(body.rest().end(body.rest().size() - 1), std::size_t(1) << 16);
  EXPECT_EQ(body.rest().sharedGradients(), 0u);
  body.expectGradientsAsComputed();
}

TEST(ElasticRestState, ALargeLatticeBodySharesItsFewDistinctRestGradients) {
  // 17^3 particles: two blocks of distinct gradients to merge, each with far more pairs than its buffer holds
  // before it is made distinct again (about 100,000 against 4,096), so the values are gathered in many rounds.
  const std::vector<Vec3> x = sampleBox(Vec3::Zero(), Vec3(0.34, 0.34, 0.34), kR);
  ASSERT_EQ(x.size(), 17u * 17u * 17u);
  const RestStateOf body(x);
  ASSERT_GT(body.rest().end(body.rest().size() - 1), 100000u);
  EXPECT_GE(body.rest().sharedGradients(), 26u);
  EXPECT_LE(body.rest().sharedGradients(), 4 * 26u);
  body.expectGradientsAsComputed();
}

TEST_F(ElasticBlock, RestStateIsRebuiltWhenTheParticlesAreReorderedOrRemoved) {
  // Its pairs are indices into the set's order: a reordering (Morton sort), a removal or other ids (a restart)
  // must rebuild them, and nothing else need.
  build(rubber());
  begin();
  const CubicKernel& kernel = ctx_->kernel;
  ElasticRestState rest;
  ASSERT_TRUE(rest.update(set(), kernel));
  EXPECT_FALSE(rest.update(set(), kernel)) << "nothing changed";
  const auto& ids = set().integer(field::id);
  const auto neighbourIds = [&](std::size_t s) {
    std::vector<std::int64_t> out;
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair)
      out.push_back(ids[static_cast<std::size_t>(rest.neighbour(pair))]);
    return out;
  };
  const std::vector<std::int64_t> ofSeven = neighbourIds(7);
  std::vector<Index> order(set().size());
  std::iota(order.begin(), order.end(), Index{0});
  std::swap(order[3], order[7]); // two particles trade places
  set().permute(order);
  EXPECT_TRUE(rest.update(set(), kernel));
  EXPECT_EQ(neighbourIds(3), ofSeven);
  EXPECT_FALSE(rest.update(set(), kernel));
  set().remove({0});
  EXPECT_TRUE(rest.update(set(), kernel));
  set().integer(field::id)[5] += 100000;
  EXPECT_TRUE(rest.update(set(), kernel));
}

TEST_F(ElasticBlock, ShepardRestVolumesMatchTheLatticeTable) {
  // V0/V = 1.00003 interior, 1.176 face, 1.390 edge, 1.649 corner (METHOD.md §2.2).
  build(rubber());
  begin();
  Elasticity term;
  term.prepare(*ctx_);
  const ElasticRestState& rest = term.restState(0);
  const auto& X = set().vec3(field::restPosition);
  const double v = std::pow(2 * kR, 3);
  auto volumeAt = [&](const Vec3& p) { return rest.volume(nearest(X, p)) / v; };
  EXPECT_NEAR(volumeAt(Vec3(0.05, 0.05, 0.03)), 1.00003, 1e-4);
  EXPECT_NEAR(volumeAt(Vec3(0.05, 0.05, 0.0)), 1.176, 2e-3);
  EXPECT_NEAR(volumeAt(Vec3(0.05, 0.0, 0.0)), 1.390, 2e-3);
  EXPECT_NEAR(volumeAt(Vec3(0.0, 0.0, 0.0)), 1.649, 2e-3);
}

TEST(RotationExtraction, WarmStartedCallsConvergeToTheRotationOfQS) {
  const Mat3 q = rotationAbout(Vec3(1, 2, -0.5), 2.0);
  Mat3 sym;
  sym << 1.3, 0.2, -0.1, 0.2, 0.8, 0.05, -0.1, 0.05, 1.1;
  Mat3 r = Mat3::Identity();
  for (int call = 0; call < 20; ++call) r = extractRotation(q * sym, r);
  EXPECT_LT((r - q).norm(), 1e-6);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
}

// The polar rotation U V^T of f = U S V^T: the rotation that maximises tr(R^T f), which the extraction seeks.
Mat3 polarRotation(const Mat3& f) {
  const Eigen::JacobiSVD<Mat3> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

TEST(RotationExtraction, OneWarmStartedCallReachesThePolarRotationOfAStrongStretch) {
  // A stretch of 2 : 0.5 : 1 warm-started 0.3 rad away: the plain step omega = g/tr contracts the error only by
  // about s_max/tr(S) = 0.57 per iteration (0.57^10 = 4e-3 after the 10 allowed); the Newton step on
  // H = tr(M) I - sym(M) converges quadratically, so a single call lands on U V^T to round-off.
  const Mat3 q = rotationAbout(Vec3(1, 2, -0.5), 2.0);
  const Mat3 stretch = Vec3(2.0, 0.5, 1.0).asDiagonal();
  const Mat3 shear = rotationAbout(Vec3(0.2, -1, 0.4), 0.6);
  const Mat3 f = q * shear * stretch * shear.transpose();
  const Mat3 start = rotationAbout(Vec3(-1, 0.3, 0.8), 0.3) * q;
  const Mat3 r = extractRotation(f, start);
  EXPECT_LT((r - polarRotation(f)).norm(), 1e-12);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
}

TEST(RotationExtraction, InvertedAndFlatDeformationsGiveRotations) {
  // No polar decomposition with det > 0 exists for these; the extraction must still return a rotation near
  // the start and never NaN (METHOD.md §6.5.2: robust for inverted and degenerate F).
  const Mat3 q = rotationAbout(Vec3(0.3, 1, 0.2), 0.7);
  Mat3 inverted = q;
  inverted.col(2) *= -1.0;
  Mat3 flat = q;
  flat.col(1).setZero();
  for (const Mat3& f : {inverted, flat, Mat3(Mat3::Zero())}) {
    const Mat3 r = extractRotation(f, q);
    ASSERT_TRUE(r.allFinite());
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
    EXPECT_LT((r * r.transpose() - Mat3::Identity()).norm(), 1e-12);
  }
  // A flattened F keeps the rotation it had (its remaining columns agree with q).
  EXPECT_LT((extractRotation(flat, q) - q).norm(), 1e-12);
}

TEST_F(ElasticBlock, RigidRotationGivesItsRotationAndNoForce) {
  const PorousMaterial m = rubber();
  build(m);
  const Mat3 q = rotationAbout(Vec3(0.3, 1, 0.2), 0.7);
  const Vec3 shift(0.4, -0.2, 0.1);
  deform([&](const Vec3& p) { return Vec3(q * p + shift); });
  begin();
  Elasticity term;
  // Warm-started from I: repeated steps at the same pose converge (the solver runs one extraction per step).
  for (int k = 0; k < 5; ++k) term.prepare(*ctx_);
  const std::vector<Vec3> f = positionForces(term);
  const auto& r = set().mat3(field::rotation);
  // The extraction stops at |omega| < 1e-9 (an angle of about 1.5e-9 for F = R), hence 1e-8.
  for (std::size_t s = 0; s < f.size(); ++s) {
    EXPECT_LT((r[s] - q).norm(), 1e-8) << "particle " << s;
    EXPECT_LT(term.strain(0, s).norm(), 1e-8) << "particle " << s;
    EXPECT_LT(f[s].norm(), 1e-8 * forceScale(m)) << "particle " << s;
  }
}

TEST_F(ElasticBlock, AffineStretchGivesItsStrainExactlyEverywhere) {
  // x = A X with A symmetric positive definite: eps = A - I at every particle, surfaces included (§6.5.4).
  build(rubber(), false, true);
  Mat3 a;
  a << 1.02, 0.005, -0.003, 0.005, 0.99, 0.004, -0.003, 0.004, 1.01;
  deform([&](const Vec3& p) { return Vec3(a * p); });
  begin();
  Elasticity term;
  term.prepare(*ctx_);
  for (std::size_t s = 0; s < set().size(); ++s)
    EXPECT_LT((term.strain(0, s) - (a - Mat3::Identity())).norm(), 1e-10) << "particle " << s;
}

TEST_F(ElasticBlock, FreeSwellingByBloatingIsAnEquilibrium) {
  // Uniform S and no gravity: expanding by eta_bloat S / (3K), K = lambda + 2 mu / 3, zeroes every stress.
  PorousMaterial m = rubber();
  m.bloating = 3e4;
  build(m);
  const double saturation = 0.8;
  const double bulk = m.lameLambda() + 2.0 * m.shearModulus() / 3.0;
  const double swelling = m.bloating * saturation / (3.0 * bulk);
  deform([&](const Vec3& p) { return Vec3((1.0 + swelling) * p); });
  begin();
  for (double& s : set().real(field::saturation)) s = saturation;
  Elasticity term;
  const std::vector<Vec3> swollen = positionForces(term);
  deform([&](const Vec3& p) { return p; });
  for (double& s : set().real(field::saturation)) s = saturation;
  const std::vector<Vec3> unswollen = positionForces(term);
  double largest = 0.0;
  for (const Vec3& f : unswollen) largest = std::max(largest, f.norm());
  ASSERT_GT(largest, 1e-3 * forceScale(m)) << "bloating must push a body at its rest size";
  for (std::size_t s = 0; s < swollen.size(); ++s) EXPECT_LT(swollen[s].norm(), 1e-9 * largest) << "particle " << s;
}

/// Momentum: the forces sum to zero, to round-off of their magnitudes (which must not all vanish).
void expectForcesCancel(const std::vector<Vec3>& forces) {
  Vec3 total = Vec3::Zero();
  double scale = 0.0;
  for (const Vec3& f : forces) {
    total += f;
    scale += f.norm();
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(total.norm(), 1e-12 * scale);
}

TEST_F(ElasticBlock, PairForcesCancel) {
  // Momentum: sum of the position-part forces and of the velocity-part forces vanish to round-off.
  build(rubber(), true, true);
  Mat3 a;
  a << 1.05, 0.02, 0.0, -0.01, 0.97, 0.03, 0.02, 0.0, 1.01;
  const Mat3 q = rotationAbout(Vec3(0, 0, 1), 0.3);
  deform([&](const Vec3& p) { return Vec3(q * a * p); });
  begin();
  Elasticity term;
  expectForcesCancel(positionForces(term));

  randomise(kU, 3);
  solver_->implicitSolver().prepare(*ctx_);
  solver_->implicitSolver().apply(view(kU), view(kAu));
  const auto u = view(kU), au = view(kAu);
  std::vector<Vec3> velocityForces(u[0].size);
  for (std::size_t i = 0; i < u[0].size; ++i) velocityForces[i] = au[0].data[i] - set().mass * u[0].data[i];
  expectForcesCancel(velocityForces);
}

TEST_F(ElasticBlock, OperatorIsSymmetricPositiveDefiniteWithExactDiagonalUnderARigidRotation) {
  build(rubber(2.5e5, 0.45), true, true);
  deform([&](const Vec3& p) { return Vec3(rotationAbout(Vec3(1, 1, 0), 0.4) * p); }, rotationAbout(Vec3(1, 1, 0), 0.4));
  begin();
  for (std::size_t s = 0; s < set().size(); ++s) set().real(field::saturation)[s] = (s % 7) / 6.0;
  const ImplicitSolver& op = solver_->implicitSolver();
  solver_->implicitSolver().prepare(*ctx_);
  randomise(kU, 1);
  randomise(kW, 2);
  op.apply(view(kU), view(kAu));
  op.apply(view(kW), view(kAw));
  const double wAu = linalg::dot(view(kW), view(kAu)), awU = linalg::dot(view(kAw), view(kU));
  EXPECT_NEAR(wAu, awU, 1e-12 * std::abs(wAu));
  EXPECT_GT(linalg::dot(view(kU), view(kAu)), 0.0);

  set().addMat3("testD");
  linalg::BlockDiagonal d{{set().mat3("testD").data(), set().size()}};
  op.diagonal(d);
  const auto u = view(kU), au = view(kAu);
  for (std::size_t i = 0; i < u[0].size; i += 7)
    for (int c = 0; c < 3; ++c) {
      for (std::size_t j = 0; j < u[0].size; ++j) u[0].data[j].setZero();
      u[0].data[i][c] = 1.0;
      op.apply(u, au);
      const Vec3 column = au[0].data[i];
      // The body turns as a whole, so the preconditioner's blocks are the operator's: to round-off, and to single
      // precision in the neighbours' rest moment S_s that they are formed from.
      const double elastic = (d[0].data[i] - set().mass * Mat3::Identity()).norm();
      EXPECT_LT((column - d[0].data[i].col(c)).norm(), 1e-12 * column.norm() + 1e-6 * elastic) << "particle " << i;
      // The elastic part of the diagonal is really there: more than the mass alone.
      EXPECT_GT(d[0].data[i](c, c), set().mass * (1.0 + 1e-3));
    }
}

/// A block of material m twisted by 2 rad/m about x on top of a turn of 0.5 rad about (1, 2, 3), its rotations
/// settled by warm-started extractions: the neighbours' rotations differ. Holds the term's preconditioner blocks
/// and the operator's diagonal blocks, probed with each particle's three unit vectors.
class TwistedBlock : public ElasticBlock {
protected:
  void twist(const PorousMaterial& m, bool varySaturation = false) {
    build(m, false, true);
    const Mat3 turn = rotationAbout(Vec3(1, 2, 3), 0.5);
    deform([&](const Vec3& p) { return Vec3(turn * rotationAbout(Vec3(1, 0, 0), 2.0 * p.x()) * p); }, turn);
    begin();
    if (varySaturation)
      for (std::size_t s = 0; s < set().size(); ++s) set().real(field::saturation)[s] = (s % 7) / 6.0;
    for (int k = 0; k < 4; ++k) term_.prepare(*ctx_);
    const std::size_t n = set().size();
    set().addMat3("testD");
    linalg::BlockDiagonal d{{set().mat3("testD").data(), n}};
    for (std::size_t i = 0; i < n; ++i) d[0].data[i].setZero();
    term_.addDiagonal(d);
  }
  const Mat3& preconditioner(std::size_t i) { return set().mat3("testD")[i]; }
  Mat3 diagonal(std::size_t i) {
    const auto u = view(kU), au = view(kAu);
    Mat3 block;
    for (int c = 0; c < 3; ++c) {
      for (std::size_t j = 0; j < u[0].size; ++j) {
        u[0].data[j].setZero();
        au[0].data[j].setZero();
      }
      u[0].data[i][c] = 1.0;
      term_.addApply(u, au);
      block.col(c) = au[0].data[i];
    }
    return block;
  }
  Elasticity term_;
};

TEST_F(TwistedBlock, StiffBodysPreconditionerIsTheExactDiagonal) {
  // E = 1 GPa: the neighbours' blocks outweigh the mass many times, so they are summed pair by pair with their own
  // rotations.
  twist(rubber(1e9, 0.4));
  for (std::size_t i = 0; i < set().size(); i += 5) {
    const Mat3 exact = diagonal(i);
    EXPECT_LT((exact - preconditioner(i)).norm(), 1e-12 * exact.norm()) << "particle " << i;
  }
}

TEST_F(TwistedBlock, SofteningBodysPreconditionerIsTheExactDiagonal) {
  // Softening with saturation gives the neighbours moduli of their own, which the rest moment cannot carry.
  PorousMaterial m = rubber(2.5e5, 0.3);
  m.shearSoftening = -0.5;
  m.volumeSoftening = -0.3;
  twist(m, true);
  for (std::size_t i = 0; i < set().size(); i += 5) {
    const Mat3 exact = diagonal(i);
    EXPECT_LT((exact - preconditioner(i)).norm(), 1e-12 * exact.norm()) << "particle " << i;
  }
}

TEST_F(TwistedBlock, SoftBodysPreconditionerIsWithinTheNeighboursRotationsOfTheDiagonal) {
  // The preconditioner takes each neighbour's rotation as the particle's own. A neighbour turned by delta against it
  // moves its block B by R (Q B Q^T - B) R^T, |Q - I| = 2 sin(delta / 2), so the blocks differ from the operator's
  // diagonal by at most dt^2 V0_s^2 4 sin(delta_max / 2) (2 mu + lambda) tr(S_s), delta_max the largest relative
  // rotation among s's rest neighbours. Blocks turned the wrong way (R^T S R) would miss by the 0.5 rad turn.
  const PorousMaterial m = rubber(2.5e5, 0.3);
  twist(m);
  const ElasticRestState& rest = term_.restState(0);
  const auto& rotation = set().mat3(field::rotation);
  const double mu = m.shearModulus(), lambda = m.lameLambda();
  double largestDelta = 0.0, largestMiss = 0.0;
  for (std::size_t i = 0; i < set().size(); i += 5) {
    double delta = 0.0;
    for (std::size_t pair = rest.begin(i); pair < rest.end(i); ++pair) {
      const Mat3 q = rotation[i].transpose() * rotation[static_cast<std::size_t>(rest.neighbour(pair))];
      delta = std::max(delta, std::acos(std::clamp(0.5 * (q.trace() - 1.0), -1.0, 1.0)));
    }
    const double v0 = rest.volume(i);
    const double bound =
        kDt * kDt * v0 * v0 * 4.0 * std::sin(0.5 * delta) * (2.0 * mu + lambda) * rest.neighbourMoment(i).trace();
    const Mat3& block = preconditioner(i);
    EXPECT_GT(block.eigenvalues().real().minCoeff(), 0.0) << "particle " << i;
    EXPECT_LT((block - block.transpose()).norm(), 1e-12 * block.norm());
    const Mat3 exact = diagonal(i);
    for (int c = 0; c < 3; ++c) {
      const double miss = (exact.col(c) - block.col(c)).norm();
      EXPECT_LT(miss, bound + 1e-6 * exact.col(c).norm()) << "particle " << i << ", delta " << delta;
      largestMiss = std::max(largestMiss, miss / exact.col(c).norm());
    }
    largestDelta = std::max(largestDelta, delta);
  }
  EXPECT_GT(largestDelta, 0.02) << "the twist turns neighbours against each other";
  EXPECT_GT(largestMiss, 1e-5) << "the blocks are not the diagonal here";
}

TEST_F(ElasticBlock, VelocityPartIsTheLinearisationOfThePositionPart) {
  checkVelocityPartLinearisesPositionPart(rubber(2.5e5, 0.3));
}

TEST_F(ElasticBlock, VelocityPartIsTheLinearisationOfThePositionPartWithHourglassControl) {
  // The control's matrix part (dt^2 K u) and its right-hand side (-dt K x) with one sign and one dt each.
  PorousMaterial m = rubber(2.5e5, 0.3);
  m.hourglassControl = 3.0;
  checkVelocityPartLinearisesPositionPart(m);
}

void ElasticBlock::checkVelocityPartLinearisesPositionPart(const PorousMaterial& m) {
  build(m, false, true);
  const Mat3 q = rotationAbout(Vec3(1, -1, 2), 0.5);
  deform([&](const Vec3& p) { return Vec3(q * p); }, q);
  begin();
  randomise(kW, 9);
  const std::vector<Vec3> x0 = set().x();
  const auto w = view(kW);
  const double h = 1e-7;
  auto forcesAt = [&](double sign) {
    for (std::size_t i = 0; i < x0.size(); ++i) set().x()[i] = x0[i] + sign * h * w[0].data[i];
    for (Mat3& r : set().mat3(field::rotation)) r = q;
    Elasticity term;
    for (int k = 0; k < 3; ++k) term.prepare(*ctx_);
    return positionForces(term);
  };
  const std::vector<Vec3> plus = forcesAt(1.0), minus = forcesAt(-1.0);
  for (std::size_t i = 0; i < x0.size(); ++i) set().x()[i] = x0[i];
  for (Mat3& r : set().mat3(field::rotation)) r = q;
  Elasticity term;
  term.prepare(*ctx_);
  const auto aw = view(kAw);
  for (std::size_t i = 0; i < aw[0].size; ++i) aw[0].data[i].setZero();
  term.addApply(w, aw); // -dt F^u(w)
  double largest = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    const Vec3 difference = (plus[i] - minus[i]) / (2 * h);
    const Vec3 linear = -aw[0].data[i] / (kDt * kDt);
    largest = std::max(largest, linear.norm());
    worst = std::max(worst, (difference - linear).norm());
  }
  ASSERT_GT(largest, 0.0);
  EXPECT_LT(worst, 1e-5 * largest);
}

// Zero-energy-mode (hourglass) control (HourglassControl.hpp): an optional energy on what each particle's affine
// estimate F_s misses at its rest neighbours, E = 1/2 sum_s sum_t w_st |F_s X_st - x_st|^2.

/// The control of set 0's body with stiffness c, on the rest state an Elasticity term has built.
HourglassControl controlOf(const Elasticity& term, const ParticleSet& set, double c) {
  HourglassControl control;
  control.prepare(term.restState(0), set.vec3(field::restPosition), c, set.size(), {}, true);
  return control;
}

std::vector<Vec3> controlForces(const HourglassControl& control, const std::vector<Vec3>& y) {
  std::vector<Vec3> f(y.size(), Vec3::Zero());
  control.formGradients(y.data());
  control.addForces(y.data(), y.size(), 1.0, f.data());
  return f;
}

/// The control's weight k_st = -W'(r)/r, from the kernel in double (the control reads rounded rest gradients).
double laplacianWeight(const CubicKernel& kernel, const Vec3& offset) {
  return -kernel.grad(offset).dot(offset) / offset.squaredNorm();
}

TEST_F(ElasticBlock, HourglassControlIsZeroForEveryAffineMapAndConservesMomentum) {
  // Corrected gradients reproduce linear fields at every particle, surfaces and corners included, so a stretched,
  // sheared, turned and shifted body has no error to control; and E depends on differences only.
  const PorousMaterial m = rubber();
  build(m, true, true);
  Mat3 a;
  a << 1.05, 0.02, 0.0, -0.01, 0.97, 0.03, 0.02, 0.0, 1.01;
  const Mat3 q = rotationAbout(Vec3(0.2, 1, -0.4), 0.9);
  deform([&](const Vec3& p) { return Vec3(q * a * p + Vec3(0.3, -0.1, 0.2)); });
  begin();
  Elasticity term;
  term.prepare(*ctx_);
  const double c = 2.0 * m.shearModulus();
  const HourglassControl control = controlOf(term, set(), c);
  const double scale = c * std::pow(2 * kR, 3) / (4 * kR); // c V0 / H: the force of an error of one spacing's size
  const std::vector<Vec3> affine = controlForces(control, set().x());
  for (std::size_t s = 0; s < affine.size(); ++s) EXPECT_LT(affine[s].norm(), 1e-10 * scale) << "particle " << s;

  randomise(kU, 4);
  const auto u = view(kU);
  expectForcesCancel(controlForces(control, std::vector<Vec3>(u[0].data, u[0].data + u[0].size)));
}

TEST_F(ElasticBlock, HourglassControlResistsTheCheckerboardEq19DoesNotSee) {
  // u_s = d (-1)^(i+j+k) e_y on the lattice: every neighbour at an odd offset moves by -2 u_s relative to s, and
  // their gradients sum to zero by symmetry, so F_s = I and Eq. 19 exerts no force. The control's error is then
  // eps_st = -(u_t - u_s), and deep inside (every particle within 2H interior) its force is exactly
  // f_s = -4 u_s sum_{t odd} w_st.
  const PorousMaterial m = rubber();
  build(m, false, false, Vec3(0.24, 0.24, 0.24));
  const double d = 1e-3 * kR;
  const auto parity = [](const Vec3& p) {
    const long long sum = std::llround(p.x() / (2 * kR) - 0.5) + std::llround(p.y() / (2 * kR) - 0.5) +
                          std::llround(p.z() / (2 * kR) - 0.5);
    return sum % 2 == 0 ? 1.0 : -1.0;
  };
  deform([&](const Vec3& p) { return Vec3(p + parity(p) * d * Vec3::UnitY()); });
  begin();
  Elasticity term;
  const std::vector<Vec3> elastic = positionForces(term);
  const double c = m.shearModulus();
  const HourglassControl control = controlOf(term, set(), c);
  const std::vector<Vec3> f = controlForces(control, set().x());
  const ElasticRestState& rest = term.restState(0);
  const auto& X = set().vec3(field::restPosition);
  std::size_t interior = 0;
  for (std::size_t s = 0; s < set().size(); ++s) {
    const Vec3 p = X[s];
    if ((p.array() < 4 * 2 * kR).any() || (p.array() > 0.24 - 4 * 2 * kR).any()) continue;
    ++interior;
    double odd = 0.0;
    for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
      const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
      if (parity(X[t]) == parity(p)) continue;
      odd += c * rest.volume(s) * rest.volume(t) * laplacianWeight(ctx_->kernel, X[t] - p);
    }
    const Vec3 expected = -4.0 * odd * parity(p) * d * Vec3::UnitY();
    ASSERT_GT(expected.norm(), 0.0);
    EXPECT_LT((f[s] - expected).norm(), 1e-6 * expected.norm()) << "particle " << s;
    EXPECT_LT(elastic[s].norm(), 1e-6 * expected.norm()) << "Eq. 19 must not see the checkerboard, particle " << s;
  }
  EXPECT_EQ(interior, 64u);
}

TEST_F(ElasticBlock, HourglassForceIsMinusTheGradientOfItsEnergy) {
  // E summed here from its definition, independently of the control's two-pass gather; central differences.
  const PorousMaterial m = rubber();
  build(m, true, true);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.1 * kR, 0.1 * kR);
  const Mat3 q = rotationAbout(Vec3(1, 0.5, 0), 0.3);
  deform([&](const Vec3& p) { return Vec3(q * p + Vec3(jitter(rng), jitter(rng), jitter(rng))); });
  begin();
  Elasticity term;
  term.prepare(*ctx_);
  const ElasticRestState& rest = term.restState(0);
  const auto& X = set().vec3(field::restPosition);
  const double c = m.shearModulus();
  const HourglassControl control = controlOf(term, set(), c);
  const auto energy = [&](const std::vector<Vec3>& x) {
    double e = 0.0;
    for (std::size_t s = 0; s < x.size(); ++s) {
      Mat3 f = Mat3::Zero();
      for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
        const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
        f += (x[t] - x[s]) * (rest.correction(s) * rest.weightedGradient(pair)).transpose();
      }
      for (std::size_t pair = rest.begin(s); pair < rest.end(s); ++pair) {
        const std::size_t t = static_cast<std::size_t>(rest.neighbour(pair));
        const Vec3 offset = X[t] - X[s];
        const double w = c * rest.volume(s) * rest.volume(t) * laplacianWeight(ctx_->kernel, offset);
        e += 0.5 * w * (f * offset - (x[t] - x[s])).squaredNorm();
      }
    }
    return e;
  };
  const std::vector<Vec3> x0 = set().x();
  const std::vector<Vec3> f = controlForces(control, x0);
  const double h = 1e-8;
  double largest = 0.0;
  for (const Vec3& fs : f) largest = std::max(largest, fs.norm());
  ASSERT_GT(largest, 0.0);
  for (std::size_t s = 0; s < x0.size(); s += 37)
    for (int k = 0; k < 3; ++k) {
      std::vector<Vec3> plus = x0, minus = x0;
      plus[s][k] += h;
      minus[s][k] -= h;
      const double derivative = (energy(plus) - energy(minus)) / (2 * h);
      EXPECT_NEAR(f[s][k], -derivative, 1e-5 * largest) << "particle " << s << ", coordinate " << k;
    }
}

TEST_F(ElasticBlock, HourglassControlIsSymmetricPositiveWithItsExactDiagonal) {
  const PorousMaterial m = rubber();
  build(m, true, true);
  deform([&](const Vec3& p) { return Vec3(rotationAbout(Vec3(0, 1, 1), 0.6) * p); });
  begin();
  Elasticity term;
  term.prepare(*ctx_);
  const HourglassControl control = controlOf(term, set(), m.shearModulus());
  const std::size_t n = set().size();
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<Vec3> u(n), w(n);
  for (std::size_t i = 0; i < n; ++i) {
    u[i] = Vec3(value(rng), value(rng), value(rng));
    w[i] = Vec3(value(rng), value(rng), value(rng));
  }
  const std::vector<Vec3> ku = controlForces(control, u), kw = controlForces(control, w); // -K u, -K w
  double wKu = 0.0, uKw = 0.0, uKu = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    wKu -= w[i].dot(ku[i]);
    uKw -= u[i].dot(kw[i]);
    uKu -= u[i].dot(ku[i]);
  }
  EXPECT_NEAR(wKu, uKw, 1e-12 * std::abs(wKu));
  EXPECT_GT(uKu, 0.0);
  // Probed with a unit vector, K's column at the particle itself is K_ii e_c: the diagonal the preconditioner adds.
  std::vector<Vec3> unit(n, Vec3::Zero());
  for (std::size_t i = 0; i < n; i += 11)
    for (int k = 0; k < 3; ++k) {
      unit[i][k] = 1.0;
      const Vec3 column = -controlForces(control, unit)[i];
      unit[i][k] = 0.0;
      Vec3 expected = Vec3::Zero();
      expected[k] = control.diagonal(i);
      ASSERT_GT(expected[k], 0.0);
      EXPECT_LT((column - expected).norm(), 1e-12 * expected[k]) << "particle " << i << ", coordinate " << k;
    }
}

TEST_F(TwistedBlock, HourglassControlKeepsThePreconditionerTheExactDiagonal) {
  // Through Elasticity: the control's dt^2 K_ii joins the exact elastic blocks of a stiff body.
  PorousMaterial m = rubber(1e9, 0.4);
  m.hourglassControl = 4.0;
  twist(m);
  for (std::size_t i = 0; i < set().size(); i += 5) {
    const Mat3 exact = diagonal(i);
    EXPECT_LT((exact - preconditioner(i)).norm(), 1e-12 * exact.norm()) << "particle " << i;
  }
}

TEST_F(TwistedBlock, HourglassDiagonalKeptAcrossStepsFollowsAReorder) {
  // K_kk depends on the rest state alone and is formed only when that is rebuilt: after particles trade places the
  // preconditioner must be the diagonal at their new indices.
  PorousMaterial m = rubber(1e9, 0.4);
  m.hourglassControl = 4.0;
  build(m, false, true);
  begin();
  term_.prepare(*ctx_);
  std::vector<Index> order(set().size());
  std::iota(order.begin(), order.end(), Index{0});
  std::swap(order[0], order[40]); // a surface corner and an interior particle: different diagonals
  set().permute(order);
  term_.prepare(*ctx_);
  set().addMat3("testD");
  linalg::BlockDiagonal d{{set().mat3("testD").data(), set().size()}};
  for (std::size_t i = 0; i < set().size(); ++i) d[0].data[i].setZero();
  term_.addDiagonal(d);
  for (std::size_t i : {std::size_t{0}, std::size_t{40}}) {
    const Mat3 exact = diagonal(i);
    EXPECT_LT((exact - preconditioner(i)).norm(), 1e-12 * exact.norm()) << "particle " << i;
  }
}

} // namespace
} // namespace poro
