// system/solverDict compatibility block: the switches of METHOD.md §10.

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "physics/SolverSettings.hpp"

#include <gtest/gtest.h>

#include <string>

namespace poro {
namespace {

CompatibilitySettings read(const std::string& text) {
  return SolverSettings::read(Dictionary::parse(text, "system/solverDict")).compatibility;
}

std::string errorOf(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return "";
}

TEST(CompatibilitySettings, DefaultsFollowThePaper) {
  const CompatibilitySettings c = read("threads: 0\n");
  EXPECT_FALSE(c.unitLambdaVolumetricStress);
  EXPECT_FALSE(c.lambdaScaledBloating);
  EXPECT_FALSE(c.deltaTScaledInitialGuess);
  EXPECT_FALSE(c.restCouplingSolidDensity);
  EXPECT_FALSE(c.setSequentialPressure);
  EXPECT_FALSE(c.cappedPressureWarmStart);
}

TEST(CompatibilitySettings, ReferencePresetSetsEverySwitchAndSingleKeysOverrideIt) {
  const CompatibilitySettings all = read("compatibility:\n  preset: reference\n");
  EXPECT_TRUE(all.unitLambdaVolumetricStress && all.lambdaScaledBloating && all.deltaTScaledInitialGuess &&
              all.restCouplingSolidDensity && all.setSequentialPressure);
  EXPECT_FALSE(all.cappedPressureWarmStart); // for number-level comparisons only, by its own key
  const CompatibilitySettings mixed = read("compatibility:\n  preset: reference\n  volumetricStress: lambda\n");
  EXPECT_FALSE(mixed.unitLambdaVolumetricStress);
  EXPECT_TRUE(mixed.restCouplingSolidDensity);
  EXPECT_TRUE(read("compatibility: {couplingSolidDensity: rest}\n").restCouplingSolidDensity);
  EXPECT_TRUE(read("compatibility: {pressureSweep: setSequential}\n").setSequentialPressure);
  EXPECT_TRUE(read("compatibility: {pressureWarmStartCap: reference}\n").cappedPressureWarmStart);
}

TEST(CompatibilitySettings, BadValuesAreInputErrorsWithLine) {
  EXPECT_NE(errorOf("compatibility:\n  volumetricStress: unit\n").find("system/solverDict:2"), std::string::npos);
  EXPECT_NE(errorOf("compatibility:\n  bloatingStres: absolute\n").find("did you mean 'bloatingStress'?"),
            std::string::npos);
  const std::string sweep = errorOf("compatibility:\n  pressureSweep: sequential\n");
  EXPECT_NE(sweep.find("system/solverDict:2"), std::string::npos) << sweep;
  EXPECT_NE(sweep.find("setSequential"), std::string::npos) << sweep;
  EXPECT_NO_THROW(read("compatibility:\n  pressureSweep: jacobi\n  pressureWarmStartCap: none\n"));
}

TEST(PoreFluidDensity, PaperByDefaultLatticeCorrectedOnRequestAndAnythingElseIsAnError) {
  // Not a compatibility switch: a correction the paper does not make (PoreFluidDensityBias.hpp), so the
  // reference preset leaves it alone.
  const auto pressure = [](const std::string& text) {
    return SolverSettings::read(Dictionary::parse(text, "system/solverDict")).pressure;
  };
  EXPECT_FALSE(pressure("threads: 0\n").latticeCorrectedPoreFluid);
  EXPECT_TRUE(pressure("pressure:\n  poreFluidDensity: latticeCorrected\n").latticeCorrectedPoreFluid);
  EXPECT_FALSE(pressure("pressure: {poreFluidDensity: paper}\ncompatibility: {preset: reference}\n")
                   .latticeCorrectedPoreFluid);
  try {
    pressure("pressure:\n  maxIterations: 50\n  poreFluidDensity: corrected\n");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("system/solverDict:3"), std::string::npos) << message;
    EXPECT_NE(message.find("latticeCorrected"), std::string::npos) << message;
  }
}

} // namespace
} // namespace poro
