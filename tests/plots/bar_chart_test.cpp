#include "roomscout/plots/bar_chart.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "plot_test_support.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::plots {
namespace {

using test::count;

TEST(BarChart, OneRectPerValueWithNamesAndValues) {
  const BarChart chart = test::exampleBarChart();
  const Figure figure = renderBarChart(chart);
  EXPECT_TRUE(test::TagsBalanced(figure.svg));
  EXPECT_EQ(count(figure.svg, "class=\"bar\""), 8u);  // 3 x 3, one NaN
  for (const std::string& c : chart.categories) {
    EXPECT_NE(figure.svg.find(">" + c + "</text>"), std::string::npos) << c;
  }
  for (const BarSeries& s : chart.series) {
    EXPECT_NE(figure.svg.find(">" + s.name + "</text>"), std::string::npos) << s.name;
  }
  EXPECT_NE(figure.svg.find(">15</text>"), std::string::npos);  // a value label
  EXPECT_EQ(figure.image.cols, 640);
  EXPECT_EQ(figure.image.rows, 360);
}

TEST(BarChart, BarHeightsAreProportionalToTheValues) {
  BarChart chart;
  chart.categories = {"a", "b"};
  chart.series = {{"s", {2.0, 4.0}, {}}};
  const std::string svg = renderBarChart(chart).svg;
  const std::vector<double> heights = test::attributeValues(svg, "class=\"bar\"", "height");
  ASSERT_EQ(heights.size(), 2u);
  EXPECT_NEAR(heights[1], 2.0 * heights[0], 0.05);
  const std::vector<double> tops = test::attributeValues(svg, "class=\"bar\"", "y");
  EXPECT_NEAR(tops[0] + heights[0], tops[1] + heights[1], 0.05);  // both stand on zero
}

TEST(BarChart, PngShowsEverySeriesColour) {
  const Figure figure = renderBarChart(test::exampleBarChart());
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_GT(test::pixelsNear(figure.image, paletteColor(k), 2), 200) << "series " << k;
  }
}

TEST(BarChart, RejectsSeriesOfTheWrongLength) {
  BarChart chart = test::exampleBarChart();
  chart.series[1].values.pop_back();
  EXPECT_THROW(renderBarChart(chart), InvalidArgument);
}

TEST(BarChart, WritesBothFiles) {
  test::TempDir dir;
  const FigureFiles files = writeFigure(renderBarChart(test::exampleBarChart()), dir / "revisits");
  EXPECT_TRUE(std::filesystem::is_regular_file(files.png));
  EXPECT_TRUE(std::filesystem::is_regular_file(files.svg));
  const cv::Mat png = cv::imread(files.png.string());
  EXPECT_EQ(png.size(), cv::Size(640, 360));
}

}  // namespace
}  // namespace roomscout::plots
