#include "io/ProcessorDirectories.hpp"

#include "core/Error.hpp"

#include <set>

namespace fs = std::filesystem;

namespace poro {

fs::path processorDirectory(const fs::path& caseDir, int n) { return caseDir / ("processor" + std::to_string(n)); }

std::vector<fs::path> listProcessorDirectories(const fs::path& caseDir) {
  std::set<int> ranks;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string prefix = "processor";
    if (!entry.is_directory() || name.rfind(prefix, 0) != 0 || name.size() == prefix.size() || name.size() > 15 ||
        name.find_first_not_of("0123456789", prefix.size()) != std::string::npos)
      continue;
    ranks.insert(std::stoi(name.substr(prefix.size())));
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

} // namespace poro
