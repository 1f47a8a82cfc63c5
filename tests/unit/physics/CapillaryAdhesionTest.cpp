// Implicit capillary adhesion (METHOD.md §6.5.6, Eq. 11-15) as a term of the momentum operator (§6.5.1,
// §6.5.8), and the coupling densities it shares with the drag (§6.4, §10).

#include "physics/CapillaryAdhesion.hpp"
#include "PorousTestSystems.hpp"
#include "physics/CouplingDensity.hpp"
#include "physics/PorousDrag.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace poro {
namespace {

using namespace test;

const char* const kU = "testU";
const char* const kAu = "testAu";
const char* const kW = "testW";
const char* const kAw = "testAw";
const char* const kB = "testB";
const char* const kD = "testD";
constexpr double kDt = 1e-3;

PorousMaterial withCapillarity(PorousMaterial m, double strength, double falloff) {
  m.capillaryStrength = strength;
  m.capillaryFalloff = falloff;
  return m;
}

void zero(const linalg::BlockVector& v) {
  for (const auto& part : v)
    for (std::size_t i = 0; i < part.size; ++i) part.data[i].setZero();
}

void zero(const linalg::BlockDiagonal& d) {
  for (const auto& part : d)
    for (std::size_t i = 0; i < part.size; ++i) part.data[i].setZero();
}

/// The sum over all particles and its scale (sum of norms).
std::pair<Vec3, double> total(const linalg::BlockVector& v) {
  Vec3 sum = Vec3::Zero();
  double scale = 0.0;
  for (const auto& part : v)
    for (std::size_t i = 0; i < part.size; ++i) {
      sum += part.data[i];
      scale += part.data[i].norm();
    }
  return {sum, scale};
}

/// A prepared step of a solver with scratch fields for test vectors; the term under test is driven
/// directly, so its contributions are seen alone (no mass, no other term).
class Prepared {
public:
  Prepared(ParticleSystem ps, std::vector<PorousMaterial> materials, bool restDensity = false, bool fades = false) {
    SolverSettings settings = eq4AsPublished();                    // PairByHand evaluates Eq. 4 as published
    settings.compatibility.restCouplingSolidDensity = restDensity; // couplingSolidDensity: rest (METHOD.md §10)
    settings.implicit.adhesionFadesInFullPores = fades;            // Eq. 13 as published unless asked
    solver_ = std::make_unique<Solver>(std::move(ps), weightless(), std::move(materials), settings, fixedStep(kDt),
                                       RunState{});
    ctx_ = std::make_unique<StepContext>(solver_->beginStep(kDt));
    for (std::size_t a : ctx_->dynamicSets) {
      for (const char* name : {kU, kAu, kW, kAw, kB}) solver_->particles()[a].addVec3(name);
      solver_->particles()[a].addMat3(kD);
    }
  }
  StepContext& ctx() { return *ctx_; }
  ParticleSet& set(std::size_t part) { return solver_->particles()[ctx_->dynamicSets[part]]; }
  linalg::BlockVector view(const char* name) const { return ImplicitSolver::view(*ctx_, name); }
  linalg::BlockDiagonal diagonalView() const {
    linalg::BlockDiagonal d;
    for (std::size_t a : ctx_->dynamicSets) {
      auto& f = solver_->particles()[a].mat3(kD);
      d.push_back({f.data(), f.size()});
    }
    return d;
  }
  void randomise(const char* name, unsigned seed) const {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (const auto& part : view(name))
      for (std::size_t i = 0; i < part.size; ++i) part.data[i] = Vec3(value(rng), value(rng), value(rng));
  }
  /// au = the term's part of A u, -dt F(u).
  void apply(const ImplicitTerm& term, const char* u, const char* au) const {
    zero(view(au));
    term.addApply(view(u), view(au));
  }
  /// b = the term's part of b, dt F^x.
  void rhs(const ImplicitTerm& term, const char* b) const {
    zero(view(b));
    term.addRhs(view(b));
  }
  /// The term's diagonal blocks.
  linalg::BlockDiagonal diagonal(const ImplicitTerm& term) const {
    const linalg::BlockDiagonal d = diagonalView();
    zero(d);
    term.addDiagonal(d);
    return d;
  }

private:
  std::unique_ptr<Solver> solver_;
  std::unique_ptr<StepContext> ctx_;
};

/// Jittered fluid that covers the upper part of two porous materials side by side (partly saturated, so
/// S, phi^loc and rho vary from pair to pair), one compressible; no walls, no Fixed particles.
ParticleSystem partlyWettedBlocks() {
  std::mt19937 rng(17);
  const double a = 0.3 * kR;
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, jittered(sampleBox(Vec3(0, 0.05, 0), Vec3(0.16, 0.15, 0.1), kR), rng, a));
  addSet(ps, "sand", SetKind::Porous, jittered(sampleBox(Vec3::Zero(), Vec3(0.08, 0.1, 0.1), kR), rng, a));
  addSet(ps, "foam", SetKind::Porous, jittered(sampleBox(Vec3(0.08, 0, 0), Vec3(0.16, 0.1, 0.1), kR), rng, a));
  return ps;
}

std::vector<PorousMaterial> partlyWettedMaterials() {
  return {withCapillarity(material("sand", 0.4, 2650.0, false), 2500.0, 0.7),
          withCapillarity(material("foam", 0.7, 800.0, true), 500.0, 0.3)};
}

class CapillaryOperator : public ::testing::Test {
protected:
  void SetUp() override {
    // The system must exercise the saturation factor: some porous particles dry, some partly, some fully wet.
    for (std::size_t p = 1; p < 3; ++p) {
      const auto& s = system_.set(p).real(field::saturation);
      ASSERT_EQ(*std::min_element(s.begin(), s.end()), 0.0);
      ASSERT_EQ(*std::max_element(s.begin(), s.end()), 1.0);
      ASSERT_TRUE(std::any_of(s.begin(), s.end(), [](double v) { return v > 0.0 && v < 1.0; }));
    }
    ASSERT_TRUE(term_.enabled(system_.ctx()));
    term_.prepare(system_.ctx());
  }
  Prepared system_{partlyWettedBlocks(), partlyWettedMaterials()};
  CapillaryAdhesion term_;
};

TEST_F(CapillaryOperator, DiagonalBlocksEqualProbes) {
  // D_a equals the term's operator applied to the three unit vectors of particle a (METHOD.md §6.5.8).
  const linalg::BlockDiagonal d = system_.diagonal(term_);
  const auto u = system_.view(kU), au = system_.view(kAu);
  int coupled = 0;
  for (std::size_t p = 0; p < u.size(); ++p)
    for (std::size_t i = 0; i < u[p].size; i += 7)
      for (int c = 0; c < 3; ++c) {
        zero(u);
        u[p].data[i][c] = 1.0;
        system_.apply(term_, kU, kAu);
        const Vec3 column = au[p].data[i];
        EXPECT_LE((column - d[p].data[i].col(c)).norm(), 1e-12 * column.norm()) << "part " << p << " particle " << i;
        if (column.norm() > 0.0) ++coupled;
      }
  EXPECT_GT(coupled, 50); // the probes saw real couplings
}

TEST_F(CapillaryOperator, IsSymmetricPositiveSemiDefinite) {
  // <w, A u> = <A w, u>; <u, A u> > 0 for random u and = 0 for a rigid translation (METHOD.md §6.5.1).
  system_.randomise(kU, 1);
  system_.randomise(kW, 2);
  system_.apply(term_, kU, kAu);
  system_.apply(term_, kW, kAw);
  const auto u = system_.view(kU), au = system_.view(kAu), w = system_.view(kW), aw = system_.view(kAw);
  const double wAu = linalg::dot(w, au), awU = linalg::dot(aw, u);
  ASSERT_GT(std::abs(wAu), 0.0);
  EXPECT_NEAR(wAu, awU, 1e-12 * std::abs(wAu));
  const double uAu = linalg::dot(u, au);
  EXPECT_GT(uAu, 0.0);

  for (const auto& part : u)
    for (std::size_t i = 0; i < part.size; ++i) part.data[i] = Vec3(0.3, -1.0, 2.0);
  system_.apply(term_, kU, kAu);
  EXPECT_LT(std::sqrt(linalg::dot(au, au)), 1e-12 * std::sqrt(uAu * linalg::dot(u, u)));
}

TEST_F(CapillaryOperator, ConservesMomentum) {
  // Without walls the pair forces cancel, in the matrix part (sum_a F_a(u) = 0) and in the right-hand side
  // part (sum_a F^x_a = 0): one coefficient per pair, applied with opposite signs.
  system_.randomise(kU, 3);
  system_.apply(term_, kU, kAu);
  const auto [matrixSum, matrixScale] = total(system_.view(kAu));
  ASSERT_GT(matrixScale, 0.0);
  EXPECT_LT(matrixSum.norm(), 1e-13 * matrixScale);

  system_.rhs(term_, kB);
  const auto [rhsSum, rhsScale] = total(system_.view(kB));
  ASSERT_GT(rhsScale, 0.0);
  EXPECT_LT(rhsSum.norm(), 1e-13 * rhsScale);
}

TEST_F(CapillaryOperator, LinearisationMatchesPositionUpdate) {
  // Eq. 15: the right-hand-side force -c x_it evaluated at x + dt u (coefficients of the step held fixed)
  // differs from the one at x by the matrix part -dt c u_it: dt F^x(x + dt u) - dt F^x(x) = -(A u - M u).
  system_.randomise(kU, 4);
  system_.apply(term_, kU, kAu);
  system_.rhs(term_, kB);
  const auto u = system_.view(kU), au = system_.view(kAu), b0 = system_.view(kW), b1 = system_.view(kB);
  linalg::copy(b1, b0);
  for (std::size_t p = 0; p < u.size(); ++p)
    for (std::size_t i = 0; i < u[p].size; ++i) system_.set(p).x()[i] += kDt * u[p].data[i];
  system_.rhs(term_, kB);
  double mismatch = 0.0, scale = 0.0;
  for (std::size_t p = 0; p < u.size(); ++p)
    for (std::size_t i = 0; i < u[p].size; ++i) {
      mismatch += (b1[p].data[i] - b0[p].data[i] + au[p].data[i]).squaredNorm();
      scale += au[p].data[i].squaredNorm();
    }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(std::sqrt(mismatch), 1e-9 * std::sqrt(scale));
}

/// One fluid particle at the origin and one porous particle at distance `distance` along x.
ParticleSystem onePair(double distance) {
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, {Vec3::Zero()});
  addSet(ps, "sand", SetKind::Porous, {Vec3(distance, 0.0, 0.0)});
  return ps;
}

/// The pair of onePair worked out by hand from METHOD.md §3.3 (densities), §6.4 (S, phi^loc, rho^mix) and
/// §2.1 (W), for an incompressible material.
struct PairByHand {
  double w, rhoMix, rhoT, rhoB, saturation, massI, massT;

  PairByHand(double distance, double phi, double solidDensity) {
    const double h = 4.0 * kR, volume = 8.0 * kR * kR * kR, kW = 8.0 / (M_PI * h * h * h), q = distance / h;
    EXPECT_LE(q, 0.5); // the branch used below
    w = kW * (6.0 * q * q * q - 6.0 * q * q + 1.0);
    rhoB = (1.0 - phi) * solidDensity;
    massI = 1000.0 * volume;
    massT = rhoB * volume;
    const double rhoHat = 1000.0 * (volume * kW + (1.0 - phi) * volume * w); // Eq. 4: self + (1 - phi) V W
    const double phiLocal = 1.0 - (1.0 - phi) * volume * w;
    rhoMix = rhoHat * std::max(phiLocal, std::max(0.05 * phi, 0.01));
    rhoT = rhoB * volume * kW; // Eq. 3: the solid sees only itself
    // Eq. 12: N_t = (m_t / rho_t) W(0) = 1.
    saturation = std::min(volume * w / phi, 1.0);
  }
  double c(double strength, double falloff, bool rest) const {
    return strength * (1.0 - falloff * saturation) * (massI + massT) / (rhoMix + (rest ? rhoB : rhoT)) * w;
  }
};

TEST(CapillaryPair, DiagonalAndRhsMatchTheFormulaByHand) {
  // Diagonal blocks dt^2 c I on both particles (METHOD.md §6.5.6) and b = -/+ dt c x_it, with c from Eq. 13.
  const double distance = 1.5 * kR, phi = 0.5, rhoS = 2000.0, strength = 2500.0, falloff = 0.7;
  const PairByHand pair(distance, phi, rhoS);
  ASSERT_GT(pair.saturation, 0.1); // S enters and is not clamped
  ASSERT_LT(pair.saturation, 0.9);
  Prepared system(onePair(distance), {withCapillarity(material("sand", phi, rhoS, false), strength, falloff)});
  // The inputs of c as the step computed them (diagnoses a failure below).
  EXPECT_NEAR(system.set(1).real(field::saturation)[0], pair.saturation, 1e-12);
  EXPECT_NEAR(system.set(1).real(field::density)[0], pair.rhoT, 1e-12 * pair.rhoT);

  CapillaryAdhesion term;
  term.prepare(system.ctx());
  const double c = pair.c(strength, falloff, false);
  ASSERT_GT(c, 0.0);
  // c is stored in single precision (kPairFactorRounding); the rest is double.
  const double tolerance = 2.0 * kPairFactorRounding;
  const linalg::BlockDiagonal d = system.diagonal(term);
  for (std::size_t p = 0; p < 2; ++p)
    EXPECT_LT((d[p].data[0] - kDt * kDt * c * Mat3::Identity()).norm(), tolerance * kDt * kDt * c) << "part " << p;

  system.rhs(term, kB);
  const auto b = system.view(kB);
  const Vec3 xit(-distance, 0.0, 0.0);
  EXPECT_LT((b[0].data[0] + kDt * c * xit).norm(), tolerance * kDt * c * distance);
  EXPECT_LT((b[1].data[0] - kDt * c * xit).norm(), tolerance * kDt * c * distance);
}

TEST(CapillaryPair, RestSolidDensityChangesTheCoefficientByTheDensityRatio) {
  // couplingSolidDensity: rest (METHOD.md §10) puts rho_b in place of the current rho_t of Eq. 11:
  // c_rest / c_current = (rho^mix + rho_t) / (rho^mix + rho_b).
  const double distance = 1.5 * kR, phi = 0.5, rhoS = 2000.0;
  const PairByHand pair(distance, phi, rhoS);
  ASSERT_GT(std::abs(pair.rhoT / pair.rhoB - 1.0), 0.5); // the switch must make a difference
  const std::vector<PorousMaterial> materials{withCapillarity(material("sand", phi, rhoS, false), 1000.0, 0.5)};
  double diagonal[2];
  for (const bool rest : {false, true}) {
    Prepared system(onePair(distance), materials, rest);
    CapillaryAdhesion term;
    term.prepare(system.ctx());
    diagonal[rest] = system.diagonal(term)[0].data[0](0, 0);
  }
  ASSERT_GT(diagonal[0], 0.0);
  // Two coefficients, each rounded once to single precision (kPairFactorRounding).
  EXPECT_NEAR(diagonal[1] / diagonal[0], (pair.rhoMix + pair.rhoT) / (pair.rhoMix + pair.rhoB),
              3.0 * kPairFactorRounding);
}

TEST(DragRestDensity, SolidSideScalesByCurrentOverBulkDensity) {
  // The drag honours the same switch (METHOD.md §10: Eq. 11 and 16): K_it contains 1/rho_t, so every block
  // of a porous particle t scales by rho_t / rho_b, and the fluid blocks change too.
  Prepared current(partlyWettedBlocks(),
                   {material("sand", 0.4, 2650.0, false, 20.0), material("foam", 0.7, 800.0, true, 50.0)});
  Prepared rest(partlyWettedBlocks(),
                {material("sand", 0.4, 2650.0, false, 20.0), material("foam", 0.7, 800.0, true, 50.0)}, true);
  PorousDrag dragCurrent, dragRest;
  dragCurrent.prepare(current.ctx());
  dragRest.prepare(rest.ctx());
  const linalg::BlockDiagonal dc = current.diagonal(dragCurrent), dr = rest.diagonal(dragRest);
  double largestRatio = 0.0;
  for (std::size_t p = 1; p < 3; ++p) {
    const ParticleSet& solid = current.set(p);
    const double rhoB = current.ctx().materials[current.ctx().dynamicSets[p]]->bulkDensity;
    for (std::size_t s = 0; s < solid.size(); ++s) {
      const double ratio = solid.real(field::density)[s] / rhoB;
      largestRatio = std::max(largestRatio, std::abs(ratio - 1.0));
      // Sums of positive semi-definite blocks, each from a coefficient rounded to single precision.
      EXPECT_LE((dr[p].data[s] - ratio * dc[p].data[s]).norm(), 4.0 * kPairFactorRounding * dc[p].data[s].norm())
          << "part " << p;
    }
  }
  EXPECT_GT(largestRatio, 0.1); // surface particles are lighter than rho_b: the switch is visible
  double fluidChange = 0.0;
  for (std::size_t i = 0; i < dc[0].size; ++i) fluidChange += (dr[0].data[i] - dc[0].data[i]).norm();
  EXPECT_GT(fluidChange, 0.0);
}

TEST(CapillaryFalloff, NoForceWhenFullySaturatedAndFalloffIsOne) {
  // eta_cap = 1 and S = 1 switch the adhesion off (Eq. 13): A, D and b get nothing. A smaller falloff on the
  // same system does act, so the zero is the saturation factor's doing.
  ParticleSystem ps(kR);
  const std::vector<Vec3> block = sampleBox(Vec3::Zero(), Vec3::Constant(0.1), kR);
  addSet(ps, "fluid", SetKind::Fluid, block);
  addSet(ps, "sand", SetKind::Porous, block, 1);
  Prepared system(std::move(ps), {withCapillarity(material("sand", 0.5, 2000.0, false), 2500.0, 1.0)});
  for (double s : system.set(1).real(field::saturation)) ASSERT_EQ(s, 1.0);
  system.randomise(kU, 5);

  for (const double falloff : {1.0, 0.5}) {
    const PorousMaterial changed =
        withCapillarity(*system.ctx().materials[system.ctx().dynamicSets[1]], 2500.0, falloff);
    StepContext ctx = system.ctx();
    ctx.materials[ctx.dynamicSets[1]] = &changed;
    CapillaryAdhesion term;
    ASSERT_TRUE(term.enabled(ctx));
    term.prepare(ctx);
    system.apply(term, kU, kAu);
    system.rhs(term, kB);
    const linalg::BlockDiagonal d = system.diagonal(term);
    double size = linalg::dot(system.view(kAu), system.view(kAu)) + linalg::dot(system.view(kB), system.view(kB));
    for (const auto& part : d)
      for (std::size_t i = 0; i < part.size; ++i) size += part.data[i].squaredNorm();
    if (falloff == 1.0)
      EXPECT_EQ(size, 0.0);
    else
      EXPECT_GT(size, 0.0);
  }
}

TEST(CapillaryFade, OverFullPoresScaleTheCoefficientDownToNothing) {
  // implicit.adhesionInFullPores: fades (PoreFill.hpp): the pairs of a solid particle whose pores hold more
  // than 1.05 times their volume lose Eq. 13's coefficient linearly, none from 1.1 on; below 1.05 it is Eq. 13's.
  const double distance = 1.5 * kR, phi = 0.5, rhoS = 2000.0, strength = 2500.0, falloff = 0.7;
  const PairByHand pair(distance, phi, rhoS);
  Prepared system(onePair(distance), {withCapillarity(material("sand", phi, rhoS, false), strength, falloff)}, false,
                  true);
  ASSERT_NE(system.ctx().poreFill, nullptr);
  const double c = pair.c(strength, falloff, false);
  for (const auto& [fill, factor] :
       std::vector<std::pair<double, double>>{{0.3, 1.0}, {1.05, 1.0}, {1.075, 0.5}, {1.1, 0.0}, {2.0, 0.0}}) {
    system.set(1).real(field::poreFill)[0] = fill;
    CapillaryAdhesion term;
    term.prepare(system.ctx());
    const linalg::BlockDiagonal d = system.diagonal(term);
    for (std::size_t p = 0; p < 2; ++p)
      EXPECT_NEAR(d[p].data[0](0, 0), factor * kDt * kDt * c, 2.0 * kPairFactorRounding * kDt * kDt * c)
          << "fill " << fill; // c is stored in single precision
  }
}

TEST(CapillaryEnabled, NeedsFluidAndACapillaryMaterial) {
  Prepared dry(onePair(1.5 * kR), {material("sand", 0.5, 2000.0, false)});
  EXPECT_FALSE(CapillaryAdhesion().enabled(dry.ctx()));
  Prepared wet(onePair(1.5 * kR), {withCapillarity(material("sand", 0.5, 2000.0, false), 10.0, 0.0)});
  EXPECT_TRUE(CapillaryAdhesion().enabled(wet.ctx()));
  ParticleSystem ps(kR);
  addSet(ps, "sand", SetKind::Porous, {Vec3::Zero()});
  Prepared noFluid(std::move(ps), {withCapillarity(material("sand", 0.5, 2000.0, false), 10.0, 0.0)});
  EXPECT_FALSE(CapillaryAdhesion().enabled(noFluid.ctx()));
}

TEST(CouplingDensity, MixtureDensityFloorsTheLocalPorosity) {
  // rho^mix = rho^ max(phi^loc, max(0.05 phi, 0.01)) (METHOD.md §6.4).
  ParticleSet fluid("fluid", SetKind::Fluid);
  fluid.resize(3);
  auto& rho = fluid.addReal(field::density);
  auto& phiLocal = fluid.addReal(field::localPorosity);
  rho = {1000.0, 1010.0, 990.0};
  phiLocal = {0.6, 0.015, -0.2}; // open, below the floor of phi = 0.4 (0.02), squeezed shut
  const MixtureDensity sand(fluid, material("sand", 0.4, 2650.0, false));
  EXPECT_EQ(sand(0), 1000.0 * 0.6);
  EXPECT_EQ(sand(1), 1010.0 * (0.05 * 0.4));
  EXPECT_EQ(sand(2), 990.0 * (0.05 * 0.4));
  const MixtureDensity clay(fluid, material("clay", 0.1, 2650.0, false)); // 0.05 phi < 0.01
  EXPECT_EQ(clay(1), 1010.0 * 0.015);
  EXPECT_EQ(clay(2), 990.0 * 0.01);
  EXPECT_EQ(couplingPorosityFloor(0.7), 0.05 * 0.7);
  EXPECT_EQ(couplingPorosityFloor(0.0), 0.01);
}

} // namespace
} // namespace poro
