#include "roomscout/plots/bar_chart.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "plot_test_support.hpp"
#include "recording_canvas.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::plots {
namespace {

using test::record;
using test::RecordingCanvas;

TEST(BarChart, OneBarPerValueWithNamesAndValues) {
  const BarChart chart = test::exampleBarChart();
  const Figure figure = renderBarChart(chart);
  const RecordingCanvas drawn = record(figure);
  EXPECT_EQ(drawn.count("bar"), 8u);  // 3 x 3, one NaN
  for (const std::string& c : chart.categories) EXPECT_TRUE(drawn.hasText(c)) << c;
  for (const BarSeries& s : chart.series) EXPECT_TRUE(drawn.hasText(s.name)) << s.name;
  EXPECT_TRUE(drawn.hasText("15"));  // a value label
  EXPECT_EQ(drawn.count("legend-swatch"), 3u);
  EXPECT_EQ(drawn.clip_depth, 0);
  EXPECT_EQ(renderImage(figure).size(), cv::Size(640, 360));
  EXPECT_TRUE(test::TagsBalanced(renderSvg(figure)));
}

TEST(BarChart, BarHeightsAreProportionalToTheValues) {
  BarChart chart;
  chart.categories = {"a", "b"};
  chart.series = {{"s", {2.0, 4.0}, {}}};
  const std::vector<RecordingCanvas::Fill> bars = record(renderBarChart(chart)).fillsOf("bar");
  ASSERT_EQ(bars.size(), 2u);
  EXPECT_NEAR(bars[1].rect.height, 2.0 * bars[0].rect.height, 0.05);
  EXPECT_NEAR(bars[0].rect.br().y, bars[1].rect.br().y, 0.05);  // both stand on zero
  EXPECT_EQ(bars[0].color, paletteColor(0));
}

TEST(BarChart, PngShowsEverySeriesColour) {
  const cv::Mat image = renderImage(renderBarChart(test::exampleBarChart()));
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_GT(test::pixelsNear(image, paletteColor(k), 2), 200) << "series " << k;
  }
}

TEST(BarChart, RejectsSeriesOfTheWrongLength) {
  BarChart chart = test::exampleBarChart();
  chart.series[1].values.pop_back();
  EXPECT_THROW(renderBarChart(chart), InvalidArgument);
}

TEST(BarChart, WritesEveryFile) {
  test::TempDir dir;
  const FigureFiles files = writeFigure(renderBarChart(test::exampleBarChart()), dir / "revisits");
  EXPECT_TRUE(std::filesystem::is_regular_file(files.png));
  EXPECT_TRUE(std::filesystem::is_regular_file(files.svg));
  EXPECT_TRUE(std::filesystem::is_regular_file(files.pdf));
  const cv::Mat png = cv::imread(files.png.string());
  EXPECT_EQ(png.size(), cv::Size(640, 360));
}

}  // namespace
}  // namespace roomscout::plots
