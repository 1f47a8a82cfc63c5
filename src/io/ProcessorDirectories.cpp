#include "io/ProcessorDirectories.hpp"

#include "core/Error.hpp"
#include "io/TimeDirectory.hpp"
#include "parallel/Decomposition.hpp"

#include <set>

namespace fs = std::filesystem;

namespace poro {

namespace {
constexpr const char* kPrefix = "processor";
} // namespace

fs::path processorDirectory(const fs::path& caseDir, int n) { return caseDir / (kPrefix + std::to_string(n)); }

bool isProcessorDirectory(const fs::path& dir) {
  const std::string name = dir.filename().string();
  const std::string prefix = kPrefix;
  return name.rfind(prefix, 0) == 0 && name.size() > prefix.size() && name.size() <= 15 &&
         name.find_first_not_of("0123456789", prefix.size()) == std::string::npos;
}

std::vector<fs::path> listProcessorDirectories(const fs::path& caseDir) {
  std::set<int> ranks;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
    if (!entry.is_directory() || !isProcessorDirectory(entry.path())) continue;
    ranks.insert(std::stoi(entry.path().filename().string().substr(std::string(kPrefix).size())));
  }
  std::vector<fs::path> result;
  for (const int rank : ranks) {
    const int expected = static_cast<int>(result.size());
    if (rank != expected)
      throw InputError(processorDirectory(caseDir, expected).string() + ": missing, but " +
                       processorDirectory(caseDir, rank).string() +
                       " exists; a decomposed case has processor0 to processor<N-1>, decompose it again");
    result.push_back(processorDirectory(caseDir, rank));
  }
  return result;
}

namespace {

void requireTimeInEvery(const std::vector<fs::path>& processors, const std::string& time) {
  for (const fs::path& p : processors)
    if (!fs::exists(p / time / "uniform" / "time"))
      throw InputError((p / time).string() + ": missing or incomplete, but " + (processors.front() / time).string() +
                       " exists; every subdomain needs each time");
}

} // namespace

PvdSeries seriesOfSubdomains(const std::vector<fs::path>& processors) {
  PvdSeries all;
  for (const fs::path& processor : processors) {
    const std::string name = processor.filename().string();
    const PvdSeries own = seriesOfTimeDirectories(processor);
    for (const PvdSeries::Entry& e : own.entries()) all.add(e.time, e.part + "." + name, name + "/" + e.file);
  }
  return all;
}

ParticleSystem readDecomposedParticles(const std::vector<fs::path>& processors, const std::string& time,
                                       double particleRadius, const std::vector<PorousMaterial>& materials) {
  requireTimeInEvery(processors, time);
  std::vector<ParticleSystem> pieces;
  std::vector<std::string> names;
  for (const fs::path& p : processors) {
    pieces.push_back(readParticles(p, time, particleRadius, materials));
    names.push_back((p / time).string());
  }
  return mergePieces(std::move(pieces), names, particleSetOrder(materials));
}

RunState readDecomposedRunState(const std::vector<fs::path>& processors, const std::string& time) {
  requireTimeInEvery(processors, time);
  const RunState state = readRunState(processors.front() / time);
  for (std::size_t p = 1; p < processors.size(); ++p) {
    const RunState other = readRunState(processors[p] / time);
    if (other.time != state.time || other.step != state.step || other.nextDeltaT != state.nextDeltaT ||
        other.rigidBodies.size() != state.rigidBodies.size())
      throw InputError((processors[p] / time / "uniform" / "time").string() + ": step " + std::to_string(other.step) +
                       ", but " + (processors.front() / time).string() + " is at step " + std::to_string(state.step) +
                       "; the subdomains of one time must come from one run");
  }
  return state;
}

} // namespace poro
