// system/solverDict compatibility block: the switches of METHOD.md §10, and the pore-fluid density it sets the
// default of (§3.3).

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

TEST(SolverDict, AKeyInTheWrongSectionIsSentToItsOwnWhetherThatSectionIsGivenOrNot) {
  EXPECT_EQ(
      errorOf("preset: paper\n"),
      "system/solverDict:1: unknown key 'preset'; did you mean 'compatibility.preset', a key of 'compatibility'?");
  EXPECT_EQ(
      errorOf("wallContact: allSkeletons\n"),
      "system/solverDict:1: unknown key 'wallContact'; did you mean 'pressure.wallContact', a key of 'pressure'?");
  EXPECT_EQ(errorOf("pressure:\n  xsph: 0.1\n"),
            "system/solverDict:2: unknown key 'pressure.xsph'; did you mean 'xsph', a key of the top level?");
  EXPECT_EQ(errorOf("pressure:\n  adhesionInFullPores: paper\n"),
            "system/solverDict:2: unknown key 'pressure.adhesionInFullPores'; did you mean "
            "'implicit.adhesionInFullPores', a key of 'implicit'?");
}

PressureSettings pressure(const std::string& text) {
  return SolverSettings::read(Dictionary::parse(text, "system/solverDict")).pressure;
}

TEST(PoreFluidDensity, LatticeCorrectedByDefaultSoPoresHoldPhiV) {
  // Not in the paper (PoreFluidDensityBias.hpp), but with Eq. 4 as published phi = 0.4 pores hold 0.87 phi V.
  EXPECT_TRUE(pressure("threads: 0\n").latticeCorrectedPoreFluid);
  EXPECT_TRUE(pressure("pressure:\n  maxIterations: 50\n").latticeCorrectedPoreFluid);
  EXPECT_TRUE(SolverSettings{}.pressure.latticeCorrectedPoreFluid); // the struct states the file's default
  // Single compatibility switches are not a preset: they leave the default alone.
  EXPECT_TRUE(pressure("compatibility: {volumetricStress: unitLambda}\n").latticeCorrectedPoreFluid);
}

TEST(PoreFluidDensity, TheTemplateStatesTheDefaults) {
  // etc/caseDicts/solverDict says "these are the defaults": read as a case's file it changes nothing here.
  const SolverSettings file =
      SolverSettings::read(Dictionary::read(std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/solverDict"));
  EXPECT_EQ(file.pressure.latticeCorrectedPoreFluid, SolverSettings{}.pressure.latticeCorrectedPoreFluid);
  EXPECT_FALSE(file.compatibility.unitLambdaVolumetricStress || file.compatibility.setSequentialPressure);
  EXPECT_EQ(file.xsph, SolverSettings{}.xsph);
  EXPECT_EQ(file.pressure.chebyshev, SolverSettings{}.pressure.chebyshev);
  EXPECT_EQ(file.pressure.spectralRadius, SolverSettings{}.pressure.spectralRadius);
  EXPECT_EQ(file.pressure.wallContactAllSkeletons, SolverSettings{}.pressure.wallContactAllSkeletons);
}

TEST(PoreFluidDensity, EitherPresetKeepsEq4AsPublished) {
  // A named preset, paper or reference, asks for the published method: Eq. 4 verbatim, in either order of the
  // two blocks in the file.
  EXPECT_FALSE(pressure("compatibility: {preset: paper}\n").latticeCorrectedPoreFluid);
  EXPECT_FALSE(pressure("compatibility: {preset: reference}\n").latticeCorrectedPoreFluid);
  EXPECT_FALSE(
      pressure("pressure: {maxIterations: 50}\ncompatibility: {preset: reference}\n").latticeCorrectedPoreFluid);
  EXPECT_FALSE(pressure("compatibility: {preset: paper}\npressure: {maxIterations: 50}\n").latticeCorrectedPoreFluid);
}

TEST(PoreFluidDensity, TheKeyWinsOverDefaultAndPresetAndAnythingElseIsAnError) {
  EXPECT_FALSE(pressure("pressure:\n  poreFluidDensity: paper\n").latticeCorrectedPoreFluid);
  EXPECT_TRUE(pressure("pressure:\n  poreFluidDensity: latticeCorrected\n").latticeCorrectedPoreFluid);
  EXPECT_TRUE(pressure("pressure: {poreFluidDensity: latticeCorrected}\ncompatibility: {preset: paper}\n")
                  .latticeCorrectedPoreFluid);
  EXPECT_TRUE(pressure("compatibility: {preset: reference}\npressure: {poreFluidDensity: latticeCorrected}\n")
                  .latticeCorrectedPoreFluid);
  EXPECT_FALSE(
      pressure("pressure: {poreFluidDensity: paper}\ncompatibility: {preset: reference}\n").latticeCorrectedPoreFluid);
  try {
    pressure("pressure:\n  maxIterations: 50\n  poreFluidDensity: corrected\n");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("system/solverDict:3"), std::string::npos) << message;
    EXPECT_NE(message.find("latticeCorrected"), std::string::npos) << message;
  }
}

TEST(AdhesionInFullPores, FadesByDefaultEitherPresetKeepsEq13AndTheKeyWins) {
  // Not in the paper (PoreFill.hpp): without it, adhesion packs two pore volumes into bodies thinner than H.
  const auto fades = [](const std::string& text) {
    return SolverSettings::read(Dictionary::parse(text, "system/solverDict")).implicit.adhesionFadesInFullPores;
  };
  EXPECT_TRUE(fades("threads: 0\n"));
  EXPECT_TRUE(SolverSettings{}.implicit.adhesionFadesInFullPores); // the struct states the file's default
  EXPECT_TRUE(fades("compatibility: {volumetricStress: unitLambda}\n"));
  EXPECT_FALSE(fades("compatibility: {preset: paper}\n"));
  EXPECT_FALSE(fades("compatibility: {preset: reference}\n"));
  EXPECT_FALSE(fades("implicit: {adhesionInFullPores: paper}\n"));
  EXPECT_TRUE(fades("implicit: {adhesionInFullPores: fades}\ncompatibility: {preset: paper}\n"));
  EXPECT_TRUE(fades("compatibility: {preset: reference}\nimplicit: {adhesionInFullPores: fades}\n"));
  try {
    fades("threads: 0\nimplicit:\n  adhesionInFullPores: stops\n");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("system/solverDict:3"), std::string::npos) << message;
    EXPECT_NE(message.find("fades"), std::string::npos) << message;
  }
  const SolverSettings file =
      SolverSettings::read(Dictionary::read(std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/solverDict"));
  EXPECT_EQ(file.implicit.adhesionFadesInFullPores, SolverSettings{}.implicit.adhesionFadesInFullPores);
}

TEST(PressureAcceleration, ChebyshevByDefaultAndInPaperModeJacobiAloneUnderTheReferencePreset) {
  // The same fixed point and tolerance as the sweeps alone (PressureAccelerationTest.cpp); the reference preset
  // reproduces the authors' iteration sweep for sweep (METHOD.md §10).
  EXPECT_TRUE(pressure("threads: 0\n").chebyshev);
  EXPECT_TRUE(SolverSettings{}.pressure.chebyshev); // the struct states the file's default
  EXPECT_EQ(pressure("threads: 0\n").spectralRadius, 0.9);
  EXPECT_TRUE(pressure("compatibility: {preset: paper}\n").chebyshev);
  EXPECT_FALSE(pressure("compatibility: {preset: reference}\n").chebyshev);
  EXPECT_TRUE(pressure("compatibility: {pressureSweep: setSequential}\n").chebyshev); // a switch is not a preset
  EXPECT_FALSE(pressure("pressure: {acceleration: none}\n").chebyshev);
  EXPECT_TRUE(pressure("pressure: {acceleration: chebyshev}\ncompatibility: {preset: reference}\n").chebyshev);
  EXPECT_EQ(pressure("pressure: {spectralRadius: 0.98}\n").spectralRadius, 0.98);
}

TEST(PressureAcceleration, ASpectralRadiusWithoutTheAccelerationIsNamedAsHavingNoEffect) {
  const auto warnings = [](const std::string& text) {
    ::testing::internal::CaptureStderr();
    pressure(text);
    return ::testing::internal::GetCapturedStderr();
  };
  for (const char* text : {"pressure:\n  acceleration: none\n  spectralRadius: 0.95\n",
                           "compatibility: {preset: reference}\npressure:\n  spectralRadius: 0.95\n"})
    EXPECT_NE(warnings(text).find("system/solverDict:3: key 'pressure.spectralRadius' has no effect"),
              std::string::npos)
        << text;
  EXPECT_EQ(warnings("pressure:\n  spectralRadius: 0.95\n"), "");
}

TEST(PressureAcceleration, BadValuesAreInputErrorsWithFileAndLine) {
  for (const char* text :
       {"threads: 0\npressure: {acceleration: conjugateGradients}\n", "threads: 0\npressure: {spectralRadius: 1}\n",
        "threads: 0\npressure: {spectralRadius: 0}\n"}) {
    try {
      pressure(text);
      ADD_FAILURE() << "no InputError for " << text;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("system/solverDict:2"), std::string::npos) << message;
    }
  }
}

TEST(PressureParticleBound, OffByDefaultInTheStructAndTheFileAndReadInPercent) {
  // The mean alone is the published criterion; a bound on single particles is asked for (0 = none).
  EXPECT_EQ(pressure("threads: 0\n").maxParticleDensityError, 0.0);
  const SolverSettings file =
      SolverSettings::read(Dictionary::read(std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/solverDict"));
  EXPECT_EQ(file.pressure.maxParticleDensityError, SolverSettings{}.pressure.maxParticleDensityError);
  EXPECT_EQ(pressure("pressure: {maxParticleDensityError: 0.3}\n").maxParticleDensityError, 0.3);
  EXPECT_EQ(
      pressure("compatibility: {preset: paper}\npressure: {maxParticleDensityError: 0.3}\n").maxParticleDensityError,
      0.3);
  const std::string negative = errorOf("threads: 0\npressure: {maxParticleDensityError: -0.1}\n");
  EXPECT_NE(negative.find("system/solverDict:2"), std::string::npos) << negative;
  EXPECT_NE(negative.find("maxParticleDensityError"), std::string::npos) << negative;
}

TEST(PressureSkeletonBound, OnByDefaultOffUnderEitherPresetAndTheKeyWinsInPercent) {
  EXPECT_EQ(pressure("threads: 0\n").maxSkeletonParticleDensityError, 0.2);
  const SolverSettings file =
      SolverSettings::read(Dictionary::read(std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/solverDict"));
  EXPECT_EQ(file.pressure.maxSkeletonParticleDensityError, SolverSettings{}.pressure.maxSkeletonParticleDensityError);
  // A preset asks for the published stopping rule, the mean alone (METHOD.md §6.7), in either order of the blocks.
  EXPECT_EQ(pressure("compatibility: {preset: paper}\n").maxSkeletonParticleDensityError, 0.0);
  EXPECT_EQ(
      pressure("pressure: {maxIterations: 50}\ncompatibility: {preset: reference}\n").maxSkeletonParticleDensityError,
      0.0);
  EXPECT_EQ(pressure("compatibility: {volumetricStress: unitLambda}\n").maxSkeletonParticleDensityError, 0.2);
  const PressureSettings both = pressure("compatibility: {preset: paper}\npressure: {maxSkeletonParticleDensityError: "
                                         "0.1}\n");
  EXPECT_EQ(both.maxSkeletonParticleDensityError, 0.1);
  EXPECT_EQ(both.maxParticleDensityError, 0.0); // the bound on everyone stays off
  const std::string negative = errorOf("threads: 0\npressure: {maxSkeletonParticleDensityError: -0.1}\n");
  EXPECT_NE(negative.find("system/solverDict:2"), std::string::npos) << negative;
  EXPECT_NE(negative.find("maxSkeletonParticleDensityError"), std::string::npos) << negative;
}

double xsph(const std::string& text) { return SolverSettings::read(Dictionary::parse(text, "system/solverDict")).xsph; }

TEST(Xsph, OffByDefaultAndTheKeyWinsOverAnyPreset) {
  // Not in the paper (XsphSmoothing.hpp), and a viscosity of about 0.05 eps H^2 / dt: a case asks for it.
  EXPECT_EQ(xsph("threads: 0\n"), 0.0);
  EXPECT_EQ(SolverSettings{}.xsph, 0.0); // the struct states the file's default
  EXPECT_EQ(xsph("compatibility: {preset: paper}\n"), 0.0);
  EXPECT_EQ(xsph("xsph: 0.1\n"), 0.1);
  EXPECT_EQ(xsph("xsph: 0.05\ncompatibility: {preset: reference}\n"), 0.05);
  EXPECT_EQ(xsph("compatibility: {preset: paper}\nxsph: 0.2\n"), 0.2);
}

TEST(Xsph, OutsideZeroToOneIsAnInputErrorWithFileAndLine) {
  for (const char* text : {"threads: 0\nxsph: 1.5\n", "threads: 0\nxsph: -0.1\n", "threads: 0\nxsph: strong\n"}) {
    try {
      xsph(text);
      ADD_FAILURE() << "no InputError for " << text;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("system/solverDict:2"), std::string::npos) << message;
      EXPECT_NE(message.find("xsph"), std::string::npos) << message;
    }
  }
}

} // namespace
} // namespace poro
