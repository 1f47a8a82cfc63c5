// ReallocVector (core/ReallocVector.hpp): growth keeps what is held, copies are deep, clear() keeps the block and
// memory::freeAll gives it back.

#include "core/ReallocVector.hpp"
#include "core/Memory.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>

namespace poro {
namespace {

ReallocVector<std::uint32_t> counting(std::size_t n) {
  ReallocVector<std::uint32_t> values;
  values.resize(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = static_cast<std::uint32_t>(i * 2654435761u);
  return values;
}

void expectCounting(const ReallocVector<std::uint32_t>& values, std::size_t n) {
  ASSERT_GE(values.size(), n);
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(values[i], static_cast<std::uint32_t>(i * 2654435761u)) << i;
}

TEST(ReallocVector, GrowthKeepsTheValuesHeld) {
  // A small block grown to a large one, and that to a larger one: realloc's copy out of the heap and, where glibc
  // maps the large blocks (the solver's setting), its move of a mapped block's pages.
  ReallocVector<std::uint32_t> values = counting(1000);
  values.reserve(1 << 19); // 2 MiB
  EXPECT_EQ(values.size(), 1000u);
  expectCounting(values, 1000);
  const std::size_t held = values.size();
  values.resize(1 << 19);
  for (std::size_t i = held; i < values.size(); ++i) values[i] = static_cast<std::uint32_t>(i * 2654435761u);
  values.resize(1 << 22); // 16 MiB
  EXPECT_GE(values.capacity(), std::size_t{1} << 22);
  expectCounting(values, 1 << 19);
}

TEST(ReallocVector, CopiesAreDeepAndMovesEmptyTheSource) {
  ReallocVector<std::uint32_t> original = counting(5000);
  ReallocVector<std::uint32_t> copy = original;
  ASSERT_NE(copy.data(), original.data());
  expectCounting(copy, 5000);
  original[0] = 7;
  EXPECT_NE(copy[0], 7u);

  const std::uint32_t* block = copy.data();
  ReallocVector<std::uint32_t> moved = std::move(copy);
  EXPECT_EQ(moved.data(), block);
  EXPECT_EQ(moved.size(), 5000u);
  EXPECT_EQ(copy.size(), 0u);      // NOLINT(bugprone-use-after-move): the state a move leaves is the point
  EXPECT_EQ(copy.data(), nullptr); // NOLINT(bugprone-use-after-move)

  copy = moved; // assignment copies too
  expectCounting(copy, 5000);
  EXPECT_NE(copy.data(), moved.data());
}

TEST(ReallocVector, ClearKeepsTheBlockAndFreeAllGivesItBack) {
  ReallocVector<std::uint16_t> codes;
  codes.resize(3000);
  const std::size_t capacity = codes.capacity();
  codes.clear();
  EXPECT_TRUE(codes.empty());
  EXPECT_EQ(codes.capacity(), capacity);
  memory::freeAll(codes);
  EXPECT_EQ(codes.capacity(), 0u);
  EXPECT_EQ(codes.data(), nullptr);
  codes.resize(10); // usable again
  codes[9] = 3;
  EXPECT_EQ(codes[9], 3u);
}

} // namespace
} // namespace poro
