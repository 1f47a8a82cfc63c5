#include "analysis/Axis.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

namespace poro::test {
namespace {

TEST(Axis, ParsesSignedAxisNames) {
  for (const std::string name : {"x", "y", "z", "-x", "-y", "-z"}) EXPECT_EQ(Axis::parse(name).name(), name);
  EXPECT_EQ(Axis::parse("+z").name(), "z");
  EXPECT_DOUBLE_EQ(Axis::parse("-y").coordinate(Vec3(1, 2, 3)), -2.0);
  EXPECT_DOUBLE_EQ(Axis::parse("z").coordinate(Vec3(1, 2, 3)), 3.0);
}

TEST(Axis, RejectsAnythingElseNamingTheOption) {
  for (const std::string bad : {"", "w", "xy", "--x", "Y", "-"}) {
    try {
      Axis::parse(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("-axis"), std::string::npos) << e.what();
    }
  }
}

TEST(Axis, UpPointsAgainstGravity) {
  EXPECT_EQ(Axis::up(Vec3(0, -9.81, 0)).name(), "y");
  EXPECT_EQ(Axis::up(Vec3(0, 0, -9.81)).name(), "z");
  EXPECT_EQ(Axis::up(Vec3(9.81, 0, 0)).name(), "-x");
  EXPECT_EQ(Axis::up(Vec3(1, -9, 0.5)).name(), "y"); // a tilted gravity: its largest component
  EXPECT_EQ(Axis::up(Vec3::Zero()).name(), "y");
}

} // namespace
} // namespace poro::test
