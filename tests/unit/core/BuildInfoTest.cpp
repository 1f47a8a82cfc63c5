// The build description the logs print (core/BuildInfo.hpp): it must name the arithmetic this code was compiled with.

#include "core/BuildInfo.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

TEST(BuildInfo, NamesTheCompilerAndWhetherFusedMultiplyAddsAreUsed) {
  const std::string text = buildDescription();
#if defined(__clang__)
  EXPECT_EQ(text.rfind("Clang ", 0), 0u) << text;
#elif defined(__GNUC__)
  EXPECT_EQ(text.rfind(std::string("GCC ") + __VERSION__, 0), 0u) << text;
#endif
  // This test is compiled with the project's flags, like the library: both see the same instruction set.
#if defined(__x86_64__) && defined(__FMA__)
  EXPECT_NE(text.find(", fused multiply-adds"), std::string::npos) << text;
  EXPECT_EQ(text.find("no fused multiply-adds"), std::string::npos) << text;
#elif defined(__x86_64__)
  EXPECT_NE(text.find(", no fused multiply-adds"), std::string::npos) << text;
#endif
#if defined(__x86_64__) && defined(__AVX2__) && !defined(__AVX512F__)
  EXPECT_NE(text.find(", AVX2"), std::string::npos) << text;
#endif
}

} // namespace
} // namespace poro
