/// fluidSurface: time directories -> <t>/fluidSurface.vtp and <t>/porousSurface.vtp, listed in case.pvd.

#include "analysis/AnalysisSettings.hpp"
#include "analysis/TimeSelection.hpp"
#include "core/Arguments.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "core/Timer.hpp"
#include "io/CaseLock.hpp"
#include "io/PvdSeries.hpp"
#include "io/TimeDirectory.hpp"
#include "surface/SurfaceFile.hpp"
#include "surface/SurfaceReconstruction.hpp"

#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;
using namespace poro;

namespace {

const char* const kDetails = R"(
Each surface is the contour c = isoValue of the colour field c(x) = sum_j V_j W(x - x_j) (cubic kernel of support
kernelRadius r), sampled on a grid of spacing gridSpacing r that reaches beyond the particles, so the surface is
closed and faces outward; c is 1 inside a lattice of particles and 0.5 on its faces, so with the default
isoValue 0.5 the surface encloses the particles' volume N (2r)^3 (edges and corners rounded over about H).
  fluidSurface.vtp   the fluid with its velocity `v` (Shepard average of the particles' v over the kernel).
                     Pore fluid (within the lattice cell of a porous particle, as saturationAnalysis counts it)
                     is left out (surfaceDict fluid.poreFluid: exclude): it fills only the pores, so a surface
                     around it would be a second skin on the body, hiding it; it shows as the body's saturation.
  porousSurface.vtp  all porous bodies with their `saturation`; particle volumes follow the body's deformation
                     (rest against current number density), so a swollen or squeezed body stays closed.
Keys (all optional) in system/surfaceDict, see etc/caseDicts/surfaceDict. Both files are added to case.pvd as the
blocks fluidSurface and porousSurface, at the times they were made. poroSph and saturationAnalysis ignore them.
A time directory that cannot be read is named in a warning and skipped; if none can be read, the exit status is 1.
)";

std::string describeGrid(const ScalarGrid& grid) {
  std::ostringstream out;
  out << grid.dims[0] << " x " << grid.dims[1] << " x " << grid.dims[2];
  return out.str();
}

/// Reconstructs, writes and lists one surface; returns the log line.
std::string makeSurface(const ParticleCloud& cloud, const ReconstructionSettings& settings, double radius,
                        const fs::path& caseDir, const TimeCandidate& time, const char* file, PvdSeries& series) {
  const Timer timer;
  const Reconstruction made = reconstruct(cloud, settings, radius);
  writeSurface(made.surface, caseDir / time.name / file);
  series.add(time.time, fs::path(file).stem().string(), time.name + "/" + file);
  const double particles = static_cast<double>(cloud.positions.size()) * 8.0 * radius * radius * radius;
  std::ostringstream line;
  line << fs::path(file).stem().string() << " " << made.surface.triangles.size() << " triangles, "
       << made.surface.points.size() << " points (grid " << describeGrid(made.grid) << "), volume "
       << made.surface.enclosedVolume() << " m^3 (" << cloud.positions.size() << " particles: " << particles
       << " m^3), " << std::setprecision(3) << timer.seconds() << " s";
  return line.str();
}

} // namespace

int main(int argc, char* argv[]) try {
  const Arguments args(
      argc, argv, "fluidSurface",
      "Post-processing: reconstructs the free surface of the fluid and the surfaces of the porous bodies at each\n"
      "selected time into <t>/fluidSurface.vtp (with the velocity) and <t>/porousSurface.vtp (with the\n"
      "saturation), and lists them in case.pvd as the blocks fluidSurface and porousSurface.",
      timeOptions("process"));
  if (args.help()) {
    std::cout << args.usage() << kDetails;
    return 0;
  }
  const fs::path caseDir = args.caseDir();
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const CaseLock lock(caseDir, "fluidSurface"); // it writes into time directories and case.pvd
  if (args.threads() > 0) parallel::setThreads(args.threads());

  const AnalysisSettings analysis = readAnalysisSettings(caseDir);
  const SurfaceSettings settings = readSurfaceSettings(caseDir);
  const TimeSelection selection = selectTimes(args, caseDir);
  log::info("Case: " + caseDir.string() + "\nTimes: " + std::to_string(selection.complete.size()) +
            "\nThreads: " + std::to_string(parallel::threads()));

  const fs::path pvd = caseDir / "case.pvd";
  PvdSeries series;
  if (fs::exists(pvd)) {
    series = PvdSeries::read(pvd);
  } else { // written with the surfaces alone, it would hide the particles from ParaView
    series = seriesOfTimeDirectories(caseDir);
    log::warning(pvd.string() + ": not found; rebuilt from the time directories (" +
                 std::to_string(series.entries().size()) + " files) before adding the surfaces");
  }
  std::size_t done = 0;
  for (const TimeCandidate& time : selection.complete) {
    const Timer timer;
    // Only the reading is tried: an unreadable directory is reported and skipped, never the end of the run, while an
    // error of surfaceDict (a grid too large for gridSpacing) or of writing ends it at once, naming file and key.
    std::optional<ParticleSystem> read;
    try {
      read.emplace(readParticles(caseDir, time.name, analysis.particleRadius, analysis.materials));
    } catch (const InputError& e) {
      log::warning((caseDir / time.name).string() + ": cannot be read; skipped:\n    " + e.what());
      continue;
    }
    const ParticleSystem& particles = *read;
    std::ostringstream line;
    line << "Time " << time.name << ":";
    const double r = particles.particleRadius();
    if (settings.writeFluid)
      line << "\n  "
           << makeSurface(fluidCloud(particles, settings), settings.fluid, r, caseDir, time, kFluidSurfaceFile, series);
    bool porous = false;
    for (std::size_t s = 0; s < particles.size(); ++s) porous = porous || particles[s].kind() == SetKind::Porous;
    if (settings.writePorous && porous)
      line << "\n  "
           << makeSurface(porousCloud(particles), settings.porous, r, caseDir, time, kPorousSurfaceFile, series);
    line << "\n  " << std::setprecision(3) << timer.seconds() << " s with reading and writing";
    log::info(line.str());
    series.write(pvd); // after every time: what is done stays listed if the run is stopped
    ++done;
  }
  if (done == 0) throw noneReadable(caseDir, selection.complete.size());
  log::info("Wrote the surfaces of " + std::to_string(done) + " of " + std::to_string(selection.complete.size()) +
            " time directories and " + pvd.string() + "\nEnd");
  return 0;
} catch (const Error& e) {
  log::fatal(e);
  return 1;
} catch (const std::exception& e) {
  log::fatal(e.what());
  return 1;
}
