// Which names saturationAnalysis gives a time directory's porous objects.

#include "analysis/AnalysisSettings.hpp"
#include "../io/ScratchDirectory.hpp"

#include <gtest/gtest.h>

namespace poro::test {
namespace {

TEST(SampledRegionNames, ATimeIsNamedAsItWasSampledNotAsParticleDictReadsNow) {
  // A fluid region inserted at the top of particleDict after the run: objectId 1 is still the block that was
  // sampled as region 1, not the region now listed second.
  ScratchDirectory dir;
  for (const char* time : {"0.5", "2"}) std::filesystem::create_directories(dir / time / "uniform");
  writeAll(dir / "0.5/uniform/sampling", "regions:\n"
                                         "  - {name: column, phase: fluid, shape: box}\n"
                                         "  - {name: block, phase: porous, shape: box}\n"
                                         "porousMaterials: []\n");
  const std::vector<std::string> now{"drop", "column", "block"};
  EXPECT_EQ(sampledRegionNames(dir / "0.5", now), (std::vector<std::string>{"column", "block"}));
  // Written before the record existed, or unreadable: particleDict's names.
  EXPECT_EQ(sampledRegionNames(dir / "1", now), now);
  writeAll(dir / "2/uniform/sampling", "regions: [\n");
  EXPECT_EQ(sampledRegionNames(dir / "2", now), now);
}

} // namespace
} // namespace poro::test
