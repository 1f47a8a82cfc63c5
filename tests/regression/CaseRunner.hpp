#pragma once
/// A tutorial copied to a scratch directory, edited to a coarse resolution and run through the real
/// executables, as a user would (tests/regression).

#include "core/Types.hpp"
#include "io/CaseReader.hpp"
#include "io/TimeDirectory.hpp"

#include <gtest/gtest.h>

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

namespace poro::test {

/// A case directory to copy (CaseRunner's second constructor). `inputsOnly` copies system/ and constant/ (the
/// dictionaries and shipped geometry) and nothing a run of the source left there (time directories, case.pvd,
/// logs, postProcessing): a tutorial that ./Allrun ran must not hand its output to a test.
struct CaseSource {
  std::filesystem::path dir;
  bool inputsOnly = false;
};

class CaseRunner {
public:
  /// Copies tutorials/<tutorial> to a fresh scratch directory named after the running test (or `name`
  /// outside a test, e.g. in SetUpTestSuite) and numbered, so that two runners of one test never share it.
  explicit CaseRunner(const std::string& tutorial, std::string name = "")
      : CaseRunner(CaseSource{std::filesystem::path(POROSPH_TUTORIALS) / tutorial, true}, std::move(name)) {}

  /// Copies any case directory (e.g. the base of tests/data/bad) the same way; a CaseSource without a directory
  /// gives an empty case for the test to write.
  explicit CaseRunner(const CaseSource& source, std::string name = "") {
    if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
      name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name)
      if (c == '/') c = '_';
    static int created = 0;
    dir_ = std::filesystem::temp_directory_path() /
           ("porosph_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(++created));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    if (source.dir.empty()) return;
    if (!source.inputsOnly) {
      std::filesystem::copy(source.dir, dir_, std::filesystem::copy_options::recursive);
      return;
    }
    for (const char* inputs : {"system", "constant"})
      if (std::filesystem::exists(source.dir / inputs))
        std::filesystem::copy(source.dir / inputs, dir_ / inputs, std::filesystem::copy_options::recursive);
  }
  ~CaseRunner() {
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir_); // keep a failed case to look at
  }

  const std::filesystem::path& dir() const { return dir_; }

  /// Replaces the text `from` by `to` in a case file (exactly one occurrence expected).
  void replace(const std::string& file, const std::string& from, const std::string& to) {
    std::string text = read(file);
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << file << " has no '" << from << "'";
    text.replace(at, from.size(), to);
    write(file, text);
  }

  /// Sets a top-level `key: value` line of a YAML dictionary.
  void setKey(const std::string& file, const std::string& key, const std::string& value) {
    std::string text = read(file);
    const std::regex line("^" + key + ":.*$", std::regex::multiline);
    ASSERT_TRUE(std::regex_search(text, line)) << file << " has no key " << key;
    write(file, std::regex_replace(text, line, key + ": " + value));
  }

  std::string read(const std::string& file) const {
    std::ifstream in(dir_ / file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  void write(const std::string& file, const std::string& text) const { std::ofstream(dir_ / file) << text; }

  /// Runs an executable on the case with its output in log.<name>; returns its exit code. With
  /// `timeoutSeconds` > 0 a run that takes longer is killed and returns 124 (coreutils timeout), so a hang
  /// fails the test instead of stalling it.
  int run(const std::string& executable, const std::string& arguments = "", int timeoutSeconds = 0) const {
    const std::string name = std::filesystem::path(executable).filename().string();
    const std::string timeout =
        timeoutSeconds > 0 ? "timeout -k 5 " + std::to_string(timeoutSeconds) + " " : std::string();
    const std::string command = timeout + "'" + executable + "' -case '" + dir_.string() + "' " + arguments + " > '" +
                                (dir_ / ("log." + name)).string() + "' 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  /// Starts the solver on the case in the background (log in log.poroSph); returns its process id.
  pid_t startSolver(const std::string& threads) const {
    const std::string log = (dir_ / "log.poroSph").string();
    const pid_t pid = ::fork();
    if (pid == 0) {
      std::FILE* out = std::freopen(log.c_str(), "w", stdout);
      if (!out || ::dup2(::fileno(stdout), 2) < 0) std::_Exit(127);
      ::execl(POROSPH_SOLVER, POROSPH_SOLVER, "-case", dir_.c_str(), "-threads", threads.c_str(), nullptr);
      std::_Exit(127);
    }
    return pid;
  }
  int sample() const { return run(POROSPH_SAMPLER); }
  int solve(const std::string& arguments = "-threads 2") const { return run(POROSPH_SOLVER, arguments); }

  ParticleSystem particles(const std::string& time, double radius) const {
    return readParticles(dir_, time, radius, readPorousMaterials(dir_));
  }

private:
  std::filesystem::path dir_;
};

} // namespace poro::test
