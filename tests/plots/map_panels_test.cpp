#include "roomscout/plots/map_panels.hpp"

#include <gtest/gtest.h>

#include "plot_test_support.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::plots {
namespace {

using test::count;

TEST(MapPanels, EveryPanelHasItsImageTitleAndTrack) {
  const MapPanelFigure spec = test::exampleMapPanels();
  const Figure figure = renderMapPanels(spec);
  EXPECT_EQ(figure.image.cols, 800);
  EXPECT_EQ(figure.image.rows, 640);
  EXPECT_TRUE(test::TagsBalanced(figure.svg));
  EXPECT_EQ(count(figure.svg, "<image "), 4u);
  EXPECT_EQ(count(figure.svg, "data:image/png;base64,"), 4u);
  EXPECT_EQ(count(figure.svg, "class=\"track\""), 4u);
  for (const MapPanel& p : spec.panels) {
    EXPECT_NE(figure.svg.find(">" + p.title + "</text>"), std::string::npos) << p.title;
  }
  EXPECT_NE(figure.svg.find(">Trajectories</text>"), std::string::npos);
  // Tracks in the trajectory blue, start and end dots.
  EXPECT_GT(test::pixelsNear(figure.image, colors::kTrajectory, 30), 200);
  EXPECT_GT(test::pixelsNear(figure.image, colors::kStart, 30), 4 * 10);
  EXPECT_GT(test::pixelsNear(figure.image, colors::kEnd, 30), 4 * 10);
}

TEST(MapPanels, ImagesKeepTheirAspectRatioInTwoRows) {
  const MapPanelFigure spec = test::exampleMapPanels();
  const std::string svg = renderMapPanels(spec).svg;
  const std::vector<double> widths = test::attributeValues(svg, "<image ", "width");
  const std::vector<double> heights = test::attributeValues(svg, "<image ", "height");
  const std::vector<double> ys = test::attributeValues(svg, "<image ", "y");
  ASSERT_EQ(widths.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const double aspect =
        static_cast<double>(spec.panels[k].image.cols) / spec.panels[k].image.rows;
    EXPECT_NEAR(widths[k] / heights[k], aspect, 0.01) << k;
    EXPECT_LE(widths[k], 800.0 / 2);
  }
  EXPECT_DOUBLE_EQ(ys[0], ys[1]);  // first row
  EXPECT_DOUBLE_EQ(ys[2], ys[3]);  // second row
  EXPECT_GT(ys[2], ys[0] + heights[0]);
}

TEST(MapPanels, OneRowByDefaultAndPanelsWithoutTracks) {
  MapPanelFigure spec;
  spec.size = {900, 300};
  for (const char* title : {"occupancy", "point cloud", "topological", "semantic"}) {
    spec.panels.push_back({title, test::exampleMap(200, 150), {}});
  }
  const Figure figure = renderMapPanels(spec);
  EXPECT_EQ(count(figure.svg, "<image "), 4u);
  EXPECT_EQ(count(figure.svg, "<polyline"), 0u);
  const std::vector<double> ys = test::attributeValues(figure.svg, "<image ", "y");
  for (double y : ys) EXPECT_DOUBLE_EQ(y, ys[0]);
  EXPECT_EQ(figure.image.size(), cv::Size(900, 300));
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
