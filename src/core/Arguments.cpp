#include "core/Arguments.hpp"

#include "core/Error.hpp"

#include <sstream>

namespace poro {

Arguments::Arguments(int argc, const char* const argv[], std::string application, std::string synopsis,
                     std::vector<Option> extra)
    : application_(std::move(application)), synopsis_(std::move(synopsis)) {
  options_ = {{"case", "DIR", "case directory (default: the current directory)"},
              {"threads", "N", "number of OpenMP threads (default: all cores, or solverDict threads)"},
              {"help", "", "print this usage and exit"}};
  options_.insert(options_.end(), extra.begin(), extra.end());
  for (int i = 1; i < argc; ++i) {
    std::string word = argv[i];
    const std::string name = word.rfind("--", 0) == 0 ? word.substr(2) : word.rfind('-', 0) == 0 ? word.substr(1) : "";
    const Option* option = nullptr;
    for (const Option& o : options_)
      if (o.name == name) option = &o;
    if (!option) throw InputError("unknown argument '" + word + "'; run " + application_ + " -help for the options");
    if (option->argument.empty()) {
      values_[name] = "";
      continue;
    }
    if (i + 1 >= argc) throw InputError("option -" + name + " expects " + option->argument);
    values_[name] = argv[++i];
  }
  if (has("threads")) threads(); // validate now
}

std::string Arguments::value(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? std::string() : it->second;
}

std::string Arguments::caseDir() const { return has("case") ? value("case") : std::string("."); }

int Arguments::threads() const {
  if (!has("threads")) return 0;
  const std::string text = value("threads");
  std::size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  // The bound of solverDict's threads: far more threads than the OS grants a process crash OpenMP's start-up.
  constexpr int maxThreads = 4096;
  if (used != text.size() || n < 1 || n > maxThreads)
    throw InputError("option -threads expects a whole number in [1, " + std::to_string(maxThreads) + "], got '" + text +
                     "'");
  return n;
}

std::string Arguments::usage() const {
  std::ostringstream out;
  out << "Usage: " << application_ << " [OPTIONS]\n\n" << synopsis_ << "\n\nOptions:\n";
  for (const Option& o : options_) {
    std::string left = "  -" + o.name + (o.argument.empty() ? "" : " " + o.argument);
    if (left.size() < 22) left.resize(22, ' ');
    out << left << " " << o.description << '\n';
  }
  return out.str();
}

} // namespace poro
