// Occupancy grids as images: the fast state image and known-cell count agree with
// OccupancyGrid::state() cell by cell, thresholds included.

#include "roomscout/maps/grid_image.hpp"

#include <gtest/gtest.h>

#include <random>

#include <opencv2/core.hpp>

namespace roomscout::maps {
namespace {

OccupancyGrid randomGrid(std::uint32_t seed) {
  OccupancyGrid grid(GridGeometry(Vec2(-1.0, 2.0), 0.05, 37, 23));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> hits(0, 6);
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) {
    // Sequences of hits and misses reach values on and around both thresholds.
    const int n = hits(rng);
    for (int k = 0; k < n; ++k) (rng() & 1) ? grid.addHit(i) : grid.addMiss(i);
  }
  return grid;
}

TEST(GridImage, StateImageAndKnownCountMatchTheGrid) {
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    const OccupancyGrid grid = randomGrid(seed);
    const GridGeometry& g = grid.geometry();
    const cv::Mat image = stateImage(grid);
    ASSERT_EQ(image.rows, g.height());
    ASSERT_EQ(image.cols, g.width());
    std::size_t known = 0, kinds[3] = {0, 0, 0};
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        const CellState s = grid.state(Cell{x, y});
        EXPECT_EQ(image.at<std::uint8_t>(y, x), static_cast<std::uint8_t>(s));
        known += s != CellState::kUnknown;
        ++kinds[static_cast<int>(s)];
      }
    }
    EXPECT_EQ(knownCellCount(grid), known);
    EXPECT_GT(kinds[0], 0u);
    EXPECT_GT(kinds[1], 0u);
    EXPECT_GT(kinds[2], 0u);
    // Into an existing buffer, reused when it has the size.
    cv::Mat buffer(g.height(), g.width(), CV_8U, cv::Scalar(7));
    const std::uint8_t* data = buffer.data;
    stateImage(grid, buffer);
    EXPECT_EQ(buffer.data, data);
    EXPECT_EQ(cv::countNonZero(buffer != image), 0);
  }
}

}  // namespace
}  // namespace roomscout::maps
