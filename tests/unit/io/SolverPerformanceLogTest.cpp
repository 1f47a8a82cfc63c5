// postProcessing/solverPerformance: one CSV row per step whose values are the step's, with per-step (not
// accumulated) phase times.

#include "ScratchDirectory.hpp"

#include "io/SolverPerformanceLog.hpp"
#include "physics/FieldNames.hpp"

#include <sstream>

namespace poro::test {
namespace {

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

TEST(SolverPerformanceLog, OneRowPerStepMatchingTheSolversReports) {
  ScratchDirectory dir;
  ParticleSystem ps(0.01);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.resize(8);
  for (std::size_t i = 0; i < 8; ++i) {
    fluid.x()[i] = Vec3(0.02 * (i % 2), 0.02 * ((i / 2) % 2), 0.02 * (i / 4));
    fluid.integer(field::id)[i] = static_cast<std::int64_t>(i);
  }
  TimeControl control;
  control.deltaT = 1e-3;
  control.endTime = 5e-3;
  control.writeInterval = 1.0;
  Solver solver(std::move(ps), FluidProperties{}, {}, SolverSettings{}, control, RunState{});
  SolverPerformanceLog log(dir.path(), "0");
  std::vector<StepReport> reports;
  double phaseSum = 0.0;
  solver.run([](const Solver&) {}, {},
             [&](const Solver& s) {
               log.record(s);
               reports.push_back(s.lastStep());
             });
  for (const auto& [name, seconds] : solver.phaseTimes().phases()) phaseSum += seconds;

  std::ifstream in(dir.path() / "postProcessing" / "solverPerformance" / "0" / "solverPerformance.csv");
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const auto header = splitCsv(line);
  EXPECT_EQ(header.front(), "step");
  EXPECT_EQ(header.back(), "output_s");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) rows.push_back(splitCsv(line));
  ASSERT_EQ(rows.size(), 5u);
  double rowPhaseSum = 0.0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), header.size());
    EXPECT_EQ(std::stoll(rows[k][0]), static_cast<long long>(k + 1));
    EXPECT_NEAR(std::stod(rows[k][1]), 1e-3 * static_cast<double>(k + 1), 1e-12);
    EXPECT_EQ(std::stod(rows[k][2]), reports[k].deltaT);
    EXPECT_EQ(std::stoi(rows[k][5]), reports[k].pressure.iterations);
    for (std::size_t c = header.size() - SolverPerformanceLog::phaseColumns().size(); c < header.size(); ++c) {
      EXPECT_GE(std::stod(rows[k][c]), 0.0);
      rowPhaseSum += std::stod(rows[k][c]);
    }
  }
  // Per-step differences add up to the accumulated totals (to the 6 digits written).
  EXPECT_NEAR(rowPhaseSum, phaseSum, 1e-5 + 1e-5 * phaseSum);
}

TEST(SolverPerformanceLog, AFileNamedPostProcessingIsNamedAsTheProblem) {
  // create_directories fails with "Not a directory" or "File exists" and the open with "No such file or
  // directory"; neither says which path is wrong. The run goes on, with one warning that does.
  ScratchDirectory dir;
  writeAll(dir / "postProcessing", "not a directory");
  ::testing::internal::CaptureStderr();
  const SolverPerformanceLog log(dir.path(), "0");
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(warning, "Warning: " + (dir / "postProcessing").string() + " is a file, not a directory, so " +
                         (dir / "postProcessing" / "solverPerformance" / "0").string() +
                         " cannot be created: rename or remove the file; the run goes on without its "
                         "solverPerformance record\n");
}

TEST(SolverPerformanceLog, ADirectoryWithoutWritePermissionIsNamedAsTheProblem) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  ScratchDirectory dir;
  std::filesystem::create_directories(dir / "postProcessing");
  std::filesystem::permissions(dir / "postProcessing",
                               std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  ::testing::internal::CaptureStderr();
  const SolverPerformanceLog log(dir.path(), "0");
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find((dir / "postProcessing").string() +
                         ": no permission to create solverPerformance/0 in this directory"),
            std::string::npos)
      << warning;
}

} // namespace
} // namespace poro::test
