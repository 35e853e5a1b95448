#include "roomscout/exploration/frontier_cells.hpp"

#include "roomscout/core/errors.hpp"

#include <gtest/gtest.h>

#include <random>

namespace roomscout {
namespace {

OccupancyGrid makeGrid(int width, int height, CellState fill) {
  OccupancyGrid grid(GridGeometry({0.0, 0.0}, 0.05, width, height));
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) grid.setState(i, fill);
  return grid;
}

void fill(OccupancyGrid& grid, int x0, int y0, int x1, int y1, CellState s) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) grid.setState(grid.geometry().index(Cell{x, y}), s);
  }
}

// A walled room open on its right side to unknown space: the frontier is the unknown column
// next to the opening, minus the cells within L1 < 4 of the walls.
TEST(FrontierCellsTest, OpenSideOfARoomIsItsFrontier) {
  OccupancyGrid grid = makeGrid(60, 40, CellState::kUnknown);
  fill(grid, 5, 5, 30, 35, CellState::kFree);
  fill(grid, 4, 4, 31, 5, CellState::kOccupied);    // bottom wall
  fill(grid, 4, 35, 31, 36, CellState::kOccupied);  // top wall
  fill(grid, 4, 4, 5, 36, CellState::kOccupied);    // left wall; the right side (x = 30) is open
  Costmap costmap;
  costmap.update(grid);
  const Vec2 robot(0.8, 1.0);
  const std::vector<Cell> cells = reachableFrontierCells(grid, costmap, 4, nullptr, &robot);
  ASSERT_FALSE(cells.empty());
  for (const Cell& c : cells) {
    EXPECT_EQ(c.x, 30);
    EXPECT_GE(c.y, 5 + 3);   // L1 distance to the bottom wall row (y = 4) at least 4
    EXPECT_LT(c.y, 35 - 3);  // and to the top wall row (y = 35)
  }
  EXPECT_EQ(countReachableFrontierCells(grid, costmap, 4, nullptr, robot, 1000), cells.size());
  EXPECT_EQ(countReachableFrontierCells(grid, costmap, 4, nullptr, robot, 2), 2u);
  // Exhausted cells are not counted.
  std::vector<std::uint8_t> exhausted(grid.geometry().cellCount(), 0);
  for (const Cell& c : cells) exhausted[grid.geometry().index(c)] = 1;
  EXPECT_EQ(countReachableFrontierCells(grid, costmap, 4, &exhausted, robot, 2), 0u);
  // A robot walled off from the room reaches none of them.
  fill(grid, 20, 5, 21, 35, CellState::kOccupied);
  costmap.update(grid);
  EXPECT_EQ(countReachableFrontierCells(grid, costmap, 4, nullptr, robot, 2), 0u);
  EXPECT_TRUE(reachableFrontierCells(grid, costmap, 4, nullptr, &robot).empty());
}

// The early-exit count agrees with the full scan on random maps, for every limit.
TEST(FrontierCellsTest, CountAgreesWithTheFullScan) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> xs(0, 79), ys(0, 59), sizes(2, 20), kinds(0, 9);
  int above_every_limit = 0;  // trials with more frontier cells than the limits 1, 2 and 7
  for (int trial = 0; trial < 20; ++trial) {
    OccupancyGrid grid = makeGrid(80, 60, CellState::kUnknown);
    for (int k = 0; k < 25; ++k) {
      const int x = xs(rng), y = ys(rng);
      const int kind = kinds(rng);
      const CellState s = kind < 6   ? CellState::kFree
                          : kind < 8 ? CellState::kOccupied
                                     : CellState::kUnknown;
      fill(grid, x, y, std::min(80, x + sizes(rng)), std::min(60, y + sizes(rng)), s);
    }
    Costmap costmap;
    costmap.update(grid);
    const Vec2 robot = grid.geometry().centerOf(Cell{xs(rng), ys(rng)});
    const std::size_t all = reachableFrontierCells(grid, costmap, 4, nullptr, &robot).size();
    above_every_limit += all > 7;
    for (const std::size_t limit :
         {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{100000}}) {
      EXPECT_EQ(countReachableFrontierCells(grid, costmap, 4, nullptr, robot, limit),
                std::min(all, limit))
          << "trial " << trial << " limit " << limit;
    }
  }
  // Most trials have more frontier cells than the limits, so the early exit is exercised.
  EXPECT_GE(above_every_limit, 10);
}

// A costmap computed for another grid is refused, not read out of bounds.
TEST(FrontierCellsTest, RejectsACostmapOfAnotherGrid) {
  OccupancyGrid grid = makeGrid(60, 40, CellState::kFree);
  const OccupancyGrid small = makeGrid(20, 20, CellState::kFree);
  Costmap costmap;
  costmap.update(small);
  const Vec2 robot(0.5, 0.5);
  EXPECT_THROW(reachableFrontierCells(grid, costmap, 4, nullptr, &robot), InvalidArgument);
  EXPECT_THROW(countReachableFrontierCells(grid, costmap, 4, nullptr, robot, 2), InvalidArgument);
  EXPECT_THROW(nearestGoalCell(grid, costmap, robot, 1.0), InvalidArgument);
  std::vector<std::uint8_t> exhausted;
  EXPECT_THROW(markUnknownPockets(exhausted, grid, costmap, {Cell{5, 5}}, 1.0, 0.0),
               InvalidArgument);
}

}  // namespace
}  // namespace roomscout
