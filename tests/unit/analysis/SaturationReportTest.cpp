// The CSV tables and plots saturationAnalysis writes, from records of the synthetic system.

#include "analysis/SaturationReport.hpp"
#include "../io/ScratchDirectory.hpp"
#include "AnalysisTestSystems.hpp"
#include "XmlCheck.hpp"
#include "analysis/SaturationPlots.hpp"
#include "analysis/SaturationTables.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace poro::test {
namespace {

/// Records at t = 0 (no saturation yet), 0.5 and 1.
std::vector<TimeRecord> records() {
  std::vector<TimeRecord> result;
  for (int k = 0; k < 3; ++k) {
    TimeRecord record = analyse(syntheticSystem(k > 0), syntheticSettings());
    record.time = 0.5 * k;
    record.name = k == 0 ? "0" : k == 1 ? "0.5" : "1";
    record.step = 10 * k;
    result.push_back(record);
  }
  return result;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

TEST(SaturationTables, TimeSeriesHasNamedColumnsWithUnits) {
  const CsvTable table = timeSeriesTable(records());
  const auto rows = lines(table.text());
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0],
            "time_s,step,"
            "block.solidParticles,block.absorbedParticles,block.absorbedVolume_m3,block.absorbedMass_kg,"
            "block.poreVolume_m3,block.fractionFilled,block.meanSaturation,block.maxSaturation,block.wetParticles,"
            "block.wetMin_m,block.wetMax_m,block.wetHeight_m,"
            "block.centre_m,block.minPosition_m,block.maxPosition_m,block.maxDensity_kg_per_m3,"
            "object3.solidParticles,object3.absorbedParticles,object3.absorbedVolume_m3,object3.absorbedMass_kg,"
            "object3.poreVolume_m3,object3.fractionFilled,object3.meanSaturation,object3.maxSaturation,"
            "object3.wetParticles,object3.wetMin_m,object3.wetMax_m,object3.wetHeight_m,"
            "object3.centre_m,object3.minPosition_m,object3.maxPosition_m,object3.maxDensity_kg_per_m3,"
            "fluid.particles,fluid.meanDensityError_percent,fluid.maxDensityError_percent,fluid.kineticEnergy_J,"
            "fluid.momentumX_kg_m_per_s,fluid.momentumY_kg_m_per_s,fluid.momentumZ_kg_m_per_s,"
            "fluid.potentialEnergy_J,fluid.maxSpeed_m_per_s,fluid.minPosition_m,fluid.maxPosition_m,"
            "fluid.meanSpeed_m_per_s,fluid.pressureGradient_rho0g");
  const double v = 8.0 * kR * kR * kR;
  const std::string volume = CsvTable::formatNumber(10 * v), pores = CsvTable::formatNumber(0.4 * 64 * v);
  // t = 0: no saturation and no density yet, so those cells are empty.
  EXPECT_EQ(rows[1].rfind("0,0,64,10," + volume + ",", 0), 0u) << rows[1];
  // Then six empty saturation cells, the block's centre and extent, an empty density, object3's 8 particles.
  const std::size_t saturations = rows[1].find("," + pores + "," + CsvTable::formatNumber(10 / (0.4 * 64)) + ",,,,,,,");
  EXPECT_NE(saturations, std::string::npos) << rows[1];
  EXPECT_NE(rows[1].find(",,8,", saturations), std::string::npos) << rows[1];
  EXPECT_EQ(rows[2].rfind("0.5,10,64,10," + volume + ",", 0), 0u) << rows[2];
  EXPECT_NE(rows[2].find(",0.5,1,32,"), std::string::npos) << rows[2]; // mean and max saturation, wet particles
}

TEST(SaturationTables, ProfilesInLongFormat) {
  const auto rows = lines(profileTable(records()).text());
  ASSERT_EQ(rows.size(), 1u + 2 * (4 + 2)); // t = 0 has no saturation: no profile
  EXPECT_EQ(rows[0], "time_s,object,position_m,meanSaturation,particles");
  EXPECT_EQ(rows[1], "0.5,block,0.01,0,16");
  EXPECT_EQ(rows[4].rfind("0.5,block,", 0), 0u);
  EXPECT_EQ(rows[4].substr(rows[4].size() - 5), ",1,16"); // the top layer, saturation 1
  EXPECT_EQ(rows[5].rfind("0.5,object3,0.01,", 0), 0u);
  EXPECT_EQ(rows[5].substr(rows[5].size() - 2), ",4");
}

TEST(SaturationPlots, ProfileTimesAreEvenlySpreadAndEndAtTheLatest) {
  std::vector<TimeRecord> many;
  for (int k = 0; k < 11; ++k) {
    many.push_back(analyse(syntheticSystem(k > 0), syntheticSettings()));
    many.back().time = k;
  }
  EXPECT_EQ(profileTimes(many, 1), (std::vector<std::size_t>{1, 3, 5, 6, 8, 10}));
  many.resize(4);
  EXPECT_EQ(profileTimes(many, 1), (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_TRUE(profileTimes(many, 99).empty());
}

TEST(SaturationPlots, EveryPlotIsWellFormed) {
  const auto plots = saturationPlots(records(), syntheticSettings());
  std::vector<std::string> names;
  for (const auto& [name, plot] : plots) {
    names.push_back(name);
    EXPECT_TRUE(wellFormedXml(plot.svg())) << name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"absorbedVolume.svg", "fillFraction.svg", "wetFront.svg",
                                             "densityError.svg", "energy.svg", "fluidExtent.svg",
                                             "saturationProfiles_block.svg", "saturationProfiles_object3.svg"}));
  EXPECT_EQ(plots[0].second.lines(), 4u); // absorbed and pore volume of two objects
  EXPECT_EQ(plots[4].second.lines(), 3u); // kinetic, potential change, their sum
  EXPECT_EQ(plots[6].second.lines(), 2u); // profiles at 0.5 and 1
}

TEST(SaturationPlots, AFluidOnlyCaseGetsTheFluidPlotsOnly) {
  ParticleSystem ps(kR);
  addSet(ps, "fluid", SetKind::Fluid, lattice(2, Vec3::Zero()), 0);
  const auto plots = saturationPlots({analyse(ps, syntheticSettings())}, syntheticSettings());
  std::vector<std::string> names;
  for (const auto& [name, plot] : plots) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"densityError.svg", "energy.svg", "fluidExtent.svg"}));
}

TEST(SaturationReport, WritesTheFilesIntoTheDirectory) {
  ScratchDirectory dir;
  const auto files = writeSaturationReport(records(), syntheticSettings(), dir / "postProcessing" / "sa");
  ASSERT_EQ(files.size(), 10u);
  for (const auto& file : files) EXPECT_TRUE(std::filesystem::is_regular_file(file)) << file;
  EXPECT_EQ(readAll(files[0]), timeSeriesTable(records()).text());
}

} // namespace
} // namespace poro::test
