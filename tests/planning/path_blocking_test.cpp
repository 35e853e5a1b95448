// The blocked-path test that makes a driver replan.

#include <gtest/gtest.h>

#include "roomscout/planning/path_blocking.hpp"

namespace roomscout {
namespace {

TEST(PathBlocking, DiscHoldsTheCellsWithinTheRadius) {
  EXPECT_EQ(discOffsets(0.5).size(), 1u);
  EXPECT_EQ(discOffsets(1.5).size(), 9u);   // 3 x 3
  EXPECT_EQ(discOffsets(2.0).size(), 9u);   // (2, 0) is not strictly within
  EXPECT_EQ(discOffsets(2.1).size(), 13u);  // ... now it is, on all four axes
}

TEST(PathBlocking, AnObstacleNearAWaypointAheadWithinTheHorizonBlocks) {
  OccupancyGrid grid(GridGeometry(Vec2::Zero(), 0.1, 100, 10));
  std::vector<Vec2> path;
  for (int i = 0; i < 90; ++i) path.emplace_back(0.05 + 0.1 * i, 0.55);  // along row 5
  const std::vector<Cell> disc = discOffsets(2.5);
  const Vec2 robot(0.05, 0.55);
  EXPECT_FALSE(pathBlockedAhead(grid, path, 0, robot, 100.0, disc));
  grid.setState(grid.geometry().index(Cell{60, 7}),
                CellState::kOccupied);  // 2 cells off waypoint 60
  EXPECT_TRUE(pathBlockedAhead(grid, path, 0, robot, 100.0, disc));
  EXPECT_FALSE(pathBlockedAhead(grid, path, 0, robot, 5.0, disc)) << "beyond the horizon";
  EXPECT_FALSE(pathBlockedAhead(grid, path, 0, robot, 100.0, discOffsets(1.5)))
      << "outside the disc";
  EXPECT_FALSE(pathBlockedAhead(grid, path, 63, robot, 100.0, disc)) << "already passed";
}

}  // namespace
}  // namespace roomscout
