#include "analysis/CsvTable.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

namespace poro::test {
namespace {

TEST(CsvTable, NumbersAreShortestAndExact) {
  EXPECT_EQ(CsvTable::formatNumber(0.1), "0.1");
  EXPECT_EQ(CsvTable::formatNumber(0.0), "0");
  EXPECT_EQ(CsvTable::formatNumber(6.4e-5), "6.4e-05");
  EXPECT_EQ(CsvTable::formatNumber(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(CsvTable::formatNumber(NAN), "nan");
  EXPECT_EQ(CsvTable::formatNumber(-INFINITY), "-inf");
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  for (int k = 0; k < 1000; ++k) {
    const double value = mantissa(random) * std::pow(10.0, k % 40 - 20);
    EXPECT_EQ(std::strtod(CsvTable::formatNumber(value).c_str(), nullptr), value);
  }
}

TEST(CsvTable, QuotesCellsThatNeedIt) {
  EXPECT_EQ(CsvTable::quote("block"), "block");
  EXPECT_EQ(CsvTable::quote("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvTable::quote("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvTable::quote("two\nlines"), "\"two\nlines\"");
}

TEST(CsvTable, RowsWithMissingCellsStayRectangular) {
  CsvTable table({"time_s", "name", "value_m3"});
  table.row().add(0.5).add(std::string("a,b")).add(std::optional<double>());
  table.row().add(1.0);
  table.row().add(std::size_t{3}).add(std::string("c")).add(std::optional<double>(2.5));
  EXPECT_EQ(table.rows(), 3u);
  EXPECT_EQ(table.text(), "time_s,name,value_m3\n0.5,\"a,b\",\n1,,\n3,c,2.5\n");
  EXPECT_THROW(table.add(1.0), std::logic_error); // a fourth cell
}

} // namespace
} // namespace poro::test
