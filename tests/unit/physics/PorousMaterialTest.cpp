// constant/porosityProperties: derived densities, density limits (METHOD.md §3.1) and input checks (§9).

#include "physics/PorousMaterial.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace poro {
namespace {

const std::string kFile = "constant/porosityProperties";

std::vector<PorousMaterial> read(const std::string& text) {
  return PorousMaterial::readAll(Dictionary::parse(text, kFile));
}

/// The message of the InputError reading `text` throws; a test failure if it throws nothing.
std::string errorOf(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return "";
}

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

TEST(PorousMaterial, ReadsEveryKeyInFileOrder) {
  const auto materials = read("sand:\n"                                          // 1
                              "  porosity: 0.4\n"                                // 2
                              "  solidDensity: 2650\n"                           // 3
                              "  compressible: true\n"                           // 4
                              "  dragViscosity: 10\n"                            // 5
                              "  poissonsRatio: 0.25\n"                          // 6
                              "  capillaryFalloff: 0.5\n"                        // 7
                              "  youngsModulus: 2.5e5\n"                         // 8
                              "  fixedBox: {min: [0, 0, 0], max: [1, 0.1, 1]}\n" // 9
                              "  capillaryStrength: 500\n"
                              "  bloating: -1e3\n"
                              "  shearSoftening: -2\n"
                              "  volumeSoftening: 0.5\n"
                              "  dampingViscosity: 20\n"
                              "  boundaryDampingViscosity: 200\n"
                              "  hourglassControl: 1.5\n"
                              "clay:\n"
                              "  porosity: 0.2\n"
                              "  bulkDensity: 1600\n");
  ASSERT_EQ(materials.size(), 2u);
  const PorousMaterial& sand = materials[0];
  EXPECT_EQ(sand.name, "sand");
  EXPECT_EQ(sand.porosity, 0.4);
  EXPECT_EQ(sand.solidDensity, 2650.0);
  EXPECT_DOUBLE_EQ(sand.bulkDensity, 0.6 * 2650.0);
  EXPECT_TRUE(sand.compressible);
  EXPECT_EQ(sand.dragViscosity, 10.0);
  EXPECT_EQ(sand.poissonsRatio, 0.25);
  EXPECT_EQ(sand.capillaryFalloff, 0.5);
  EXPECT_EQ(sand.youngsModulus, 2.5e5);
  EXPECT_EQ(sand.capillaryStrength, 500.0);
  EXPECT_EQ(sand.bloating, -1e3);
  EXPECT_EQ(sand.shearSoftening, -2.0);
  EXPECT_EQ(sand.volumeSoftening, 0.5);
  EXPECT_EQ(sand.dampingViscosity, 20.0);
  EXPECT_EQ(sand.boundaryDampingViscosity, 200.0);
  EXPECT_EQ(sand.hourglassControl, 1.5);
  ASSERT_TRUE(sand.fixedBox.has_value());
  EXPECT_EQ(sand.fixedBox->first, Vec3(0, 0, 0));
  EXPECT_EQ(sand.fixedBox->second, Vec3(1, 0.1, 1));

  const PorousMaterial& clay = materials[1];
  EXPECT_EQ(clay.name, "clay");
  EXPECT_EQ(clay.bulkDensity, 1600.0);
  EXPECT_DOUBLE_EQ(clay.solidDensity, 1600.0 / 0.8);
  EXPECT_FALSE(clay.compressible);
  EXPECT_EQ(clay.dragViscosity, 0.0);
  EXPECT_EQ(clay.poissonsRatio, 0.3);
  EXPECT_EQ(clay.hourglassControl, 0.0) << "off unless asked for: Eq. 19 as published";
  EXPECT_FALSE(clay.fixedBox.has_value());
}

TEST(PorousMaterial, DensityLimitAndOwnFactorOfBothKinds) {
  // METHOD.md §3.1: rho^max = rho_b (incompressible) or rho_s^0 (compressible); c_s = rho_b / rho^max.
  const auto materials = read("stiff: {porosity: 0.25, solidDensity: 2000}\n"
                              "soft: {porosity: 0.25, solidDensity: 2000, compressible: true}\n");
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_DOUBLE_EQ(materials[0].maxDensity(), 1500.0);
  EXPECT_DOUBLE_EQ(materials[0].ownFactor(), 1.0);
  EXPECT_DOUBLE_EQ(materials[1].maxDensity(), 2000.0);
  EXPECT_DOUBLE_EQ(materials[1].ownFactor(), 0.75);
}

TEST(PorousMaterial, ZeroPorosityIsASolid) {
  const auto materials = read("rock: {porosity: 0, bulkDensity: 2500}\n");
  EXPECT_EQ(materials[0].solidDensity, 2500.0);
  EXPECT_EQ(materials[0].bulkDensity, 2500.0);
}

struct BadMaterial {
  const char* text;
  const char* where;    ///< "file:line"
  const char* key;      ///< what the message must name
  const char* expected; ///< a piece of the message saying what was expected
};

class InvalidMaterial : public ::testing::TestWithParam<BadMaterial> {};

TEST_P(InvalidMaterial, IsAnInputErrorNamingFileLineAndKey) {
  const BadMaterial& bad = GetParam();
  const std::string message = errorOf(bad.text);
  EXPECT_TRUE(contains(message, std::string(bad.where) + ":"));
  EXPECT_TRUE(contains(message, bad.key));
  EXPECT_TRUE(contains(message, bad.expected));
}

INSTANTIATE_TEST_SUITE_P(
    Values, InvalidMaterial,
    ::testing::Values(
        BadMaterial{"sand:\n  porosity: 1\n  solidDensity: 2650\n", "constant/porosityProperties:2", "'sand.porosity'",
                    "in [0, 1)"},
        BadMaterial{"sand:\n  porosity: -0.1\n  solidDensity: 2650\n", "constant/porosityProperties:2",
                    "'sand.porosity'", "in [0, 1)"},
        BadMaterial{"sand:\n  solidDensity: 2650\n", "constant/porosityProperties:1", "'sand.porosity'",
                    "missing required key"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: -2650\n", "constant/porosityProperties:3",
                    "'sand.solidDensity'", "> 0"},
        BadMaterial{"sand:\n  porosity: 0.4\n  bulkDensity: 0\n", "constant/porosityProperties:3", "'sand.bulkDensity'",
                    "> 0"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  dragViscosity: -1\n",
                    "constant/porosityProperties:4", "'sand.dragViscosity'", ">= 0"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  bulkDensity: 1590\n",
                    "constant/porosityProperties:4", "'sand.bulkDensity'", "not both"},
        BadMaterial{"sand:\n  porosity: 0.4\n  bulkDensity: 1590\n  solidDensity: 2650\n",
                    "constant/porosityProperties:4", "'sand.solidDensity'", "not both"},
        BadMaterial{"sand:\n  porosity: 0.4\n  compressible: true\n", "constant/porosityProperties:1", "'solidDensity'",
                    "'bulkDensity'"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensty: 2650\n", "constant/porosityProperties:3",
                    "'sand.solidDensty'", "did you mean 'solidDensity'?"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  dragViscosty: 1\n",
                    "constant/porosityProperties:4", "'sand.dragViscosty'", "did you mean 'dragViscosity'?"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  capillaryStrength: -0.1\n",
                    "constant/porosityProperties:4", "'sand.capillaryStrength'", ">= 0"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  bloating: .nan\n", "constant/porosityProperties:4",
                    "'sand.bloating'", "finite"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  dampingViscosity: -2\n",
                    "constant/porosityProperties:4", "'sand.dampingViscosity'", ">= 0"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  boundaryDampingViscosity: -2\n",
                    "constant/porosityProperties:4", "'sand.boundaryDampingViscosity'", ">= 0"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  shearSoftening: .inf\n",
                    "constant/porosityProperties:4", "'sand.shearSoftening'", "finite"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  hourglassControl: -1\n",
                    "constant/porosityProperties:4", "'sand.hourglassControl'", "in [0, 1000]"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  youngsModulus: -1\n",
                    "constant/porosityProperties:4", "'sand.youngsModulus'", "in [0, 1e+13]"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  youngsModulus: 2e50\n",
                    "constant/porosityProperties:4", "'sand.youngsModulus'", "in [0, 1e+13]"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  hourglassControl: 1e50\n",
                    "constant/porosityProperties:4", "'sand.hourglassControl'", "in [0, 1000]"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  poissonsRatio: 0.5\n",
                    "constant/porosityProperties:4", "'sand.poissonsRatio'", "in (-1, 0.5)"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  capillaryFalloff: 1.5\n",
                    "constant/porosityProperties:4", "'sand.capillaryFalloff'", "in [0, 1]"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  fixedBox:\n    min: [0, 0, 0]\n"
                    "    max: [1, 0, 1]\n",
                    "constant/porosityProperties:6", "'sand.fixedBox.max'", "max > min"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\n  fixedBox: {min: [0, 0, 0], maxi: [1, 1, 1]}\n",
                    "constant/porosityProperties:4", "'sand.fixedBox.maxi'", "did you mean 'max'?"},
        BadMaterial{"fluid:\n  porosity: 0.4\n  solidDensity: 2650\n", "constant/porosityProperties:1", "'fluid'",
                    "cannot name a porous material"},
        BadMaterial{"boundary:\n  porosity: 0.4\n  solidDensity: 2650\n", "constant/porosityProperties:1", "'boundary'",
                    "cannot name a porous material"},
        BadMaterial{"rigid:\n  porosity: 0.4\n  solidDensity: 2650\n", "constant/porosityProperties:1", "'rigid'",
                    "cannot name a porous material"},
        BadMaterial{"sand:\n  porosity: 0.4\n  solidDensity: 2650\nfine sand:\n  porosity: 0.3\n"
                    "  solidDensity: 2650\n",
                    "constant/porosityProperties:4", "'fine sand'", "identifier"},
        BadMaterial{"2sand: {porosity: 0.4, solidDensity: 2650}\n", "constant/porosityProperties:1", "'2sand'",
                    "identifier"},
        BadMaterial{"sand: 0.4\n", "constant/porosityProperties:1", "'sand'", "expected a mapping"},
        BadMaterial{"{}\n", "constant/porosityProperties:1", "porosityProperties", "no material"}));

TEST(PorousMaterial, ElasticKeysWithoutElasticityAreNamedAsHavingNoEffect) {
  const auto warnings = [](const std::string& text) {
    ::testing::internal::CaptureStderr();
    PorousMaterial::readAll(Dictionary::parse(text, "constant/porosityProperties"));
    return ::testing::internal::GetCapturedStderr();
  };
  const std::string base = "sand:\n  porosity: 0.4\n  solidDensity: 2650\n";
  const std::string noE = warnings(base + "  hourglassControl: 1\n  bloating: 5\n  poissonsRatio: 0.3\n");
  EXPECT_TRUE(contains(noE, "constant/porosityProperties:4: key 'sand.hourglassControl' has no effect")) << noE;
  EXPECT_TRUE(contains(noE, "constant/porosityProperties:5: key 'sand.bloating' has no effect")) << noE;
  EXPECT_FALSE(contains(noE, "poissonsRatio")) << "the default value given explicitly: " << noE;
  EXPECT_EQ(warnings(base + "  youngsModulus: 1e5\n  hourglassControl: 1\n  bloating: 5\n"), "");
}

TEST(PorousMaterial, BothDensitiesNameTheFirst) {
  const std::string message = errorOf("sand:\n  porosity: 0.4\n  solidDensity: 2650\n  bulkDensity: 1590\n");
  EXPECT_TRUE(contains(message, "constant/porosityProperties:3")) << "where the first density is given";
}

} // namespace
} // namespace poro
