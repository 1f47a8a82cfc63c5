// fluidSurface and renderCase end to end through the executables (issue 22): a tiny synthetic case whose porous
// block is dry on its left half and soaked on its right, drawn head on; the picture must show the dry half light
// and the wet half dark. Without DISPLAY renderCase runs itself under xvfb-run (CI).

#include "CaseRunner.hpp"

#include "physics/FieldNames.hpp"
#include "render/ColourMap.hpp"
#include "render/PngImage.hpp"
#include "surface/SurfaceFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace poro::test {
namespace {

namespace fs = std::filesystem;

constexpr double kR = 0.01;

const char* const kParticleDict = R"(particleRadius: 0.01
regions:
  - {name: drop, phase: fluid, shape: box, min: [0.5, 0, 0], max: [0.58, 0.08, 0.08]}
  - {name: block, phase: porous, material: foam, shape: box, min: [0, 0, 0], max: [0.16, 0.16, 0.08], fixed: true}
)";
// Head on at the block's front face (z = 0.08), 20 degrees: the face spans the middle of a 200 px square.
const char* const kRenderDict = R"(imageSize: [200, 200]
background: [0, 0, 0]
timeLabel: false
legend: false
camera: {position: [0.08, 0.08, 1.0], focalPoint: [0.08, 0.08, 0.04], viewUp: [0, 1, 0], viewAngle: 20}
)";

/// Time 0 as sampled (no saturation) and time 1 with the left half (x < 0.08) dry, the right half soaked.
void writeTime(const fs::path& caseDir, double t) {
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.resize(64);
  for (int i = 0; i < 64; ++i) {
    fluid.x()[i] = Vec3(0.5 + kR + 2 * kR * (i % 4), kR + 2 * kR * (i / 4 % 4), kR + 2 * kR * (i / 16));
    fluid.v()[i] = Vec3(0.0, -1.0, 0.0);
    fluid.integer(field::id)[i] = i;
  }
  ParticleSet& foam = ps.add("foam", SetKind::Porous);
  foam.addInt(field::materialId, Restart);
  foam.resize(8 * 8 * 4);
  auto* saturation = t > 0 ? &foam.addReal(field::saturation, Output) : nullptr;
  for (int i = 0; i < 256; ++i) {
    foam.x()[i] = Vec3(kR + 2 * kR * (i % 8), kR + 2 * kR * (i / 8 % 8), kR + 2 * kR * (i / 64));
    foam.integer(field::id)[i] = 64 + i;
    foam.integer(field::objectId)[i] = 1;
    if (saturation) (*saturation)[i] = foam.x()[i].x() < 0.08 ? 0.0 : 1.0;
  }
  TimeWriter::writeAll(caseDir, ps, RunState{t, static_cast<long long>(t * 100), 0.001}, true);
}

class RenderCase : public ::testing::Test {
protected:
  RenderCase() : runner_(CaseSource{}) {
    fs::create_directories(runner_.dir() / "system");
    fs::create_directories(runner_.dir() / "constant");
    runner_.write("system/particleDict", kParticleDict);
    runner_.write("constant/fluidProperties", "density: 1000\nviscosity: 0\ngravity: [0, -9.81, 0]\n");
    runner_.write("constant/porosityProperties", "foam:\n  porosity: 0.5\n  bulkDensity: 500\n");
    writeTime(runner_.dir(), 1.0);
    writeTime(runner_.dir(), 0.0); // last: writeAll starts case.pvd afresh with time 0 ...
    PvdSeries series = PvdSeries::read(runner_.dir() / "case.pvd");
    for (const char* part : {"fluid", "porous"}) series.add(1.0, part, std::string("1/") + part + ".vtp");
    series.write(runner_.dir() / "case.pvd"); // ... and time 1 joins it as poroSph would have written it
  }
  int render(const std::string& arguments) const { return runner_.run(POROSPH_RENDER, arguments, 300); }
  std::string log() const { return runner_.read("log.renderCase"); }

  CaseRunner runner_;
};

TEST(RenderCaseScratch, AnEmptyCaseLeavesNothingBehind) {
  // The fixture's case starts empty; it used to be copied from an empty source directory that stayed in /tmp.
  const auto scratch = [] {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
      if (entry.path().filename().string().find(std::to_string(::getpid())) != std::string::npos)
        names.push_back(entry.path().filename().string());
    return names;
  };
  const std::vector<std::string> before = scratch();
  fs::path dir;
  {
    const CaseRunner runner(CaseSource{});
    dir = runner.dir();
    EXPECT_TRUE(fs::is_empty(dir));
  }
  EXPECT_FALSE(fs::exists(dir));
  EXPECT_EQ(scratch(), before);
}

/// CIE lightness of a pixel.
double lightness(const std::array<std::uint8_t, 3>& p) {
  return ColourMap::lightness(Vec3(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0));
}

/// The picture of time 1 shows the block (not the black background), its dry half light and its wet half dark
/// and blue, at the places where the camera puts them.
void expectDryLeftWetRight(const fs::path& png) {
  const PngImage image = PngImage::read(png);
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  // The front layer's particle centres (z = 0.07) at x = 0.05 (dry) and 0.11 (wet), y = 0.07 and 0.09 land at
  // 100 -+ 0.03 / (0.93 tan 10 deg) 100 px = 82 and 118 across, 106 and 94 down (on a particle of show:
  // particles, where its ball is lit; inside the face of the surface).
  int covered = 0;
  for (const auto& p : image.rgb) covered += p[0] + p[1] + p[2] > 60;
  // The block's face covers 98 px square, a quarter of the picture (balls on a lattice leave a fifth of it open).
  EXPECT_GT(covered, 200 * 200 / 6) << "the image is (nearly) empty";
  for (int y : {94, 106}) {
    const auto dry = image.at(82, y), wet = image.at(118, y);
    SCOPED_TRACE("row " + std::to_string(y));
    EXPECT_GT(lightness(dry), 70.0) << "dry is light: " << int(dry[0]) << " " << int(dry[1]) << " " << int(dry[2]);
    EXPECT_LT(lightness(wet), 45.0) << "wet is dark: " << int(wet[0]) << " " << int(wet[1]) << " " << int(wet[2]);
    EXPECT_GT(wet[2], wet[0] + 40) << "wet is blue";
  }
}

TEST_F(RenderCase, DryAndWetParticlesDifferInColour) {
  runner_.write("system/renderDict", std::string(kRenderDict) + "porous: {show: particles}\n");
  ASSERT_EQ(render("-time 1"), 0) << log();
  expectDryLeftWetRight(runner_.dir() / "postProcessing/renderCase/1.png");
}

TEST_F(RenderCase, TheSurfaceDarkensWhereTheBlockIsWet) {
  runner_.write("system/renderDict", kRenderDict);
  ASSERT_EQ(render(""), 0) << log();
  EXPECT_TRUE(fs::exists(runner_.dir() / "postProcessing/renderCase/0.png")) << log();
  expectDryLeftWetRight(runner_.dir() / "postProcessing/renderCase/1.png");
  // At time 0 (sampled, no saturation yet) the whole face is dry.
  const PngImage first = PngImage::read(runner_.dir() / "postProcessing/renderCase/0.png");
  EXPECT_GT(lightness(first.at(118, 106)), 70.0);
}

TEST_F(RenderCase, AFrameIsReplacedNotWrittenInPlace) {
  // An old frame hard-linked elsewhere (a copy kept, a viewer holding it): a frame written into the old file would
  // change the other name too, and a failed write would leave a half frame under the old name.
  runner_.write("system/renderDict", kRenderDict);
  const fs::path output = runner_.dir() / "postProcessing/renderCase";
  fs::create_directories(output);
  runner_.write("postProcessing/renderCase/kept.png", "old frame");
  fs::create_hard_link(output / "kept.png", output / "1.png");
  ASSERT_EQ(render("-time 1"), 0) << log();
  EXPECT_EQ(runner_.read("postProcessing/renderCase/kept.png"), "old frame");
  expectDryLeftWetRight(output / "1.png");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(output)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"1.png", "kept.png"})) << "no temporary is left behind";
}

TEST_F(RenderCase, TheMovieNeedsFfmpegAndSaysSo) {
  runner_.write("system/renderDict", kRenderDict);
  const int status = render("-movie -size 64x64");
  if (std::system("command -v ffmpeg > /dev/null 2>&1") == 0) {
    ASSERT_EQ(status, 0) << log();
    EXPECT_GT(fs::file_size(runner_.dir() / "postProcessing/renderCase/movie.mp4"), 0u);
  } else {
    EXPECT_EQ(status, 1);
    EXPECT_NE(log().find("-movie needs ffmpeg, which is not installed (apt-get install ffmpeg)"), std::string::npos)
        << log();
  }
}

/// The surface fluidSurface wrote around a lattice filling a box of sides `box`, with surfaceDict's defaults
/// (isoValue 0.5, kernel support H = 4 r). It must be a closed, consistently oriented 2-manifold facing outward.
/// Its volume: c = 0.5 on the lattice's faces, so the faces enclose the box, N (2r)^3, and to first order lose
/// nothing; edges and corners are rounded, over about H/2 = 2r (where a corner particle's kernel no longer overlaps
/// its neighbours'). Rounding an edge with radius rho removes (1 - pi/4) rho^2 per unit length, so the deficit is
/// D = (1 - pi/4) (2r)^2 L / V with L = 4 (a + b + c) the length of the edges: it scales with the box's edge length
/// per volume, the 8r drop's 12 / (8r)^2 loses 16 %, the 16r x 16r x 8r block 6.7 %. Corners (whose rounding the
/// edge strips count roughly) and the approximate radius get half of D either way: the deficit must be in
/// [0.5 D, 1.5 D]. A surface that is not closed, open at the grid's edge or inside out fails far outside it.
void expectBoxSurface(const fs::path& file, const Vec3& box) {
  SCOPED_TRACE(file.string());
  const TriangleSurface surface = readSurface(file);
  ASSERT_FALSE(surface.empty());
  const TriangleSurface::Defects defects = surface.defects();
  EXPECT_EQ(defects.openEdges, 0u);
  EXPECT_EQ(defects.nonManifoldEdges, 0u);
  EXPECT_EQ(defects.misorientedEdges, 0u);
  const double volume = box.prod();
  const double edges = 4.0 * box.sum();
  const double rho = 2.0 * kR;
  const double expectedDeficit = (1.0 - M_PI / 4.0) * rho * rho * edges / volume;
  const double deficit = 1.0 - surface.enclosedVolume() / volume;
  EXPECT_GT(deficit, 0.5 * expectedDeficit) << "enclosed " << surface.enclosedVolume() << " m^3 of " << volume;
  EXPECT_LT(deficit, 1.5 * expectedDeficit) << "enclosed " << surface.enclosedVolume() << " m^3 of " << volume;
}

TEST_F(RenderCase, FluidSurfaceWritesClosedSurfacesAndListsThem) {
  ASSERT_EQ(runner_.run(POROSPH_SURFACE, "-latestTime", 120), 0) << runner_.read("log.fluidSurface");
  EXPECT_TRUE(fs::exists(runner_.dir() / "1/fluidSurface.vtp"));
  EXPECT_TRUE(fs::exists(runner_.dir() / "1/porousSurface.vtp"));
  EXPECT_FALSE(fs::exists(runner_.dir() / "0/fluidSurface.vtp"));
  const std::string pvd = runner_.read("case.pvd");
  EXPECT_NE(pvd.find("name=\"fluidSurface\" file=\"1/fluidSurface.vtp\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("name=\"porousSurface\" file=\"1/porousSurface.vtp\""), std::string::npos) << pvd;
  // Each surface read back: closed and consistently oriented, facing outward, enclosing the particles' box less
  // its rounded edges (expectBoxSurface).
  expectBoxSurface(runner_.dir() / "1/fluidSurface.vtp", Vec3(8 * kR, 8 * kR, 8 * kR));   // the 4 x 4 x 4 drop
  expectBoxSurface(runner_.dir() / "1/porousSurface.vtp", Vec3(16 * kR, 16 * kR, 8 * kR)); // the 8 x 8 x 4 block
  // The particles stay readable: the analysis and a restart skip the surfaces.
  EXPECT_NO_THROW(runner_.particles("1", kR));
}

TEST_F(RenderCase, FluidSurfaceRebuildsAMissingCasePvd) {
  // Written with the surfaces alone, case.pvd would hide the particles from ParaView.
  fs::remove(runner_.dir() / "case.pvd");
  ASSERT_EQ(runner_.run(POROSPH_SURFACE, "-latestTime", 120), 0) << runner_.read("log.fluidSurface");
  EXPECT_NE(runner_.read("log.fluidSurface").find("case.pvd: not found; rebuilt from the time directories"),
            std::string::npos);
  std::vector<std::string> files;
  const PvdSeries series = PvdSeries::read(runner_.dir() / "case.pvd");
  for (const auto& entry : series.entries()) files.push_back(entry.file);
  EXPECT_EQ(files, (std::vector<std::string>{"0/fluid.vtp", "0/porous.vtp", "1/fluid.vtp", "1/porous.vtp",
                                             "1/fluidSurface.vtp", "1/porousSurface.vtp"}));
}

// A surfaceDict whose grid would be too large: a settings error, the same at every time. It must end the run at once
// with the file, line and key, not be taken for an unreadable time directory at every time ("none readable").
const char* const kHugeGridSurfaceDict = "porous:\n  kernelRadius: 16\n  gridSpacing: 0.05\n";

void expectStoppedAtTheDictionary(const std::string& log, const std::string& whereAndKey) {
  EXPECT_NE(log.find(whereAndKey), std::string::npos) << log;
  EXPECT_EQ(log.find("skipped"), std::string::npos) << log;
  EXPECT_EQ(log.find("none of"), std::string::npos) << log;
}

TEST_F(RenderCase, FluidSurfaceStopsAtABadSurfaceDict) {
  runner_.write("system/surfaceDict", kHugeGridSurfaceDict);
  EXPECT_EQ(runner_.run(POROSPH_SURFACE, "", 120), 1);
  expectStoppedAtTheDictionary(runner_.read("log.fluidSurface"), "system/surfaceDict:3: key 'gridSpacing'");
}

TEST_F(RenderCase, RenderCaseStopsAtABadSurfaceDict) {
  runner_.write("system/renderDict", kRenderDict);
  runner_.write("system/surfaceDict", kHugeGridSurfaceDict);
  EXPECT_EQ(render(""), 1);
  expectStoppedAtTheDictionary(log(), "system/surfaceDict:3: key 'gridSpacing'");
}

TEST_F(RenderCase, RenderCaseStopsAtABadRenderDict) {
  // With a range given, the field is first looked up while drawing.
  runner_.write("system/renderDict",
                std::string(kRenderDict) + "porous: {show: particles, colourBy: wetness, range: [0, 1]}\n");
  EXPECT_EQ(render(""), 1);
  expectStoppedAtTheDictionary(log(), "system/renderDict:6: key 'porous.colourBy'");
}

// The case directory is named after the test: an error message that names it contains "renderDict" and "colourBy",
// which must not make an unreadable time directory look like an error of the dictionary.
TEST_F(RenderCase, SkipsAnUnreadableTimeOfACaseNamed_renderDict_colourBy) {
  runner_.write("system/renderDict", std::string(kRenderDict) + "porous: {show: particles, colourBy: saturation}\n");
  fs::create_directories(runner_.dir() / "0.5/uniform");
  runner_.write("0.5/uniform/time", "time: 0.5\nstep: 50\ndeltaT: 0.001\n");
  runner_.write("0.5/fluid.vtp", "not a VTK file");
  ASSERT_EQ(render(""), 0) << log();
  EXPECT_NE(log().find("0.5: cannot be read; skipped"), std::string::npos) << log();
  EXPECT_TRUE(fs::exists(runner_.dir() / "postProcessing/renderCase/0.png")) << log();
  EXPECT_FALSE(fs::exists(runner_.dir() / "postProcessing/renderCase/0.5.png")) << log();
  expectDryLeftWetRight(runner_.dir() / "postProcessing/renderCase/1.png");
}

} // namespace
} // namespace poro::test
