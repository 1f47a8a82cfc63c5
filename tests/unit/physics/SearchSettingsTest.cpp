// system/solverDict neighbourSearch block: the Morton sort period and the Verlet skin.

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "physics/SolverSettings.hpp"

#include <gtest/gtest.h>

#include <string>

namespace poro {
namespace {

SolverSettings read(const std::string& text) {
  return SolverSettings::read(Dictionary::parse(text, "system/solverDict"));
}

TEST(SearchSettings, SkinDefaultsToATenthOfHAndZeroTurnsItOff) {
  EXPECT_DOUBLE_EQ(read("threads: 0\n").searchSkin, 0.1);
  EXPECT_DOUBLE_EQ(read("neighbourSearch:\n  skin: 0\n").searchSkin, 0.0);
  EXPECT_DOUBLE_EQ(read("neighbourSearch:\n  skin: 0.25\n  sortInterval: 100\n").searchSkin, 0.25);
}

TEST(SearchSettings, ASkinOutsideZeroToOneIsAnInputErrorWithLine) {
  for (const char* text : {"neighbourSearch:\n  skin: -0.1\n", "neighbourSearch:\n  skin: 1.5\n"}) {
    try {
      read(text);
      ADD_FAILURE() << "no InputError for:\n" << text;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("system/solverDict:2"), std::string::npos) << message;
      EXPECT_NE(message.find("skin"), std::string::npos) << message;
    }
  }
}

} // namespace
} // namespace poro
