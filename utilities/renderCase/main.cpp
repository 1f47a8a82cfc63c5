/// renderCase: time directories -> postProcessing/renderCase/<time>.png (and movie.mp4 with -movie).

#include "analysis/AnalysisSettings.hpp"
#include "analysis/TimeSelection.hpp"
#include "core/Arguments.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "core/Timer.hpp"
#include "io/TimeDirectory.hpp"
#include "render/CameraView.hpp"
#include "render/FrameRenderer.hpp"
#include "render/HeadlessDisplay.hpp"
#include "render/MovieEncoder.hpp"
#include "render/SceneBuilder.hpp"
#include "sph/ParticleSystem.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;
using namespace poro;

namespace {

const char* const kDetails = R"(
What is drawn (system/renderDict, every key optional; see etc/caseDicts/renderDict):
  fluid     its free surface, translucent (as fluidSurface makes it, from system/surfaceDict), in a water blue
            or coloured by the speed |v|; or its particles
  porous    the surfaces of the porous bodies coloured by saturation with the "wetness" map: dry is pale,
            wet is dark blue, with a legend; or its particles; a clip plane cuts them open to show the front
  boundary  container walls as the outline of their box with its floor, other walls (a moving plate) as surfaces
The camera looks at the fluid and porous bodies (at the case's first and last time) from the front, a little from
the side and above, with gravity pointing down; colour ranges are fixed for all frames (saturation 0-1, other fields over the selected times).
Frames are written to postProcessing/renderCase/<time>.png; -movie also encodes movie.mp4 with ffmpeg (not
installed by ./Allrun: apt-get install ffmpeg). VTK draws through an X display even off screen: without DISPLAY,
renderCase runs itself under xvfb-run -a (./Allrun installs xvfb). A time directory that cannot be read is named
in a warning and skipped; if none can be read, the exit status is 1.
)";

/// -size WxH over renderDict's imageSize.
void applySize(const Arguments& args, RenderSettings& settings) {
  if (!args.has("size")) return;
  const std::string text = args.value("size");
  int w = 0, h = 0;
  char x = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || x != 'x' || in >> rest || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw InputError("option -size expects WIDTHxHEIGHT in pixels (16-8192 each), e.g. 640x360, got '" + text + "'");
  settings.width = w;
  settings.height = h;
}

bool hasKind(const ParticleSystem& particles, SetKind kind) {
  for (std::size_t s = 0; s < particles.size(); ++s)
    if (particles[s].kind() == kind) return true;
  return false;
}

/// Extends [lo, hi] by the finite particles of the sets `include` accepts.
template <class Include>
void extend(const ParticleSystem& particles, const Include& include, Vec3& lo, Vec3& hi, bool& any) {
  for (std::size_t s = 0; s < particles.size(); ++s) {
    if (!include(particles[s])) continue;
    for (const Vec3& p : particles[s].x()) {
      if (!p.allFinite()) continue;
      lo = any ? Vec3(lo.cwiseMin(p)) : p;
      hi = any ? Vec3(hi.cwiseMax(p)) : p;
      any = true;
    }
  }
}

/// What the default camera frames: the fluid and porous particles of the given times, or all particles (walls
/// included) when those are empty (a solid case).
void framedBox(const std::vector<const ParticleSystem*>& times, Vec3& lo, Vec3& hi) {
  bool any = false;
  for (const ParticleSystem* particles : times)
    extend(*particles, [](const ParticleSet& set) { return set.kind() != SetKind::Boundary; }, lo, hi, any);
  if (any) return;
  for (const ParticleSystem* particles : times) extend(*particles, [](const ParticleSet&) { return true; }, lo, hi, any);
}

} // namespace

int main(int argc, char* argv[]) try {
  const Arguments args(
      argc, argv, "renderCase",
      "Post-processing: draws each selected time of a case (fluid surface, porous bodies coloured by saturation,\n"
      "walls) off screen into postProcessing/renderCase/<time>.png, as system/renderDict says.",
      [] {
        auto options = timeOptions("draw");
        options.push_back({"size", "WxH", "image size in pixels, e.g. 640x360 (default: renderDict imageSize, else 1280x720)"});
        options.push_back({"movie", "", "also write postProcessing/renderCase/movie.mp4 (needs ffmpeg)"});
        return options;
      }());
  if (args.help()) {
    std::cout << args.usage() << kDetails;
    return 0;
  }
  const fs::path caseDir = args.caseDir();
  if (!fs::is_directory(caseDir)) throw InputError(caseDir.string() + ": case directory not found");
  const std::string ffmpeg = args.has("movie") ? findFfmpeg() : "";
  if (args.has("movie") && ffmpeg.empty())
    throw Error("-movie needs ffmpeg, which is not installed (apt-get install ffmpeg); without -movie the frames "
                "are drawn as PNG files");
  ensureDisplay(argc, argv); // may run this program again under xvfb-run
  if (args.threads() > 0) parallel::setThreads(args.threads());

  const AnalysisSettings analysis = readAnalysisSettings(caseDir);
  const SurfaceSettings surface = readSurfaceSettings(caseDir);
  const TimeSelection selection = selectTimes(args, caseDir);

  // The case's first and last time (not the selection's, so that every run of renderCase on a case takes the same
  // view): whether there are porous bodies, and what the default camera frames.
  const std::vector<TimeDirectoryEntry> all = listTimeDirectories(caseDir);
  const auto readName = [&](const std::string& name) {
    return readParticles(caseDir, name, analysis.particleRadius, analysis.materials);
  };
  // Only the reading of a time directory can fail for that time alone (it is named and skipped); an error in the
  // settings (renderDict's colourBy, surfaceDict's gridSpacing) or in writing ends the run at once.
  const auto readIfReadable = [&](const TimeCandidate& time, std::string& why) -> std::optional<ParticleSystem> {
    try {
      return readName(time.name);
    } catch (const InputError& e) {
      why = e.what();
      return std::nullopt;
    }
  };
  // A broken first or last directory (warned about above if selected) gives way to the selection's.
  const auto readEither = [&](const std::string& name, const TimeCandidate& fallback) {
    try {
      return readName(name);
    } catch (const InputError&) {
      return readName(fallback.name);
    }
  };
  const ParticleSystem first = readEither(all.front().name, selection.complete.front());
  const ParticleSystem last = readEither(all.back().name, selection.complete.back());
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  framedBox({&first, &last}, lo, hi);
  RenderSettings settings = readRenderSettings(caseDir, hasKind(first, SetKind::Porous));
  applySize(args, settings);
  int legends = 0;
  for (const SetStyle* style : settings.styles())
    if (settings.legend && !style->colourBy.empty() && style->show != SetStyle::Show::None) ++legends;
  CameraView camera = CameraView::framing(lo, hi, analysis.gravity, settings.camera.viewAngle,
                                           double(settings.width) / double(settings.height),
                                           FrameRenderer::legendsWidth(legends));
  if (settings.camera.focalPoint) camera.focalPoint = *settings.camera.focalPoint;
  if (settings.camera.position) camera.position = *settings.camera.position;
  if (settings.camera.viewUp) camera.viewUp = *settings.camera.viewUp;
  // renderDict checks a viewUp given with position and focal point; with either taken from the default view, here.
  if (settings.camera.viewUp) {
    const std::string problem = viewUpProblem(camera.viewUp, camera.focalPoint - camera.position);
    if (!problem.empty()) throw InputError(settings.camera.viewUpWhere + ": key 'camera.viewUp': " + problem);
  }

  // Colour ranges fixed for the whole series: from renderDict, else over the particles of every selected time.
  std::map<std::string, std::array<double, 2>> ranges;
  for (const SetStyle* style : settings.styles()) {
    if (style->colourBy.empty() || style->show == SetStyle::Show::None) continue;
    if (style->range) {
      ranges[style->set] = *style->range;
      continue;
    }
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (const TimeCandidate& time : selection.complete) {
      std::string why; // named when the time is drawn
      const std::optional<ParticleSystem> particles = readIfReadable(time, why);
      if (!particles) continue;
      for (double v : SceneBuilder::particleValues(*particles, *style)) low = std::min(low, v), high = std::max(high, v);
    }
    if (!(low <= high)) low = 0.0, high = 1.0;
    if (high <= low) high = low + 1.0;
    ranges[style->set] = {low, high};
  }

  const fs::path output = caseDir / "postProcessing" / "renderCase";
  fs::create_directories(output);
  std::ostringstream banner;
  banner << "Case: " << caseDir.string() << "\nTimes: " << selection.complete.size() << "\nImage: " << settings.width
         << " x " << settings.height << "\nCamera: position [" << camera.position.transpose() << "], focal point ["
         << camera.focalPoint.transpose() << "], view up [" << camera.viewUp.transpose() << "]";
  for (const auto& [set, range] : ranges) banner << "\nColour range of " << set << ": " << range[0] << " to " << range[1];
  log::info(banner.str());

  SceneBuilder builder(caseDir, settings, surface, analysis.gravity);
  FrameRenderer renderer(settings, camera, ranges);
  std::vector<fs::path> frames;
  for (const TimeCandidate& time : selection.complete) {
    const Timer timer;
    std::string why;
    const std::optional<ParticleSystem> particles = readIfReadable(time, why);
    if (!particles) {
      log::warning((caseDir / time.name).string() + ": cannot be read; skipped:\n    " + why);
      continue;
    }
    const Scene scene = builder.build(*particles, time.name, time.time);
    const fs::path png = output / (time.name + ".png");
    renderer.render(scene, png);
    frames.push_back(png);
    std::ostringstream line;
    line << "Time " << time.name << ": " << png.string() << " (" << std::setprecision(3) << timer.seconds() << " s)";
    log::info(line.str());
  }
  if (frames.empty()) throw noneReadable(caseDir, selection.complete.size());
  if (!ffmpeg.empty()) {
    encodeMovie(ffmpeg, frames, settings.frameRate, output / "movie.mp4");
    log::info("Movie: " + (output / "movie.mp4").string());
  }
  log::info("Drew " + std::to_string(frames.size()) + " of " + std::to_string(selection.complete.size()) +
            " time directories into " + output.string() + "\nEnd");
  return 0;
} catch (const Error& e) {
  log::fatal(e);
  return 1;
} catch (const std::exception& e) {
  log::fatal(e.what());
  return 1;
}
