#include "roomscout/plots/line_chart.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "plot_test_support.hpp"
#include "recording_canvas.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"

namespace roomscout::plots {
namespace {

using test::record;
using test::RecordingCanvas;
using test::TagsBalanced;

TEST(LineChart, WritesPngOfTheRequestedSizeSvgAndPdf) {
  test::TempDir dir;
  const Figure figure = renderLineChart(test::exampleLineChart());
  const FigureFiles files = writeFigure(figure, dir / "fig5_small_house");
  EXPECT_EQ(files.png, dir / "fig5_small_house.png");
  EXPECT_EQ(files.svg, dir / "fig5_small_house.svg");
  EXPECT_EQ(files.pdf, dir / "fig5_small_house.pdf");
  const cv::Mat png = cv::imread(files.png.string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(png.empty());
  EXPECT_EQ(png.cols, 720);
  EXPECT_EQ(png.rows, 420);
  EXPECT_EQ(png.type(), CV_8UC3);
  EXPECT_EQ(io::readFile(files.png), renderPng(figure));
  EXPECT_EQ(io::readFile(files.svg), renderSvg(figure));
  EXPECT_EQ(io::readFile(files.pdf), renderPdf(figure));
  // Only the three files: no temporary left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            3);
}

TEST(LineChart, DrawsOnePolylinePerSeriesTheLegendAndTheReferenceLine) {
  const LineChart chart = test::exampleLineChart();
  const RecordingCanvas drawn = record(renderLineChart(chart));
  EXPECT_EQ(drawn.count("series"), 3u);
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    EXPECT_TRUE(drawn.hasText(chart.series[k].name)) << chart.series[k].name;
    EXPECT_EQ(drawn.polylinesOf("series")[k].stroke.color, paletteColor(k));
    EXPECT_EQ(drawn.polylinesOf("series")[k].points.size(), 41u);
  }
  EXPECT_EQ(drawn.count("reference"), 1u);
  EXPECT_EQ(drawn.count("legend-swatch"), 4u);  // three series and the reference line
  EXPECT_TRUE(drawn.hasText("98 %"));
  EXPECT_TRUE(drawn.hasText(chart.title));
  EXPECT_TRUE(drawn.hasText(chart.x_label));
  ASSERT_TRUE(drawn.hasText(chart.y_label));
  EXPECT_TRUE(drawn.findText(chart.y_label)->style.vertical);
  EXPECT_TRUE(drawn.hasText("100"));  // a y tick
  // The 98 % line lies just under the top of the 0..100 axis.
  const std::vector<RecordingCanvas::Line> grid = drawn.linesOf("grid");
  ASSERT_FALSE(grid.empty());
  double top = grid.front().a.y;
  for (const RecordingCanvas::Line& l : grid) {
    if (l.a.y == l.b.y) top = std::min(top, l.a.y);
  }
  const double ref_y = drawn.linesOf("reference").at(0).a.y;
  EXPECT_GT(ref_y, top);
  EXPECT_LT(ref_y, top + 15.0);
}

TEST(LineChart, PngShowsEverySeriesColour) {
  const cv::Mat image = renderImage(renderLineChart(test::exampleLineChart()));
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_GT(test::pixelsNear(image, paletteColor(k)), 150) << "series " << k;
  }
}

TEST(LineChart, KeepsTextAsGivenAndSkipsNonFinitePoints) {
  LineChart chart;
  chart.title = "a < b & c: 12 m², café";
  chart.series.push_back({"x<y>", {{0, 0}, {1, NAN}, {2, 2}}, Rgb{1, 2, 3}, false});
  chart.series.push_back({"single", {{1, 1}}, {}, false});
  const Figure figure = renderLineChart(chart);
  const RecordingCanvas drawn = record(figure);
  EXPECT_TRUE(drawn.hasText("a < b & c: 12 m², café"));
  EXPECT_TRUE(drawn.hasText("x<y>"));
  ASSERT_EQ(drawn.count("series"), 1u);  // a single point is a dot, not a line
  const RecordingCanvas::Polyline line = drawn.polylinesOf("series").front();
  EXPECT_EQ(line.points.size(), 2u);
  EXPECT_EQ(line.stroke.color, (Rgb{1, 2, 3}));
  ASSERT_EQ(drawn.circles.size(), 1u);
  EXPECT_EQ(drawn.circles[0].color, paletteColor(1));
  EXPECT_TRUE(TagsBalanced(renderSvg(figure)));
}

TEST(LineChart, FixedRangesClipTheData) {
  LineChart chart = test::exampleLineChart();
  chart.x_max = 50.0;
  const Figure figure = renderLineChart(chart);
  const RecordingCanvas drawn = record(figure);
  EXPECT_TRUE(drawn.hasText("50"));
  EXPECT_FALSE(drawn.hasText("200"));  // the data's own x range
  ASSERT_EQ(drawn.clips.size(), 1u);
  EXPECT_EQ(drawn.clip_depth, 0);
  const cv::Rect2d clip = drawn.clips[0];
  // The curves run on to x = 200, far right of the clip; the rendering cuts them at its edge
  // (the legend, in the same colours, starts further right).
  EXPECT_GT(drawn.polylinesOf("series")[0].points.back().x, clip.x + clip.width + 100);
  const double legend_x = drawn.linesOf("legend-swatch").at(0).a.x;
  const cv::Mat image = renderImage(figure);
  const int x0 = static_cast<int>(std::ceil(clip.x + clip.width)) + 1;
  const int x1 = static_cast<int>(std::floor(legend_x)) - 1;
  ASSERT_GT(x1, x0);
  const cv::Mat gap = image(cv::Range(0, image.rows), cv::Range(x0, x1));
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(test::pixelsNear(gap, paletteColor(k), 40), 0);
  EXPECT_GT(test::pixelsNear(image, paletteColor(0)), 100);
}

TEST(LineChart, EmptyChartStillRenders) {
  LineChart chart;
  chart.size = {200, 100};
  const Figure figure = renderLineChart(chart);
  EXPECT_EQ(renderImage(figure).size(), cv::Size(200, 100));
  EXPECT_TRUE(TagsBalanced(renderSvg(figure)));
  EXPECT_EQ(record(figure).count("series"), 0u);
}

TEST(LineChart, RejectsAnEmptyFigureSize) {
  LineChart chart = test::exampleLineChart();
  chart.size = {0, 100};
  EXPECT_THROW(renderLineChart(chart), InvalidArgument);
}

}  // namespace
}  // namespace roomscout::plots
