// saturationAnalysis end to end through the executable (issue 6): a synthetic case with known answers, broken
// and missing time directories. The real runs it analyses are the tutorials' (tutorials/*/*/Alltest).

#include "CaseRunner.hpp"

#include "physics/FieldNames.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>

namespace poro::test {
namespace {

namespace fs = std::filesystem;

constexpr double kR = 0.02;
const double kV = 8.0 * kR * kR * kR;
constexpr double kPorosity = 0.5;
const fs::path kOutput = fs::path("postProcessing") / "saturationAnalysis";

/// A CSV file as written by saturationAnalysis (no quoted cells in these cases).
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  static Csv read(const fs::path& file) {
    std::ifstream in(file);
    Csv csv;
    std::string line;
    for (bool first = true; std::getline(in, line); first = false) {
      std::vector<std::string> cells;
      std::stringstream cellStream(line);
      for (std::string cell; std::getline(cellStream, cell, ',');) cells.push_back(cell);
      if (!line.empty() && line.back() == ',') cells.emplace_back();
      (first ? csv.header : csv.rows.emplace_back()) = cells;
    }
    return csv;
  }
  std::string cell(std::size_t row, const std::string& column) const {
    const auto at = std::find(header.begin(), header.end(), column);
    if (at == header.end()) ADD_FAILURE() << "no column " << column;
    return at == header.end() ? "" : rows.at(row).at(static_cast<std::size_t>(at - header.begin()));
  }
  double number(std::size_t row, const std::string& column) const {
    return std::strtod(cell(row, column).c_str(), nullptr);
  }
};

// ---- The synthetic case: a 4x4x4 porous lattice "block" (objectId 1) and 20 fluid particles. -------------------

/// Fluid particles inside the block [0, 0.16]^3 at each written time; the rest of the 20 wait above it.
const std::map<std::string, int> kInside = {{"0", 0}, {"0.5", 8}, {"1", 14}, {"1.5", 20}};
constexpr int kFluid = 20;

/// Saturation of the block's y layer j (0..3) at time t: the layers fill from the top, one per 0.5 s, the next
/// one a quarter full.
double layerSaturation(double t, int j) { return std::clamp(2.0 * t - (3 - j) + 0.25, 0.0, 1.0); }

const char* const kParticleDict = R"(particleRadius: 0.02
regions:
  - {name: column, phase: fluid, shape: box, min: [0, 0.2, 0], max: [0.16, 0.36, 0.16]}
  - {name: block, phase: porous, material: soil, shape: box, min: [0, 0, 0], max: [0.16, 0.16, 0.16], fixed: true}
)";
const char* const kFluidProperties = "density: 1000\nviscosity: 0\ngravity: [0, -9.81, 0]\n";
const char* const kPorosityProperties = "soil:\n  porosity: 0.5\n  bulkDensity: 1000\n";

/// One time directory, as poroSph writes it (at time 0 as sampleParticles does: no saturation, no density).
void writeTime(const fs::path& caseDir, const std::string& name) {
  const double t = std::stod(name);
  ParticleSystem ps(kR);
  ParticleSet& fluid = ps.add("fluid", SetKind::Fluid);
  fluid.resize(kFluid);
  for (int k = 0; k < kFluid; ++k) {
    const bool inside = k < kInside.at(name);
    fluid.x()[k] = inside ? Vec3(0.01 + 0.007 * k, 0.05, 0.08) : Vec3(0.01 + 0.007 * k, 0.25, 0.08);
    fluid.v()[k] = Vec3(0.0, -1.0, 0.0);
    fluid.integer(field::id)[k] = k;
  }
  ParticleSet& soil = ps.add("soil", SetKind::Porous);
  soil.addInt(field::materialId, Restart);
  soil.resize(64);
  for (int i = 0; i < 64; ++i) {
    soil.x()[i] = Vec3(kR + 2 * kR * (i % 4), kR + 2 * kR * (i / 4 % 4), kR + 2 * kR * (i / 16));
    soil.integer(field::id)[i] = kFluid + i;
    soil.integer(field::objectId)[i] = 1;
  }
  if (t > 0) {
    auto& s = soil.addReal(field::saturation, Output);
    for (int i = 0; i < 64; ++i) s[i] = layerSaturation(t, i / 4 % 4);
    auto& rho = fluid.addReal(field::density, Output);
    std::fill(rho.begin(), rho.end(), 1000.0);
    rho[0] = 1002.0; // 0.2 % compressed; mean 0.01 %
  }
  TimeWriter::writeAll(caseDir, ps, RunState{t, static_cast<long long>(100 * t), 0.001}, true);
}

/// A CaseRunner on an empty source, filled with the synthetic case.
class SyntheticCase {
public:
  SyntheticCase() : source_(makeSource()), runner_(CaseSource{source_}) {
    fs::remove(source_);
    fs::create_directories(runner_.dir() / "system");
    fs::create_directories(runner_.dir() / "constant");
    runner_.write("system/particleDict", kParticleDict);
    runner_.write("constant/fluidProperties", kFluidProperties);
    runner_.write("constant/porosityProperties", kPorosityProperties);
    for (const auto& [name, inside] : kInside) writeTime(runner_.dir(), name);
  }
  CaseRunner& runner() { return runner_; }
  const fs::path& dir() const { return runner_.dir(); }
  int analyse(const std::string& arguments = "") const { return runner_.run(POROSPH_ANALYSIS, arguments, 120); }
  std::string log() const { return runner_.read("log.saturationAnalysis"); }
  Csv timeSeries() const { return Csv::read(dir() / kOutput / "timeSeries.csv"); }

private:
  static fs::path makeSource() {
    const fs::path source = fs::temp_directory_path() / ("porosph_empty_case_" + std::to_string(::getpid()));
    fs::create_directories(source);
    return source;
  }
  fs::path source_;
  CaseRunner runner_;
};

TEST(SaturationAnalysisCase, SyntheticCaseGivesExactVolumesSaturationsAndProfiles) {
  SyntheticCase synthetic;
  ASSERT_EQ(synthetic.analyse(), 0) << synthetic.log();
  const Csv series = synthetic.timeSeries();
  ASSERT_EQ(series.rows.size(), kInside.size()) << synthetic.log();
  std::size_t row = 0;
  for (const auto& [name, inside] : kInside) {
    const double t = std::stod(name);
    SCOPED_TRACE("time " + name);
    EXPECT_EQ(series.number(row, "time_s"), t);
    EXPECT_EQ(series.number(row, "block.solidParticles"), 64);
    EXPECT_EQ(series.number(row, "block.absorbedParticles"), inside);
    EXPECT_DOUBLE_EQ(series.number(row, "block.absorbedVolume_m3"), inside * kV);
    EXPECT_DOUBLE_EQ(series.number(row, "block.absorbedMass_kg"), inside * 1000.0 * kV);
    EXPECT_DOUBLE_EQ(series.number(row, "block.poreVolume_m3"), kPorosity * 64 * kV);
    EXPECT_DOUBLE_EQ(series.number(row, "block.fractionFilled"), inside / (kPorosity * 64));
    EXPECT_EQ(series.number(row, "fluid.particles"), kFluid);
    EXPECT_DOUBLE_EQ(series.number(row, "fluid.kineticEnergy_J"), 0.5 * 1000.0 * kV * kFluid);
    EXPECT_DOUBLE_EQ(series.number(row, "fluid.momentumY_kg_m_per_s"), -1000.0 * kV * kFluid);
    if (t == 0) { // sampleParticles' 0/: nothing computed yet
      EXPECT_EQ(series.cell(row, "block.meanSaturation"), "");
      EXPECT_EQ(series.cell(row, "fluid.meanDensityError_percent"), "");
    } else {
      double mean = 0.0;
      int wet = 0, lowestWet = 4;
      for (int j = 0; j < 4; ++j) {
        mean += layerSaturation(t, j) / 4;
        if (layerSaturation(t, j) >= 0.5) ++wet, lowestWet = std::min(lowestWet, j);
      }
      EXPECT_NEAR(series.number(row, "block.meanSaturation"), mean, 1e-15);
      EXPECT_EQ(series.number(row, "block.wetParticles"), 16 * wet);
      EXPECT_NEAR(series.number(row, "block.wetMin_m"), kR + 2 * kR * lowestWet, 1e-15);
      EXPECT_NEAR(series.number(row, "block.wetMax_m"), kR + 2 * kR * 3, 1e-15);
      EXPECT_NEAR(series.number(row, "block.wetHeight_m"), 2 * kR * (3 - lowestWet), 1e-15);
      EXPECT_NEAR(series.number(row, "fluid.meanDensityError_percent"), 0.2 / kFluid, 1e-12);
      EXPECT_NEAR(series.number(row, "fluid.maxDensityError_percent"), 0.2, 1e-12);
    }
    ++row;
  }

  // Profiles: one bin per layer, centred on it, at every time after 0.
  const Csv profiles = Csv::read(synthetic.dir() / kOutput / "saturationProfiles.csv");
  ASSERT_EQ(profiles.rows.size(), 3u * 4u);
  for (std::size_t k = 0; k < profiles.rows.size(); ++k) {
    const double t = profiles.number(k, "time_s");
    const int j = static_cast<int>(k % 4);
    EXPECT_EQ(t, 0.5 * static_cast<double>(1 + k / 4));
    EXPECT_EQ(profiles.cell(k, "object"), "block");
    EXPECT_NEAR(profiles.number(k, "position_m"), kR + 2 * kR * j, 1e-15);
    EXPECT_DOUBLE_EQ(profiles.number(k, "meanSaturation"), layerSaturation(t, j));
    EXPECT_EQ(profiles.number(k, "particles"), 16);
  }
  for (const char* plot : {"absorbedVolume.svg", "fillFraction.svg", "wetFront.svg", "densityError.svg",
                           "energy.svg", "fluidExtent.svg", "saturationProfiles_block.svg"})
    EXPECT_GT(fs::file_size(synthetic.dir() / kOutput / plot), 1000u) << plot;
}

TEST(SaturationAnalysisCase, BrokenTimeDirectoriesAreNamedAndSkipped) {
  SyntheticCase synthetic;
  // 0.5: fluid.vtp cut in half (a full disk, a copy interrupted); 1: no uniform/time; 2: only a name.
  const fs::path truncated = synthetic.dir() / "0.5" / "fluid.vtp";
  fs::resize_file(truncated, fs::file_size(truncated) / 2);
  fs::remove(synthetic.dir() / "1" / "uniform" / "time");
  fs::create_directories(synthetic.dir() / "2");
  ASSERT_EQ(synthetic.analyse(), 0) << synthetic.log();
  const std::string log = synthetic.log();
  EXPECT_NE(log.find((synthetic.dir() / "0.5").string() + ": cannot be read; skipped"), std::string::npos) << log;
  EXPECT_NE(log.find(truncated.string() + ": not a readable VTK PolyData file"), std::string::npos) << log;
  EXPECT_NE(log.find((synthetic.dir() / "1").string() + ": incomplete time directory (no uniform/time)"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find((synthetic.dir() / "2").string() + ": incomplete time directory"), std::string::npos) << log;
  const Csv series = synthetic.timeSeries();
  ASSERT_EQ(series.rows.size(), 2u) << log; // 0 and 1.5
  EXPECT_EQ(series.number(0, "time_s"), 0.0);
  EXPECT_EQ(series.number(1, "time_s"), 1.5);
  EXPECT_EQ(series.number(1, "block.absorbedParticles"), 20);
}

TEST(SaturationAnalysisCase, NothingToReadExitsWithAClearMessage) {
  SyntheticCase synthetic;
  EXPECT_EQ(synthetic.analyse("-time 0.7"), 1);
  EXPECT_NE(synthetic.log().find("no time directory 0.7"), std::string::npos) << synthetic.log();
  EXPECT_NE(synthetic.log().find("can be read: 0, 0.5, 1, 1.5"), std::string::npos) << synthetic.log();

  EXPECT_EQ(synthetic.analyse("-time 0.5:1"), 0) << synthetic.log();
  EXPECT_EQ(synthetic.timeSeries().rows.size(), 2u);
  EXPECT_EQ(synthetic.analyse("-latestTime"), 0) << synthetic.log();
  EXPECT_EQ(synthetic.timeSeries().rows.size(), 1u);

  EXPECT_EQ(synthetic.analyse("-axis w"), 1);
  EXPECT_NE(synthetic.log().find("-axis expects x, y, z, -x, -y or -z, got 'w'"), std::string::npos);
  EXPECT_EQ(synthetic.analyse("-wetThreshold 2"), 1);
  EXPECT_EQ(synthetic.analyse("-bogus"), 1);
  EXPECT_NE(synthetic.log().find("unknown argument '-bogus'"), std::string::npos);
  EXPECT_EQ(synthetic.analyse("-help"), 0);
  EXPECT_NE(synthetic.log().find("fractionFilled"), std::string::npos);

  // The latest directory is broken: -latestTime refuses rather than report an older time.
  const fs::path latest = synthetic.dir() / "1.5" / "porous.vtp";
  fs::resize_file(latest, 100);
  EXPECT_EQ(synthetic.analyse("-latestTime"), 1);
  EXPECT_NE(synthetic.log().find(latest.string()), std::string::npos) << synthetic.log();
  EXPECT_NE(synthetic.log().find("none of the 1 selected time directories could be read"), std::string::npos);

  const std::string missing = (synthetic.dir() / "noSuchCase").string();
  const int status =
      std::system(("'" + std::string(POROSPH_ANALYSIS) + "' -case '" + missing + "' > /dev/null 2>&1").c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << "missing case: status " << status;
}

} // namespace
} // namespace poro::test
