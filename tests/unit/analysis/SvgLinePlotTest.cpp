#include "analysis/SvgLinePlot.hpp"
#include "XmlCheck.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace poro::test {
namespace {

TEST(SvgLinePlot, WellFormedWithOnePolylinePerSeriesWithPoints) {
  SvgLinePlot plot("Absorbed <fluid> & more", "time [s]", "volume [m³]");
  plot.add({"block absorbed", {{0, 0}, {0.5, 0.01}, {1, 0.02}}});
  plot.add({"block pore volume φV", {{0, 0.03}, {1, 0.03}}, true, 0});
  plot.add({"single", {{0.5, 0.015}}});
  plot.add({"empty", {}});
  plot.add({"only NaN", {{NAN, 1.0}, {0.5, INFINITY}}});
  plot.includeZeroY();
  const std::string svg = plot.svg();
  EXPECT_TRUE(wellFormedXml(svg)) << svg;
  EXPECT_EQ(plot.lines(), 3u);
  EXPECT_EQ(occurrences(svg, "<polyline"), 3u);
  EXPECT_EQ(occurrences(svg, "<circle"), 1u);          // the single point is drawn as a dot
  EXPECT_EQ(occurrences(svg, "stroke-dasharray"), 2u); // the dashed line and its legend sample
  EXPECT_NE(svg.find("Absorbed &lt;fluid&gt; &amp; more"), std::string::npos);
  EXPECT_NE(svg.find(">time [s]<"), std::string::npos);
  EXPECT_NE(svg.find(">block pore volume φV<"), std::string::npos); // legend
  EXPECT_EQ(svg.find(">empty<"), std::string::npos);                // no legend entry without a line
  EXPECT_NE(svg.find(">0.030<"), std::string::npos);                // a y tick, step 0.005
}

TEST(SvgLinePlot, TheXmlCheckRejectsMalformedDocuments) {
  EXPECT_TRUE(wellFormedXml("<?xml version=\"1.0\"?>\n<svg a=\"1\"><g>x &amp; &#x3c6;</g><line/></svg>\n"));
  for (const std::string bad : {"<svg><g></svg>", "<svg a=1/>", "<svg>&</svg>", "<a/><b/>", "<svg>", "text<svg/>",
                                "<svg a=\"1\"b=\"2\"/>", "<svg a=\"<\"/>"})
    EXPECT_FALSE(wellFormedXml(bad)) << bad;
}

TEST(SvgLinePlot, WithoutDataItSaysSo) {
  SvgLinePlot plot("Nothing", "x [m]", "y [m]");
  plot.add({"empty", {}});
  const std::string svg = plot.svg();
  EXPECT_TRUE(wellFormedXml(svg)) << svg;
  EXPECT_EQ(plot.lines(), 0u);
  EXPECT_EQ(occurrences(svg, "<polyline"), 0u);
  EXPECT_NE(svg.find("no data"), std::string::npos);
}

TEST(SvgLinePlot, ConstantAndTinyRangesGiveFiniteAxes) {
  for (const double value : {0.0, 5.0, 1e-9, 1e12}) {
    SvgLinePlot plot("Constant", "t [s]", "v");
    plot.add({"flat", {{0.0, value}, {1.0, value}}});
    const std::string svg = plot.svg();
    EXPECT_TRUE(wellFormedXml(svg)) << svg;
    EXPECT_EQ(svg.find("nan"), std::string::npos) << value;
    EXPECT_EQ(svg.find("inf"), std::string::npos) << value;
    EXPECT_LT(occurrences(svg, "<text"), 40u) << value; // a handful of ticks, not thousands
  }
}

} // namespace
} // namespace poro::test
