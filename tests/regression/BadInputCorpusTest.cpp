// The bad-input corpus (tests/data/bad/README.md): each broken case makes its application exit with code 1
// after one message that names the error class, the file, the line where YAML gives one, and the problem.
// One test per case directory, named after it; the valid base case must run cleanly, so that every case fails
// for its own edit only.

#include "CaseRunner.hpp"
#include "core/Dictionary.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace poro::test {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = POROSPH_BAD_INPUTS;
const fs::path kBase = kCorpus / "base";
/// Seconds: every case takes a fraction of one; a hang must fail the test, not stall the suite.
constexpr int kTimeout = 60;

/// A case's expect.yaml (README.md lists the keys).
struct Expectation {
  std::string application; ///< executable path
  std::string log;         ///< log.<application>
  bool sample = true;
  std::vector<std::string> remove;
  std::optional<std::pair<std::string, double>> truncate; ///< file, fraction kept
  struct Overwrite {
    std::string file;
    double at;
    long long bytes;
  };
  std::optional<Overwrite> overwrite;
  std::string arguments;
  std::string error;
  std::string message;
};

std::vector<std::string> words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

Expectation readExpectation(const fs::path& file) {
  const Dictionary d = Dictionary::read(file.string());
  Expectation e;
  const std::string application = d.getWord("application", {"poroSph", "sampleParticles"});
  e.application = application == "poroSph" ? POROSPH_SOLVER : POROSPH_SAMPLER;
  e.log = "log." + application;
  e.sample = d.getBool("sample", application == "poroSph");
  e.remove = words(d.getString("remove", ""));
  if (const auto t = d.optionalSubDict("truncate")) {
    e.truncate = std::make_pair(t->getString("file"), t->getReal("keep", Range::halfOpen(0.0, 1.0)));
    t->checkUnknownKeys();
  }
  if (const auto o = d.optionalSubDict("overwrite")) {
    e.overwrite = Expectation::Overwrite{o->getString("file"), o->getReal("at", Range::halfOpen(0.0, 1.0)),
                                         o->getInt("bytes", Range::closed(1, 4096))};
    o->checkUnknownKeys();
  }
  e.arguments = d.getString("arguments", "");
  e.error = d.getWord("error", {"input error", "numerical error", "output error", "error"}, "input error");
  e.message = d.getString("message");
  d.checkUnknownKeys();
  return e;
}

/// Copies the files under `from` over the case, except expect.yaml and beforeSampling/ of the case itself.
void overlay(const fs::path& from, const fs::path& caseDir) {
  for (auto it = fs::recursive_directory_iterator(from); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = fs::relative(it->path(), from);
    if (relative == "expect.yaml" || relative == "beforeSampling") {
      if (it->is_directory()) it.disable_recursion_pending();
      continue;
    }
    if (it->is_directory())
      fs::create_directories(caseDir / relative);
    else
      fs::copy_file(it->path(), caseDir / relative, fs::copy_options::overwrite_existing);
  }
}

/// Time directories of a case (names starting with a digit), to see that a refused run wrote none.
std::vector<std::string> timeDirectories(const fs::path& caseDir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(caseDir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && std::isdigit(static_cast<unsigned char>(name[0]))) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> corpusCases() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kCorpus))
    if (entry.is_directory() && entry.path().filename() != "base") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(BadInputCorpus, BaseCaseRunsCleanly) {
  CaseRunner runner(CaseSource{kBase});
  ASSERT_EQ(runner.run(POROSPH_SAMPLER, "", kTimeout), 0) << runner.read("log.sampleParticles");
  ASSERT_EQ(runner.run(POROSPH_SOLVER, "", kTimeout), 0) << runner.read("log.poroSph");
  EXPECT_EQ(timeDirectories(runner.dir()), (std::vector<std::string>{"0", "0.001", "0.002", "0.003"}));
}

class BadInputCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInputCorpus, ExitsWithOneClearMessage) {
  const fs::path source = kCorpus / GetParam();
  const Expectation expect = readExpectation(source / "expect.yaml");
  CaseRunner runner(CaseSource{kBase});
  const fs::path dir = runner.dir();
  if (fs::exists(source / "beforeSampling")) overlay(source / "beforeSampling", dir);
  if (expect.sample) {
    ASSERT_EQ(runner.run(POROSPH_SAMPLER, "", kTimeout), 0) << runner.read("log.sampleParticles");
  }
  for (const std::string& path : expect.remove) {
    ASSERT_TRUE(fs::exists(dir / path)) << "expect.yaml removes " << path << ", which the case does not have";
    fs::remove_all(dir / path);
  }
  overlay(source, dir);
  if (expect.truncate) {
    const auto& [file, keep] = *expect.truncate;
    const auto size = fs::file_size(dir / file);
    fs::resize_file(dir / file, static_cast<std::uintmax_t>(keep * static_cast<double>(size)));
  }
  if (expect.overwrite) {
    const auto& o = *expect.overwrite;
    std::fstream f(dir / o.file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(o.at * static_cast<double>(fs::file_size(dir / o.file))));
    f << std::string(static_cast<std::size_t>(o.bytes), '\xFF');
    ASSERT_TRUE(f.good());
  }
  const std::vector<std::string> before = timeDirectories(dir);

  const int code = runner.run(expect.application, expect.arguments, kTimeout);
  const std::string log = runner.read(expect.log);
  EXPECT_EQ(code, 1) << log;
  // The class line, then the message; one naming a case file starts with its full path, and $CASE stands for
  // that path inside the message.
  std::string message = expect.message;
  for (std::size_t at = message.find("$CASE"); at != std::string::npos; at = message.find("$CASE", at))
    message.replace(at, 5, dir.string());
  const std::string head = message.substr(0, message.find(':'));
  const bool namesAFile = head.find(' ') == std::string::npos;
  const std::string expected =
      "--> PoroSPH FATAL " + expect.error + ":\n" + (namesAFile ? dir.string() + "/" : std::string()) + message;
  EXPECT_NE(log.find(expected), std::string::npos) << "expected:\n" << expected << "\nin the log:\n" << log;
  EXPECT_EQ(timeDirectories(dir), before) << "a refused case must write no time directory";
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInputCorpus, ::testing::ValuesIn(corpusCases()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
} // namespace poro::test
