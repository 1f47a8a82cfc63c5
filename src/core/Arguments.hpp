#pragma once
/// OpenFOAM-style command-line options shared by the applications: -case DIR, -threads N, -help, and
/// application-specific flags and options.

#include <map>
#include <string>
#include <vector>

namespace poro {

class Arguments {
public:
  struct Option {
    std::string name;        ///< without the dash
    std::string argument;    ///< placeholder ("DIR"), empty for a flag
    std::string description;
  };

  /// Parses argv against the common options plus `extra`. Unknown options or missing values throw InputError.
  Arguments(int argc, const char* const argv[], std::string application, std::string synopsis,
            std::vector<Option> extra = {});

  bool help() const { return has("help"); }
  /// The usage text for -help.
  std::string usage() const;

  bool has(const std::string& name) const { return values_.count(name) > 0; }
  std::string value(const std::string& name) const;
  /// The case directory (-case, default the current directory).
  std::string caseDir() const;
  /// -threads N (0 when not given); N in [1, 4096], as solverDict's threads.
  int threads() const;

private:
  std::string application_, synopsis_;
  std::vector<Option> options_;
  std::map<std::string, std::string> values_;
};

} // namespace poro
