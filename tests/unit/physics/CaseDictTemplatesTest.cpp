// The annotated templates in etc/caseDicts are valid dictionaries: every key they show is one the solver reads.

#include "core/Dictionary.hpp"
#include "physics/FluidProperties.hpp"
#include "physics/PorousMaterial.hpp"
#include "physics/SolverSettings.hpp"

#include <gtest/gtest.h>

#include <string>

namespace poro {
namespace {

std::string templateFile(const std::string& name) {
  return std::string(POROSPH_TEST_DATA) + "/../../etc/caseDicts/" + name;
}

TEST(CaseDictTemplates, PorosityPropertiesReadsWithEveryKey) {
  const auto materials = PorousMaterial::readAll(Dictionary::read(templateFile("porosityProperties")));
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_EQ(materials[0].name, "sand");
}

TEST(CaseDictTemplates, SolverDictReadsWithEveryKey) {
  const SolverSettings s = SolverSettings::read(Dictionary::read(templateFile("solverDict")));
  EXPECT_FALSE(s.compatibility.unitLambdaVolumetricStress); // the template shows the defaults
  EXPECT_EQ(s.pressure.maxIterations, 100);
}

TEST(CaseDictTemplates, FluidPropertiesReads) {
  EXPECT_NO_THROW(FluidProperties::read(Dictionary::read(templateFile("fluidProperties"))));
}

} // namespace
} // namespace poro
