#include "roomscout/plots/line_chart.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "plot_test_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"

namespace roomscout::plots {
namespace {

using test::count;
using test::TagsBalanced;

TEST(LineChart, WritesPngOfTheRequestedSizeAndSvg) {
  test::TempDir dir;
  const Figure figure = renderLineChart(test::exampleLineChart());
  const FigureFiles files = writeFigure(figure, dir / "fig5_small_house");
  EXPECT_EQ(files.png, dir / "fig5_small_house.png");
  EXPECT_EQ(files.svg, dir / "fig5_small_house.svg");
  const cv::Mat png = cv::imread(files.png.string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(png.empty());
  EXPECT_EQ(png.cols, 720);
  EXPECT_EQ(png.rows, 420);
  EXPECT_EQ(png.type(), CV_8UC3);
  EXPECT_EQ(io::readFile(files.svg), figure.svg);
  // Only the two files: no temporary left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            2);
}

TEST(LineChart, SvgHasOnePolylinePerSeriesTheLegendAndTheReferenceLine) {
  const LineChart chart = test::exampleLineChart();
  const std::string svg = renderLineChart(chart).svg;
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_TRUE(TagsBalanced(svg));
  EXPECT_NE(svg.find("width=\"720\" height=\"420\""), std::string::npos);
  EXPECT_EQ(count(svg, "<polyline"), 3u);
  EXPECT_EQ(count(svg, "class=\"series\""), 3u);
  for (const LineSeries& s : chart.series) {
    EXPECT_NE(svg.find(">" + s.name + "</text>"), std::string::npos) << s.name;
  }
  EXPECT_EQ(count(svg, "class=\"reference\""), 1u);
  EXPECT_NE(svg.find(">98 %</text>"), std::string::npos);
  EXPECT_NE(svg.find(">" + chart.title + "</text>"), std::string::npos);
  EXPECT_NE(svg.find(">" + chart.x_label + "</text>"), std::string::npos);
  EXPECT_NE(svg.find("rotate(-90"), std::string::npos);   // the vertical y label
  EXPECT_NE(svg.find(">100</text>"), std::string::npos);  // a y tick
  // The 98 % line lies just under the top of the 0..100 axis.
  const std::vector<double> grid_y = test::attributeValues(svg, "class=\"grid\"", "y1");
  const std::vector<double> ref_y = test::attributeValues(svg, "class=\"reference\"", "y1");
  ASSERT_EQ(ref_y.size(), 1u);
  ASSERT_FALSE(grid_y.empty());
  const double top = *std::min_element(grid_y.begin(), grid_y.end());
  EXPECT_GT(ref_y[0], top);
  EXPECT_LT(ref_y[0], top + 15.0);
}

TEST(LineChart, PngShowsEverySeriesColour) {
  const Figure figure = renderLineChart(test::exampleLineChart());
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_GT(test::pixelsNear(figure.image, paletteColor(k)), 150) << "series " << k;
  }
}

TEST(LineChart, EscapesTextAndSkipsNonFinitePoints) {
  LineChart chart;
  chart.title = "a < b & c";
  chart.series.push_back({"x<y>", {{0, 0}, {1, NAN}, {2, 2}}, Rgb{1, 2, 3}, false});
  chart.series.push_back({"single", {{1, 1}}, {}, false});
  const Figure figure = renderLineChart(chart);
  EXPECT_TRUE(TagsBalanced(figure.svg));
  EXPECT_NE(figure.svg.find("a &lt; b &amp; c"), std::string::npos);
  EXPECT_NE(figure.svg.find("x&lt;y&gt;"), std::string::npos);
  EXPECT_EQ(count(figure.svg, "<polyline"), 1u);  // a single point is a dot, not a line
  EXPECT_NE(figure.svg.find("stroke=\"#010203\""), std::string::npos);
}

TEST(LineChart, FixedRangesClipTheData) {
  LineChart chart = test::exampleLineChart();
  chart.x_max = 50.0;
  const Figure figure = renderLineChart(chart);
  EXPECT_TRUE(TagsBalanced(figure.svg));
  EXPECT_NE(figure.svg.find("overflow=\"hidden\""), std::string::npos);
  EXPECT_NE(figure.svg.find(">50</text>"), std::string::npos);
  EXPECT_EQ(figure.svg.find(">200</text>"), std::string::npos);  // the data's own x range
}

TEST(LineChart, EmptyChartStillRenders) {
  LineChart chart;
  chart.size = {200, 100};
  const Figure figure = renderLineChart(chart);
  EXPECT_EQ(figure.image.cols, 200);
  EXPECT_EQ(figure.image.rows, 100);
  EXPECT_TRUE(TagsBalanced(figure.svg));
}

TEST(LineChart, RejectsAnEmptyFigureSize) {
  LineChart chart = test::exampleLineChart();
  chart.size = {0, 100};
  EXPECT_THROW(renderLineChart(chart), InvalidArgument);
}

}  // namespace
}  // namespace roomscout::plots
