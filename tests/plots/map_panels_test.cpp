#include "roomscout/plots/map_panels.hpp"

#include <gtest/gtest.h>

#include "plot_test_support.hpp"
#include "recording_canvas.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::plots {
namespace {

using test::count;
using test::record;
using test::RecordingCanvas;

TEST(MapPanels, EveryPanelHasItsImageTitleAndTrack) {
  const MapPanelFigure spec = test::exampleMapPanels();
  const Figure figure = renderMapPanels(spec);
  const RecordingCanvas drawn = record(figure);
  EXPECT_EQ(drawn.images.size(), 4u);
  EXPECT_EQ(drawn.count("track"), 4u);
  for (const MapPanel& p : spec.panels) EXPECT_TRUE(drawn.hasText(p.title)) << p.title;
  EXPECT_TRUE(drawn.hasText("Trajectories"));
  EXPECT_EQ(drawn.clip_depth, 0);
  // The SVG embeds each image as PNG data.
  const std::string svg = renderSvg(figure);
  EXPECT_TRUE(test::TagsBalanced(svg));
  EXPECT_EQ(count(svg, "<image "), 4u);
  EXPECT_EQ(count(svg, "data:image/png;base64,"), 4u);
  // Tracks in the trajectory blue, start and end dots.
  const cv::Mat image = renderImage(figure);
  EXPECT_EQ(image.size(), cv::Size(800, 640));
  EXPECT_GT(test::pixelsNear(image, colors::kTrajectory, 30), 200);
  EXPECT_GT(test::pixelsNear(image, colors::kStart, 30), 4 * 10);
  EXPECT_GT(test::pixelsNear(image, colors::kEnd, 30), 4 * 10);
}

TEST(MapPanels, ImagesKeepTheirAspectRatioInTwoRows) {
  const MapPanelFigure spec = test::exampleMapPanels();
  const RecordingCanvas drawn = record(renderMapPanels(spec));
  ASSERT_EQ(drawn.images.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const cv::Rect2d r = drawn.images[k].rect;
    const double aspect =
        static_cast<double>(spec.panels[k].image.cols) / spec.panels[k].image.rows;
    EXPECT_NEAR(r.width / r.height, aspect, 0.01) << k;
    EXPECT_LE(r.width, 800.0 / 2);
  }
  const auto y = [&](std::size_t k) { return drawn.images[k].rect.y; };
  EXPECT_DOUBLE_EQ(y(0), y(1));  // first row
  EXPECT_DOUBLE_EQ(y(2), y(3));  // second row
  EXPECT_GT(y(2), y(0) + drawn.images[0].rect.height);
}

TEST(MapPanels, EnlargedImagesStayCrisp) {
  // A 4 x 2 checkerboard drawn about 100 times as large: nearest-neighbour keeps two colours
  // only inside the drawn image, in the PNG; the SVG embeds it at the drawn size.
  MapPanelFigure spec;
  spec.size = {420, 260};
  cv::Mat board(2, 4, CV_8UC3);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) {
      board.at<cv::Vec3b>(y, x) = (x + y) % 2 ? cv::Vec3b(0, 0, 0) : cv::Vec3b(60, 200, 250);
    }
  }
  spec.panels.push_back({"", board, {}});
  const Figure figure = renderMapPanels(spec);
  const cv::Rect2d rect = record(figure).images.at(0).rect;
  EXPECT_GT(rect.width, 300.0);
  const cv::Mat image = renderImage(figure);
  const cv::Rect inner(static_cast<int>(std::ceil(rect.x)) + 2,
                       static_cast<int>(std::ceil(rect.y)) + 2, static_cast<int>(rect.width) - 4,
                       static_cast<int>(rect.height) - 4);
  const cv::Mat drawn = image(inner);
  const int yellow = test::pixelsNear(drawn, Rgb{250, 200, 60}, 0);
  const int black = test::pixelsNear(drawn, colors::kBlack, 0);
  EXPECT_EQ(yellow + black, inner.area());
  EXPECT_NEAR(yellow, inner.area() / 2, inner.area() / 20);
  const std::string svg = renderSvg(figure);
  const std::vector<double> widths = test::attributeValues(svg, "<image ", "width");
  ASSERT_EQ(widths.size(), 1u);
  EXPECT_EQ(widths[0], std::round(rect.width));
}

TEST(MapPanels, OneRowByDefaultAndPanelsWithoutTracks) {
  MapPanelFigure spec;
  spec.size = {900, 300};
  for (const char* title : {"occupancy", "point cloud", "topological", "semantic"}) {
    spec.panels.push_back({title, test::exampleMap(200, 150), {}});
  }
  const Figure figure = renderMapPanels(spec);
  const RecordingCanvas drawn = record(figure);
  ASSERT_EQ(drawn.images.size(), 4u);
  EXPECT_EQ(drawn.polylines.size(), 0u);
  for (const RecordingCanvas::Image& im : drawn.images) {
    EXPECT_DOUBLE_EQ(im.rect.y, drawn.images[0].rect.y);
  }
  EXPECT_EQ(renderImage(figure).size(), cv::Size(900, 300));
}

TEST(MapPanels, GridImagePointFlipsRowsNorthUp) {
  const GridGeometry grid({-1.0, 2.0}, 0.05, 200, 100);
  const cv::Point2d p = gridImagePoint(grid, {-1.0 + 0.025, 2.0 + 0.025});
  EXPECT_NEAR(p.x, 0.5, 1e-9);
  EXPECT_NEAR(p.y, 99.5, 1e-9);  // bottom-left cell of the grid = last image row
  const std::vector<cv::Point2d> ps = gridImagePoints(grid, {{9.0, 7.0}});
  ASSERT_EQ(ps.size(), 1u);
  EXPECT_NEAR(ps[0].x, 200.0, 1e-9);
  EXPECT_NEAR(ps[0].y, 0.0, 1e-9);
}

TEST(MapPanels, RejectsNegativeColumns) {
  MapPanelFigure spec = test::exampleMapPanels();
  spec.columns = -1;
  EXPECT_THROW(renderMapPanels(spec), InvalidArgument);
}

}  // namespace
}  // namespace roomscout::plots
