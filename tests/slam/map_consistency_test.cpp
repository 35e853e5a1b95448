#include "roomscout/slam/map_consistency.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"

namespace roomscout::slam {
namespace {

/// A 10 m x 10 m map at 0.05 m with one occupied column of cells at x in [5.0, 5.05).
OccupancyGrid wallMap() {
  OccupancyGrid grid(GridGeometry(Vec2::Zero(), 0.05, 200, 200));
  for (int y = 0; y < 200; ++y)
    grid.setState(grid.geometry().index(Cell{100, y}), CellState::kOccupied);
  return grid;
}

/// One beam straight ahead (+x) of `range_m`.
LaserScan oneBeam(float range_m) {
  LaserScan scan;
  scan.angle_min_rad = 0.0;
  scan.angle_increment_rad = 0.01;
  scan.range_min_m = 0.1;
  scan.range_max_m = 8.0;
  scan.ranges_m = {range_m};
  return scan;
}

TEST(MapConsistencyTest, PointsOnTheWallAreAtZeroAndPointsOffItAtTheirDistance) {
  const OccupancyGrid map = wallMap();
  // From (1, 5): 4.02 m reaches the wall's cell; 3.02 m stops 1 m (20 cells) short of it.
  const MapConsistency on = mapConsistency(map, {oneBeam(4.02f)}, {Pose2{1.0, 5.0, 0.0}}, 30.0);
  ASSERT_TRUE(on.mean_distance_m);
  EXPECT_DOUBLE_EQ(*on.mean_distance_m, 0.0);
  EXPECT_EQ(on.points, 1u);
  const MapConsistency off = mapConsistency(map, {oneBeam(4.02f), oneBeam(3.02f)},
                                            {Pose2{1.0, 5.0, 0.0}, Pose2{1.0, 5.0, 0.0}}, 30.0);
  ASSERT_TRUE(off.mean_distance_m);
  EXPECT_NEAR(*off.mean_distance_m, 0.5, 0.01);  // (0 + 1 m) / 2
  EXPECT_EQ(off.points, 2u);
}

TEST(MapConsistencyTest, LeavesOutBeamsWithoutReturnAndBeyondTheCap) {
  const OccupancyGrid map = wallMap();
  const Pose2 pose{1.0, 5.0, 0.0};
  const float inf = std::numeric_limits<float>::infinity();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const MapConsistency c = mapConsistency(
      map, {oneBeam(inf), oneBeam(nan), oneBeam(0.0f), oneBeam(-1.0f), oneBeam(3.02f)},
      {pose, pose, pose, pose, pose}, 30.0);
  EXPECT_EQ(c.points, 1u);
  ASSERT_TRUE(c.mean_distance_m);
  EXPECT_NEAR(*c.mean_distance_m, 1.0, 0.01);
  // A cap of 2 m leaves the 3.02 m return out too: nothing is counted.
  const MapConsistency capped = mapConsistency(map, {oneBeam(3.02f)}, {pose}, 2.0);
  EXPECT_EQ(capped.points, 0u);
  EXPECT_FALSE(capped.mean_distance_m);
}

TEST(MapConsistencyTest, CountsPointsOffTheMapApartAndHasNoFigureForAMapWithoutWalls) {
  const OccupancyGrid map = wallMap();
  const MapConsistency c = mapConsistency(map, {oneBeam(7.0f)}, {Pose2{5.0, 5.0, M_PI}}, 30.0);
  EXPECT_EQ(c.outside_points, 1u);
  EXPECT_EQ(c.points, 0u);
  const OccupancyGrid empty(GridGeometry(Vec2::Zero(), 0.05, 20, 20));
  EXPECT_FALSE(
      mapConsistency(empty, {oneBeam(0.5f)}, {Pose2{0.2, 0.2, 0.0}}, 30.0).mean_distance_m);
}

TEST(MapConsistencyTest, RefusesScansAndPosesOfDifferentCounts) {
  EXPECT_THROW(mapConsistency(wallMap(), {oneBeam(1.0f)}, {}, 30.0), InvalidArgument);
  EXPECT_THROW(mapConsistency(wallMap(), {}, {}, 0.0), InvalidArgument);
}

}  // namespace
}  // namespace roomscout::slam
