// The summary of a run's warnings that its log ends with.

#include "physics/RunWarnings.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

using Kind = RunWarnings::Kind;

TEST(RunWarnings, NothingRecordedSaysNothing) {
  const RunWarnings warnings;
  EXPECT_FALSE(warnings.any());
  EXPECT_EQ(warnings.summary(100, 100), "");
}

TEST(RunWarnings, EachKindGivesItsStepsFirstAndLast) {
  RunWarnings warnings;
  warnings.record(Kind::PressureIterations, 801, 0.801);
  warnings.record(Kind::PressureIterations, 950, 0.95);
  warnings.record(Kind::PressureIterations, 1499, 1.499);
  warnings.record(Kind::ImplicitIterations, 5, 0.005);
  const std::string text = warnings.summary(100, 100);
  EXPECT_EQ(warnings.steps(Kind::PressureIterations), 3);
  EXPECT_NE(text.find("pressure.maxIterations reached in 3 steps, from step 801 (time 0.801 s) to step 1499 (time "
                      "1.499 s)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("implicit.maxIterations reached in 1 step, at step 5 (time 0.005 s)\n"), std::string::npos)
      << text;
  EXPECT_EQ(text.find("remain"), std::string::npos) << text; // nothing was deleted
}

TEST(RunWarnings, DeletedParticlesAddUpAndTheRemainderIsGiven) {
  RunWarnings warnings;
  warnings.record(Kind::LeftDomainRemoved, 10, 0.01, 40);
  warnings.record(Kind::LeftDomainRemoved, 12, 0.012, 2);
  warnings.record(Kind::NonFiniteRemoved, 20, 0.02, 7);
  EXPECT_EQ(warnings.particles(Kind::LeftDomainRemoved), 42u);
  const std::string text = warnings.summary(1000, 951);
  EXPECT_NE(text.find("42 particles left the domain and were deleted in 2 steps, from step 10"), std::string::npos)
      << text;
  EXPECT_NE(text.find("7 particles with a NaN or infinite position or velocity deleted in 1 step, at step 20"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("951 of the 1000 fluid and porous particles of the start remain"), std::string::npos) << text;
}

TEST(RunWarnings, ParticlesKeptOutsideAreTheMostAtOnceNotASum) {
  // The same particles stay outside step after step: counting them again in every step would overstate them.
  RunWarnings warnings;
  warnings.record(Kind::OutsideDomainKept, 14, 0.014, 64);
  warnings.record(Kind::OutsideDomainKept, 15, 0.015, 64);
  warnings.record(Kind::OutsideDomainKept, 16, 0.016, 70);
  warnings.record(Kind::OutsideDomainKept, 17, 0.017, 3);
  EXPECT_EQ(warnings.particles(Kind::OutsideDomainKept), 70u);
  const std::string text = warnings.summary(512, 512);
  EXPECT_NE(text.find("up to 70 particles outside the domain kept in the run in 4 steps"), std::string::npos) << text;
  EXPECT_EQ(text.find("remain"), std::string::npos) << text;
}

} // namespace
} // namespace poro
