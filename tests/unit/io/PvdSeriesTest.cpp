#include "io/PvdSeries.hpp"

#include "core/Error.hpp"
#include "ScratchDirectory.hpp"

#include <gtest/gtest.h>

namespace poro {
namespace {

using test::contains;
using test::readAll;
using test::ScratchDirectory;

PvdSeries threeTimes() {
  PvdSeries series;
  for (const char* name : {"0", "0.1", "0.2"}) {
    const double time = std::stod(name);
    series.add(time, "fluid", std::string(name) + "/fluid.vtp");
    series.add(time, "boundary", std::string(name) + "/boundary.vtp");
  }
  return series;
}

TEST(PvdSeries, WritesAParaViewCollection) {
  ScratchDirectory dir;
  threeTimes().write(dir / "case.pvd");
  const std::string text = readAll(dir / "case.pvd");
  EXPECT_TRUE(contains(text, "<VTKFile type=\"Collection\" version=\"0.1\">"));
  EXPECT_TRUE(contains(text, "<DataSet timestep=\"0\" group=\"\" part=\"0\" name=\"fluid\" file=\"0/fluid.vtp\"/>"));
  EXPECT_TRUE(
      contains(text, "<DataSet timestep=\"0\" group=\"\" part=\"1\" name=\"boundary\" file=\"0/boundary.vtp\"/>"));
  // 17 significant digits: the time reads back as the same double.
  EXPECT_TRUE(contains(text, "<DataSet timestep=\"0.10000000000000001\" group=\"\" part=\"0\" name=\"fluid\" "
                             "file=\"0.1/fluid.vtp\"/>"));
  EXPECT_TRUE(contains(text, "</Collection>\n</VTKFile>\n"));
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"case.pvd"});
}

TEST(PvdSeries, AStaticSetIsListedAtEveryTime) {
  // The boundary is written once, at 0. ParaView's reader restricts a collection to the DataSets of the
  // current timestep, so the boundary must be listed at every time, with the same part index and name.
  ScratchDirectory dir;
  PvdSeries series;
  series.add(0.0, "fluid", "0/fluid.vtp");
  series.add(0.0, "boundary", "0/boundary.vtp");
  series.add(0.0, "porous", "0/porous.vtp");
  for (const char* name : {"0.5", "1"}) {
    series.add(std::stod(name), "fluid", std::string(name) + "/fluid.vtp");
    series.add(std::stod(name), "porous", std::string(name) + "/porous.vtp");
  }
  series.write(dir / "case.pvd");
  const std::string text = readAll(dir / "case.pvd");
  EXPECT_EQ(text, "<?xml version=\"1.0\"?>\n"
                  "<VTKFile type=\"Collection\" version=\"0.1\">\n"
                  "  <Collection>\n"
                  "    <DataSet timestep=\"0\" group=\"\" part=\"0\" name=\"fluid\" file=\"0/fluid.vtp\"/>\n"
                  "    <DataSet timestep=\"0\" group=\"\" part=\"1\" name=\"boundary\" file=\"0/boundary.vtp\"/>\n"
                  "    <DataSet timestep=\"0\" group=\"\" part=\"2\" name=\"porous\" file=\"0/porous.vtp\"/>\n"
                  "    <DataSet timestep=\"0.5\" group=\"\" part=\"0\" name=\"fluid\" file=\"0.5/fluid.vtp\"/>\n"
                  "    <DataSet timestep=\"0.5\" group=\"\" part=\"1\" name=\"boundary\" file=\"0/boundary.vtp\"/>\n"
                  "    <DataSet timestep=\"0.5\" group=\"\" part=\"2\" name=\"porous\" file=\"0.5/porous.vtp\"/>\n"
                  "    <DataSet timestep=\"1\" group=\"\" part=\"0\" name=\"fluid\" file=\"1/fluid.vtp\"/>\n"
                  "    <DataSet timestep=\"1\" group=\"\" part=\"1\" name=\"boundary\" file=\"0/boundary.vtp\"/>\n"
                  "    <DataSet timestep=\"1\" group=\"\" part=\"2\" name=\"porous\" file=\"1/porous.vtp\"/>\n"
                  "  </Collection>\n"
                  "</VTKFile>\n");
  // Read back (a restart), the repetitions are not entries of their own, and the file is written the same.
  const PvdSeries read = PvdSeries::read(dir / "case.pvd");
  EXPECT_EQ(read.entries().size(), series.entries().size());
  read.write(dir / "again.pvd");
  EXPECT_EQ(readAll(dir / "again.pvd"), text);
  // Purging time 0 removes the boundary's file, so it is listed nowhere.
  PvdSeries purged = read;
  purged.removeTime("0");
  purged.write(dir / "purged.pvd");
  EXPECT_FALSE(contains(readAll(dir / "purged.pvd"), "boundary"));
}

TEST(PvdSeries, WallsOfALaterTimeDoNotHideTheStaticOnesBeforeIt) {
  // A case run to 0.2, decomposed there and reconstructed: 0.2/ holds walls of its own (each subdomain needs them),
  // the times between hold none. They show 0/'s walls, and 0.2 and later their own.
  ScratchDirectory dir;
  PvdSeries series;
  series.add(0.0, "boundary", "0/boundary.vtp");
  for (const char* name : {"0", "0.1", "0.2", "0.3"})
    series.add(std::stod(name), "fluid", std::string(name) + "/fluid.vtp");
  series.add(0.2, "boundary", "0.2/boundary.vtp");
  series.write(dir / "case.pvd");
  const std::string text = readAll(dir / "case.pvd");
  EXPECT_TRUE(contains(text, "timestep=\"0.10000000000000001\" group=\"\" part=\"0\" name=\"boundary\" "
                             "file=\"0/boundary.vtp\""))
      << text;
  EXPECT_TRUE(contains(text, "timestep=\"0.20000000000000001\" group=\"\" part=\"0\" name=\"boundary\" "
                             "file=\"0.2/boundary.vtp\""))
      << text;
  EXPECT_TRUE(contains(text, "timestep=\"0.29999999999999999\" group=\"\" part=\"0\" name=\"boundary\" "
                             "file=\"0.2/boundary.vtp\""))
      << text;
  PvdSeries::read(dir / "case.pvd").write(dir / "again.pvd");
  EXPECT_EQ(readAll(dir / "again.pvd"), text);
}

TEST(PvdSeries, ASurfaceOfSomeTimesIsListedOnlyThere) {
  // fluidSurface run with -time 0.5 (or before the run went on): a surface must not stand in for later times.
  ScratchDirectory dir;
  PvdSeries series;
  series.add(0.0, "boundary", "0/boundary.vtp");
  for (const char* name : {"0", "0.5", "1"}) series.add(std::stod(name), "fluid", std::string(name) + "/fluid.vtp");
  series.add(0.5, "fluidSurface", "0.5/fluidSurface.vtp");
  series.write(dir / "case.pvd");
  const std::string text = readAll(dir / "case.pvd");
  EXPECT_TRUE(contains(text, "timestep=\"0.5\" group=\"\" part=\"2\" name=\"fluidSurface\""));
  EXPECT_FALSE(contains(text, "timestep=\"1\" group=\"\" part=\"2\""));
  EXPECT_TRUE(contains(text, "timestep=\"1\" group=\"\" part=\"0\" name=\"boundary\" file=\"0/boundary.vtp\""));
  // Read back and written again (a restart of the solver): still only at 0.5.
  PvdSeries::read(dir / "case.pvd").write(dir / "again.pvd");
  EXPECT_EQ(readAll(dir / "again.pvd"), text);
}

TEST(PvdSeries, ASurfaceAtTheFirstTimeIsNotStatic) {
  // fluidSurface -time 0: the surface of the start has one file, at the series' first time, like the walls; it
  // must not stand in for the fluid's surface at every later time.
  ScratchDirectory dir;
  PvdSeries series;
  series.add(0.0, "boundary", "0/boundary.vtp");
  for (const char* name : {"0", "0.5", "1"}) series.add(std::stod(name), "fluid", std::string(name) + "/fluid.vtp");
  series.add(0.0, "fluidSurface", "0/fluidSurface.vtp");
  series.add(0.0, "porousSurface", "0/porousSurface.vtp");
  series.write(dir / "case.pvd");
  const std::string text = readAll(dir / "case.pvd");
  EXPECT_TRUE(contains(text, "timestep=\"0\" group=\"\" part=\"2\" name=\"fluidSurface\""));
  EXPECT_TRUE(contains(text, "timestep=\"0\" group=\"\" part=\"3\" name=\"porousSurface\""));
  for (const char* later : {"0.5", "1"}) {
    EXPECT_FALSE(contains(text, "timestep=\"" + std::string(later) + "\" group=\"\" part=\"2\"")) << later;
    EXPECT_FALSE(contains(text, "timestep=\"" + std::string(later) + "\" group=\"\" part=\"3\"")) << later;
    EXPECT_TRUE(contains(text, "timestep=\"" + std::string(later) +
                                   "\" group=\"\" part=\"0\" name=\"boundary\" file=\"0/boundary.vtp\""))
        << later;
  }
  PvdSeries::read(dir / "case.pvd").write(dir / "again.pvd");
  EXPECT_EQ(readAll(dir / "again.pvd"), text);
}

TEST(PvdSeries, ReadReturnsWhatWasWritten) {
  ScratchDirectory dir;
  PvdSeries written = threeTimes();
  written.add(1.0 / 3.0, "porous", "0.33333333333333331/porous.vtp");
  written.add(2.5e-7, "fluid", "2.5e-07/fluid & more.vtp");
  written.write(dir / "case.pvd");

  const PvdSeries read = PvdSeries::read(dir / "case.pvd");
  ASSERT_EQ(read.entries().size(), written.entries().size());
  for (std::size_t k = 0; k < read.entries().size(); ++k) {
    const auto& a = written.entries()[k];
    const auto& b = read.entries()[k];
    EXPECT_EQ(a.time, b.time) << k;
    EXPECT_EQ(a.file, b.file) << k;
  }
  EXPECT_EQ(read.entries()[1].part, "boundary");
  EXPECT_EQ(read.entries()[6].part, "porous");
  EXPECT_EQ(read.entries()[7].part, "fluid & more"); // the stem of the file name

  // Written again, the file is the same: a restart keeps earlier entries unchanged.
  PvdSeries renamed;
  for (const auto& e : read.entries()) renamed.add(e.time, e.part == "fluid & more" ? "fluid" : e.part, e.file);
  renamed.write(dir / "again.pvd");
  EXPECT_EQ(readAll(dir / "again.pvd"), readAll(dir / "case.pvd"));
}

TEST(PvdSeries, AddReplacesTheSameTimeAndPart) {
  PvdSeries series = threeTimes();
  series.add(0.1, "fluid", "0.1/fluid2.vtp");
  ASSERT_EQ(series.entries().size(), 6u);
  EXPECT_EQ(series.entries()[2].file, "0.1/fluid2.vtp");
}

TEST(PvdSeries, RemoveTimesAfter) {
  PvdSeries series = threeTimes();
  series.removeTimesAfter(0.1);
  ASSERT_EQ(series.entries().size(), 4u);
  EXPECT_EQ(series.entries().back().file, "0.1/boundary.vtp");
  series.removeTimesAfter(-1.0);
  EXPECT_TRUE(series.empty());
}

TEST(PvdSeries, RemoveTimeByValueAndByName) {
  PvdSeries series = threeTimes();
  series.removeTime(0.1);
  ASSERT_EQ(series.entries().size(), 4u);
  series.removeTime("0");
  ASSERT_EQ(series.entries().size(), 2u);
  EXPECT_EQ(series.entries()[0].file, "0.2/fluid.vtp");
  series.removeTime("0.3"); // absent: nothing happens
  EXPECT_EQ(series.entries().size(), 2u);
}

TEST(PvdSeries, ReadsParaViewStyleFile) {
  ScratchDirectory dir;
  test::writeAll(dir / "pv.pvd", R"(<?xml version="1.0"?>
<VTKFile type="Collection" version="0.1" byte_order="LittleEndian" compressor="vtkZLibDataCompressor">
  <Collection>
    <DataSet timestep="0" group="" part="0"
             file='case_0/fluid_0.vtp'/>
    <DataSet timestep="1.5e-3" part="0" file="case_1/fluid_0.vtp"></DataSet>
  </Collection>
</VTKFile>
)");
  const PvdSeries series = PvdSeries::read(dir / "pv.pvd");
  ASSERT_EQ(series.entries().size(), 2u);
  EXPECT_EQ(series.entries()[0].file, "case_0/fluid_0.vtp");
  EXPECT_EQ(series.entries()[1].time, 1.5e-3);
  EXPECT_EQ(series.entries()[1].part, "fluid_0");
}

TEST(PvdSeries, ReadErrorsNameFileAndLine) {
  ScratchDirectory dir;
  EXPECT_THROW(PvdSeries::read(dir / "missing.pvd"), InputError);

  test::writeAll(dir / "notPvd.pvd", "<VTKFile type=\"PolyData\">\n</VTKFile>\n");
  EXPECT_THROW(PvdSeries::read(dir / "notPvd.pvd"), InputError);

  test::writeAll(dir / "garbage.pvd", "hello\x01");
  EXPECT_THROW(PvdSeries::read(dir / "garbage.pvd"), InputError);

  test::writeAll(dir / "badTime.pvd", "<VTKFile type=\"Collection\">\n<Collection>\n"
                                      "<DataSet timestep=\"0.1x\" file=\"a.vtp\"/>\n");
  try {
    PvdSeries::read(dir / "badTime.pvd");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), (dir / "badTime.pvd").string() + ":3: "));
    EXPECT_TRUE(contains(e.what(), "0.1x"));
  }

  test::writeAll(dir / "noFile.pvd", "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"1\"/>");
  EXPECT_THROW(PvdSeries::read(dir / "noFile.pvd"), InputError);
}

TEST(PvdSeries, WriteIntoMissingDirectoryIsAnOutputError) {
  ScratchDirectory dir;
  EXPECT_THROW(threeTimes().write(dir / "missing" / "case.pvd"), OutputError);
}

} // namespace
} // namespace poro
