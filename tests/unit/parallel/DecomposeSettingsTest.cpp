// system/decomposeParDict: defaults, every key read, and errors that name the file, line and key.

#include "parallel/DecomposeSettings.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace poro {
namespace {

namespace fs = std::filesystem;

class DecomposeSettingsTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("porosph_decomposeParDict_" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "system");
  }
  void TearDown() override { fs::remove_all(dir_); }
  DecomposeSettings read(const std::string& text) {
    std::ofstream(dir_ / "system" / "decomposeParDict") << text;
    return readDecomposeSettings(dir_);
  }
  std::string error(const std::string& text) {
    try {
      read(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  fs::path dir_;
};

TEST_F(DecomposeSettingsTest, ReadsEveryKeyWithDefaults) {
  const DecomposeSettings d = read("numberOfSubdomains: 4\n");
  EXPECT_EQ(d.subdomains, 4);
  EXPECT_EQ(d.method, PartitionMethod::RecursiveBisection);
  EXPECT_EQ(d.fluidWeight, 1.0);
  EXPECT_EQ(d.porousWeight, 1.75);
  EXPECT_EQ(d.boundaryWeight, 0.05);
  EXPECT_EQ(d.rebalanceThreshold, 0.1);
  const DecomposeSettings e =
      read("numberOfSubdomains: 2\nmethod: hilbertCurve\nweights: {fluid: 1.5, porous: 3, boundary: 0.5}\n"
           "rebalanceThreshold: 0.25\n");
  EXPECT_EQ(e.method, PartitionMethod::HilbertCurve);
  EXPECT_EQ(e.fluidWeight, 1.5);
  EXPECT_EQ(e.porousWeight, 3.0);
  EXPECT_EQ(e.boundaryWeight, 0.5);
  EXPECT_EQ(e.rebalanceThreshold, 0.25);
}

TEST_F(DecomposeSettingsTest, BadValuesNameFileLineAndKey) {
  std::string m = error("method: hilbertCurve\nnumberOfSubdomains: 0\n");
  EXPECT_NE(m.find("decomposeParDict:2"), std::string::npos) << m;
  EXPECT_NE(m.find("numberOfSubdomains"), std::string::npos) << m;
  m = error("numberOfSubdomains: 2\nmethod: scotch\n");
  EXPECT_NE(m.find("method"), std::string::npos) << m;
  EXPECT_NE(m.find("recursiveBisection"), std::string::npos) << m;
  m = error("numberOfSubdomains: 2\nweights: {fluid: 0}\n");
  EXPECT_NE(m.find("fluid"), std::string::npos) << m;
  m = error("numberOfSubdomains: 2\nweights: {solid: 1}\n");
  EXPECT_NE(m.find("solid"), std::string::npos) << m;
  m = error("numberOfSubdomain: 2\n");
  EXPECT_NE(m.find("numberOfSubdomains"), std::string::npos) << m;
  fs::remove(dir_ / "system" / "decomposeParDict");
  EXPECT_THROW(readDecomposeSettings(dir_), InputError);
}

} // namespace
} // namespace poro
