// Dictionary errors reach the user as one message naming file, line and key, and exit code 1.

#include "CaseRunner.hpp"

namespace poro::test {
namespace {

struct BadInput {
  const char* file;
  const char* from;
  const char* to;
  const char* expected; ///< a piece of the message that names file, line and the problem
};

class InputErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(InputErrors, SolverExitsWithFileLineAndKey) {
  const BadInput& bad = GetParam();
  CaseRunner runner("fluid/hydrostaticTank");
  ASSERT_EQ(runner.sample(), 0);
  runner.replace(bad.file, bad.from, bad.to);
  EXPECT_EQ(runner.solve(), 1);
  const std::string log = runner.read("log.poroSph");
  EXPECT_NE(log.find(bad.expected), std::string::npos) << log;
}

INSTANTIATE_TEST_SUITE_P(
    Dictionaries, InputErrors,
    ::testing::Values(BadInput{"system/controlDict", "endTime: 2.0", "endTime: -1",
                               "system/controlDict:4: key 'endTime': expected a number > 0, got '-1'"},
                      BadInput{"system/controlDict", "endTime: 2.0", "endTim: 2.0",
                               "system/controlDict:4: unknown key 'endTim'; did you mean 'endTime'?"},
                      BadInput{"system/controlDict", "deltaT: 0.001", "deltaT: fast",
                               "system/controlDict:5: key 'deltaT': expected a number"},
                      BadInput{"constant/fluidProperties", "gravity: [0, -9.81, 0]", "gravity: [0, -9.81",
                               "constant/fluidProperties:4: malformed YAML"},
                      BadInput{"system/solverDict", "maxIterations: 100", "maxIterations: 0",
                               "system/solverDict:3: key 'pressure.maxIterations'"}));

TEST(InputErrors, MissingDictionaryIsNamed) {
  CaseRunner runner("fluid/hydrostaticTank");
  ASSERT_EQ(runner.sample(), 0);
  std::filesystem::remove(runner.dir() / "constant" / "fluidProperties");
  EXPECT_EQ(runner.solve(), 1);
  EXPECT_NE(runner.read("log.poroSph").find("constant/fluidProperties: cannot open file"), std::string::npos)
      << runner.read("log.poroSph");
}

TEST(InputErrors, SamplerRejectsInvertedBox) {
  CaseRunner runner("fluid/hydrostaticTank");
  runner.replace("system/particleDict", "max: [0.4, 0.5, 0.4]", "max: [0.4, -0.5, 0.4]");
  EXPECT_EQ(runner.sample(), 1);
  EXPECT_NE(runner.read("log.sampleParticles").find("system/particleDict:"), std::string::npos);
  EXPECT_NE(runner.read("log.sampleParticles").find("expected max > min"), std::string::npos);
}

} // namespace
} // namespace poro::test
