#include "roomscout/core/occupancy_grid.hpp"

#include <cmath>
#include <random>

#include "roomscout/core/errors.hpp"

#include <gtest/gtest.h>

namespace roomscout {
namespace {

/// The classification the grid documents: above occupied_threshold occupied, below
/// free_threshold free, unknown in between.
CellState classify(const OccupancyGrid& grid, std::size_t i) {
  const float l = grid.logOdds(i);
  if (l > static_cast<float>(grid.options().occupied_threshold)) return CellState::kOccupied;
  if (l < static_cast<float>(grid.options().free_threshold)) return CellState::kFree;
  return CellState::kUnknown;
}

TEST(OccupancyGrid, NewGridIsUnknown) {
  const OccupancyGrid grid(GridGeometry(Vec2(0, 0), 0.05, 8, 6));
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) {
    EXPECT_EQ(grid.state(i), CellState::kUnknown);
    EXPECT_EQ(grid.logOdds(i), 0.0f);
  }
}

TEST(OccupancyGrid, StatesFollowTheLogOddsThroughEveryKindOfWrite) {
  OccupancyGrid grid(GridGeometry(Vec2(0, 0), 0.05, 20, 10));
  const std::size_t n = grid.geometry().cellCount();
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::size_t> cell(0, n - 1);
  std::uniform_int_distribution<int> op(0, 9);
  for (int step = 0; step < 20000; ++step) {
    const std::size_t i = cell(rng);
    const int o = op(rng);
    if (o < 4) {
      grid.addMiss(i);
    } else if (o < 7) {
      grid.addHit(i);
    } else {
      grid.setState(i, static_cast<CellState>(o - 7));
    }
    ASSERT_EQ(grid.state(i), classify(grid, i)) << "after step " << step;
  }
  // Every cell, and the bulk view, agree with the log-odds; cells changed their minds on the
  // way (a hit after misses, misses after a hit), so all three states were crossed.
  int counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(grid.state(i), classify(grid, i));
    EXPECT_EQ(grid.states()[i], grid.state(i));
    ++counts[static_cast<int>(grid.state(i))];
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_GT(counts[1], 0);
  EXPECT_GT(counts[2], 0);
}

TEST(OccupancyGrid, AnOccupiedCellMissedOftenEnoughBecomesUnknownThenFree) {
  OccupancyGrid grid(GridGeometry(Vec2(0, 0), 0.05, 1, 1));
  grid.addHit(0);  // 1.6 > 0.62
  EXPECT_EQ(grid.state(0), CellState::kOccupied);
  grid.addMiss(0);  // 1.19
  grid.addMiss(0);  // 0.78
  EXPECT_EQ(grid.state(0), CellState::kOccupied);
  grid.addMiss(0);  // 0.37: between the thresholds
  EXPECT_EQ(grid.state(0), CellState::kUnknown);
  grid.addMiss(0);  // -0.04
  grid.addMiss(0);  // -0.45 < -0.35
  EXPECT_EQ(grid.state(0), CellState::kFree);
}

TEST(OccupancyGridReframe, KeepsCellsWhereTheyAreInTheMapFrame) {
  const GridGeometry g(Vec2(1.0, -2.0), 0.1, 20, 10);
  OccupancyGrid grid(g);
  const Vec2 wall(2.05, -1.45), floor(1.25, -1.15);
  grid.setState(g.index(g.cellOf(wall)), CellState::kOccupied);
  grid.setState(g.index(g.cellOf(floor)), CellState::kFree);
  // Grown by 3 cells on the left and 2 below, cut by 5 on the right.
  const GridGeometry bigger(Vec2(0.7, -2.2), 0.1, 18, 15);
  const OccupancyGrid moved = grid.reframed(bigger);
  const GridGeometry& m = moved.geometry();
  EXPECT_EQ(m.width(), 18);
  EXPECT_EQ(m.height(), 15);
  EXPECT_EQ(moved.state(m.cellOf(wall)), CellState::kOccupied);
  EXPECT_EQ(moved.state(m.cellOf(floor)), CellState::kFree);
  EXPECT_EQ(moved.logOdds(m.index(m.cellOf(wall))), grid.logOdds(g.index(g.cellOf(wall))));
  std::size_t known = 0;
  for (CellState s : moved.states()) known += s != CellState::kUnknown;
  EXPECT_EQ(known, 2u);
  // Cropped to exclude the wall: it is gone, the floor stays.
  const OccupancyGrid cropped = grid.reframed(GridGeometry(Vec2(1.1, -1.5), 0.1, 5, 5));
  std::size_t known_cropped = 0;
  for (CellState s : cropped.states()) known_cropped += s != CellState::kUnknown;
  EXPECT_EQ(known_cropped, 1u);
  EXPECT_EQ(cropped.state(cropped.geometry().cellOf(floor)), CellState::kFree);
}

TEST(OccupancyGridReframe, RejectsAnotherResolutionOrAnOffLatticeOrigin) {
  const OccupancyGrid grid(GridGeometry(Vec2(0, 0), 0.05, 10, 10));
  EXPECT_THROW(grid.reframed(GridGeometry(Vec2(0, 0), 0.1, 10, 10)), InvalidArgument);
  EXPECT_THROW(grid.reframed(GridGeometry(Vec2(0.02, 0), 0.05, 10, 10)), InvalidArgument);
  EXPECT_THROW(GridGeometry(Vec2(std::nan(""), 0), 0.05, 10, 10), InvalidArgument);
}

}  // namespace
}  // namespace roomscout
