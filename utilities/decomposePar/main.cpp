/// decomposePar: a time directory of a case -> processor<N>/<t>/, one subdomain each (system/decomposeParDict).

#include "core/Arguments.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "io/CaseReader.hpp"
#include "io/OutputSettings.hpp"
#include "io/ProcessorDirectories.hpp"
#include "io/TimeDirectory.hpp"
#include "parallel/Decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace poro;

namespace {

const char* const kDetails = R"(
Every particle of the time directory, walls and rigid bodies included, goes to exactly one subdomain, with every
field it has (restart fields too). processor<N>/<t>/ holds that subdomain's fluid.vtp, porous.vtp, boundary.vtp and
rigid.vtp (possibly without particles), uniform/time and uniform/sampling, as a time directory of the case would.
The log lists per subdomain its particles, its share of the weight and the particles within the support radius
4r of another subdomain (those a rank exchanges with its neighbours in a parallel run), and the imbalance: the
heaviest subdomain's weight over the mean, minus 1. reconstructPar merges the subdomains back.
)";

/// -time T, or the latest complete time directory.
std::string timeToDecompose(const Arguments& args, const fs::path& caseDir) {
  const std::vector<TimeDirectoryEntry> times = listTimeDirectories(caseDir);
  if (times.empty())
    throw InputError(caseDir.string() + ": no complete time directory to decompose; run sampleParticles first");
  if (!args.has("time")) return times.back().name;
  const std::string wanted = args.value("time");
  char* end = nullptr;
  const double value = std::strtod(wanted.c_str(), &end);
  if (wanted.empty() || *end != '\0' || !std::isfinite(value))
    throw InputError("option -time: expected a time value, got '" + wanted + "'");
  std::string available;
  for (const TimeDirectoryEntry& t : times) { // by value, as saturationAnalysis and reconstructPar: 0.20 is 0.2
    if (std::abs(t.time - value) <= 1e-10 * std::max(1.0, std::abs(value))) return t.name;
    available += " " + t.name;
  }
  throw InputError("option -time: no complete time directory " + wanted + " in " + caseDir.string() +
                   "; there are:" + available);
}

/// Removes processor directories of an earlier decomposition (-force), or refuses to touch them.
void clearProcessorDirectories(const fs::path& caseDir, bool force) {
  std::vector<fs::path> old;
  for (const auto& entry : fs::directory_iterator(caseDir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name.rfind("processor", 0) == 0 && name.size() > 9 &&
        name.find_first_not_of("0123456789", 9) == std::string::npos)
      old.push_back(entry.path());
  }
  std::sort(old.begin(), old.end());
  if (old.empty()) return;
  if (!force)
    throw InputError(old.front().string() + ": the case is decomposed already; run reconstructPar first if its "
                                            "subdomains hold results, or use -force to replace them");
  for (const fs::path& dir : old) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (ec) throw OutputError(dir.string() + ": cannot remove: " + ec.message());
  }
}

std::string report(const ParticleSystem& particles, const DecompositionSummary& summary) {
  std::ostringstream out;
  out << std::left << std::setw(12) << "subdomain";
  for (std::size_t s = 0; s < particles.size(); ++s) out << std::right << std::setw(12) << particles[s].name();
  out << std::setw(10) << "weight" << std::setw(12) << "interface"
      << "\n";
  double total = 0.0;
  for (const double w : summary.weights) total += w;
  for (std::size_t p = 0; p < summary.weights.size(); ++p) {
    out << std::left << std::setw(12) << ("processor" + std::to_string(p)) << std::right;
    for (const std::size_t n : summary.particles[p]) out << std::setw(12) << n;
    out << std::setw(9) << std::fixed << std::setprecision(1) << 100.0 * summary.weights[p] / total << "%"
        << std::setw(12) << summary.boundaryParticles[p] << "\n";
  }
  out << "Imbalance (heaviest over mean, minus 1): " << std::setprecision(3) << 100.0 * summary.imbalance << " %";
  return out.str();
}

} // namespace

int main(int argc, char* argv[]) try {
  const Arguments args(argc, argv, "decomposePar",
                       "Splits a time directory of a case into subdomains for a parallel run, as\n"
                       "system/decomposeParDict says (template: etc/caseDicts/decomposeParDict).",
                       {{"time", "T", "the time directory to decompose (default: the latest)"},
                        {"force", "", "replace the processor directories of an earlier decomposition"}});
  if (args.help()) {
    std::cout << args.usage() << kDetails;
    return 0;
  }
  const fs::path caseDir = args.caseDir();
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const DecomposeSettings settings = readDecomposeSettings(caseDir);
  const std::string time = timeToDecompose(args, caseDir);
  const OutputSettings output = OutputSettings::read(Dictionary::read((caseDir / "system" / "controlDict").string()));
  const std::vector<PorousMaterial> materials = readPorousMaterials(caseDir);
  const RunState state = readRunState(caseDir / time);
  const ParticleSystem particles = readParticles(caseDir, time, readParticleRadius(caseDir), materials);
  const std::string samplingRecord = readSamplingRecordText(caseDir / time);
  log::info("Case: " + caseDir.string() + "\nTime: " + time + ", " + std::to_string(particles.particleCount()) +
            " particles\nSubdomains: " + std::to_string(settings.subdomains) + ", method " + toString(settings.method));

  const DecomposedParticles decomposed = decomposeParticles(particles, settings);
  clearProcessorDirectories(caseDir, args.has("force"));
  for (int p = 0; p < settings.subdomains; ++p) {
    const fs::path dir = processorDirectory(caseDir, p);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw OutputError(dir.string() + ": cannot create directory: " + ec.message());
    writeTimeDirectory(dir, decomposed.pieces[static_cast<std::size_t>(p)], state, output.binary, samplingRecord, true);
  }
  log::info(report(particles, decomposed.summary) + "\nWrote processor0 to processor" +
            std::to_string(settings.subdomains - 1) + " at time " + time + "\nEnd");
  return 0;
} catch (const Error& e) {
  log::fatal(e);
  return 1;
} catch (const std::exception& e) {
  log::fatal(e.what());
  return 1;
}
