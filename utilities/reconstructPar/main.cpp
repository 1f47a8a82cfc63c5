/// reconstructPar: processor<N>/<t>/ of a decomposed case -> <t>/, as a serial run writes it.

#include "analysis/TimeSelection.hpp"
#include "core/Arguments.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "io/CaseReader.hpp"
#include "io/OutputSettings.hpp"
#include "io/ProcessorDirectories.hpp"
#include "io/PvdSeries.hpp"
#include "io/TimeDirectory.hpp"

#include <iostream>

namespace fs = std::filesystem;
using namespace poro;

namespace {

const char* const kDetails = R"(
The times are those of processor0; each must be complete in every processor directory. A reconstructed <t>/ holds
the same files a serial run writes (fluid.vtp, porous.vtp, rigid.vtp, boundary.vtp where the subdomains have their
own, uniform/time, uniform/sampling), with the particles of every set in the order of their ids, and replaces an
existing <t>/ atomically. case.pvd is then rewritten from the case's time directories. poroSph continues a run from
a reconstructed time like from any other.
)";

bool ownBoundaries(const std::vector<fs::path>& processors, const std::string& time) {
  for (const fs::path& p : processors)
    if (!fs::exists(p / time / "boundary.vtp")) return false;
  return true;
}

} // namespace

int main(int argc, char* argv[]) try {
  const Arguments args(
      argc, argv, "reconstructPar",
      "Merges the subdomains of a decomposed case (processor<N>/<t>/) back into time directories <t>/.", [] {
        auto options = timeOptions("reconstruct");
        options.push_back({"newTimes", "", "only the times the case does not have yet"});
        return options;
      }());
  if (args.help()) {
    std::cout << args.usage() << kDetails;
    return 0;
  }
  const fs::path caseDir = args.caseDir();
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const std::vector<fs::path> processors = listProcessorDirectories(caseDir);
  if (processors.empty())
    throw InputError(caseDir.string() + ": no processor directories; the case is not decomposed (decomposePar)");
  const TimeSelection selection = selectTimes(args, processors.front());
  const OutputSettings output = OutputSettings::read(Dictionary::read((caseDir / "system" / "controlDict").string()));
  const std::vector<PorousMaterial> materials = readPorousMaterials(caseDir);
  const double radius = readParticleRadius(caseDir);
  log::info("Case: " + caseDir.string() + "\nSubdomains: " + std::to_string(processors.size()));

  std::size_t written = 0;
  for (const TimeCandidate& time : selection.complete) {
    if (args.has("newTimes") && fs::exists(caseDir / time.name / "uniform" / "time")) continue;
    const RunState state = readDecomposedRunState(processors, time.name);
    const ParticleSystem merged = readDecomposedParticles(processors, time.name, radius, materials);
    writeTimeDirectory(caseDir, merged, state, output.binary, readSamplingRecordText(processors.front() / time.name),
                       ownBoundaries(processors, time.name));
    log::info("Time " + time.name + ": " + std::to_string(merged.particleCount()) + " particles");
    ++written;
  }
  seriesOfTimeDirectories(caseDir).write(caseDir / "case.pvd");
  log::info("Reconstructed " + std::to_string(written) + " time directories; rewrote case.pvd\nEnd");
  return 0;
} catch (const Error& e) {
  log::fatal(e);
  return 1;
} catch (const std::exception& e) {
  log::fatal(e.what());
  return 1;
}
