#include "roomscout/sim/slam_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/world_model.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

TEST(TrajectoryError, OfAHandMadeTrajectory) {
  // Errors of 0, 0.3 and 0.4 m; headings off by 0, 0.1 and -0.2 rad (the last across the
  // +-pi seam, which must wrap).
  const std::vector<TrajectorySample> t = {
      {0.0, Pose2{0, 0, 0}, Pose2{0, 0, 0}},
      {1.0, Pose2{1, 0, 0.5}, Pose2{1.3, 0, 0.6}},
      {2.0, Pose2{2, 0, M_PI - 0.1}, Pose2{2, 0.4, -M_PI + 0.1}},
  };
  // Third heading error: (-pi + 0.1) - (pi - 0.1) wraps to 0.2.
  const TrajectoryError e = trajectoryError(t);
  EXPECT_EQ(e.samples, 3u);
  EXPECT_NEAR(e.rmse_m, std::sqrt((0.09 + 0.16) / 3.0), 1e-12);
  EXPECT_NEAR(e.max_m, 0.4, 1e-12);
  EXPECT_NEAR(e.heading_rmse_rad, std::sqrt((0.01 + 0.04) / 3.0), 1e-12);
  EXPECT_EQ(trajectoryError({}).samples, 0u);
  EXPECT_EQ(trajectoryError({}).rmse_m, 0.0);
}

TEST(MapPrecision, CountsOccupiedCellsOnOrNextToTrueWalls) {
  const WorldModel world(testing::squareRoom(10.0, 0.2));  // wall faces at 0.1 and 9.9 m
  const GridGeometry g = mapGeometryFor(world, 0.05);
  OccupancyGrid map(g);
  EXPECT_EQ(mapPrecision(map, world), 1.0);  // nothing occupied
  auto mark = [&](double x, double y) {
    map.setState(g.index(g.cellOf(Vec2(x, y))), CellState::kOccupied);
  };
  for (double y = 1.0; y < 9.0; y += 0.05) mark(0.125, y);  // on the west wall's face: 160 cells
  for (double y = 1.0; y < 3.0; y += 0.05) mark(0.175, y);  // one cell off it: 40 cells
  for (double y = 1.0; y < 3.0; y += 0.05) mark(5.0, y);    // mid-room: 40 false cells
  EXPECT_NEAR(mapPrecision(map, world), 200.0 / 240.0, 1e-9);
}

}  // namespace
}  // namespace roomscout::sim
