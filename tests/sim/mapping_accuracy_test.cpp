// Simulated scans mapped into a grid, compared with the ground truth.

#include <gtest/gtest.h>

#include <cmath>

#include "roomscout/mapping/occupancy_mapper.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/map_accuracy.hpp"
#include "roomscout/sim/sensor_noise.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

TEST(OccupancyMapping, OneScanAgreesWithGroundTruthInRange) {
  World w = testing::squareRoom(6.0, 0.2);
  w.furniture.push_back({"cabinet", {{4.0, 4.0}, {4.8, 4.0}, {4.8, 4.5}, {4.0, 4.5}}, 0.0, 1.0});
  w.furniture.push_back({"pillar", {{1.5, 2.0}, {1.8, 2.0}, {1.8, 2.3}, {1.5, 2.3}}, 0.0, 2.5});
  const WorldModel model(w);
  const GridGeometry geometry = mapGeometryFor(model, 0.05);
  const ExplorationTruth truth(model, geometry, 0.105);
  OccupancyGrid grid(geometry);
  OccupancyMapper mapper(grid);
  LaserSimulator laser(model, LaserOptions{}, 3);
  const Pose2 pose{3.0, 3.0, 0.2};
  // Two scans from the same pose (one would do: a miss in one scan makes a cell free).
  for (int i = 0; i < 2; ++i) mapper.integrate(laser.scan(pose), pose);

  std::size_t known = 0, agree = 0, free_in_range = 0, free_known = 0;
  for (std::size_t i = 0; i < geometry.cellCount(); ++i) {
    const CellState s = grid.state(i);
    const bool truly_free = truth.trulyFree()[i] != 0;
    if (s != CellState::kUnknown) {
      ++known;
      agree += (s == CellState::kFree) == truly_free ? 1 : 0;
    }
    const double d = (geometry.centerOf(geometry.cellAt(i)) - pose.position()).norm();
    if (truly_free && d < 2.0) {
      ++free_in_range;
      free_known += s == CellState::kFree ? 1 : 0;
    }
  }
  ASSERT_GT(known, 3000u);
  EXPECT_GE(static_cast<double>(agree) / known, 0.99);
  // Everything near the robot that is not in a shadow is mapped as free.
  EXPECT_GE(static_cast<double>(free_known) / free_in_range, 0.95);
  // The cabinet's near face (y = 4.0) is seen as occupied, the cell before it as free.
  EXPECT_EQ(grid.state(geometry.cellOf({4.4, 4.01})), CellState::kOccupied);
  EXPECT_EQ(grid.state(geometry.cellOf({4.4, 3.99})), CellState::kFree);
}

TEST(ExplorationTruth, TwoRoomsAreReachableThroughTheDoor) {
  const WorldModel model(testing::twoRooms());
  const ExplorationTruth truth(model, mapGeometryFor(model, 0.05), 0.105);
  // Both rooms' free floor (about 2 x 5.8 x 4.8 m^2) minus the wall band is reachable.
  EXPECT_NEAR(truth.reachableArea_m2(), 2 * 5.8 * 4.8, 2.0);
  OccupancyGrid empty(truth.geometry());
  EXPECT_EQ(truth.explorationRate(empty), 0.0);
}

TEST(ExplorationTruth, RoomBehindANarrowGapIsNotReachable) {
  World w = testing::twoRooms();
  // Narrow the door to 0.15 m: the robot (0.21 m wide) cannot pass.
  w.walls[4].b_m = {6, 2.425};
  w.walls[5].a_m = {6, 2.575};
  const WorldModel model(w);
  const ExplorationTruth truth(model, mapGeometryFor(model, 0.05), 0.105);
  EXPECT_NEAR(truth.reachableArea_m2(), 5.8 * 4.8, 1.0);
}

}  // namespace
}  // namespace roomscout::sim

namespace roomscout::sim {
namespace {

TEST(ExplorationRateCounter, IncrementalRateEqualsFullRecount) {
  const WorldModel model(testing::twoRooms());
  const GridGeometry geometry = mapGeometryFor(model, 0.05);
  const ExplorationTruth truth(model, geometry, 0.105);
  OccupancyGrid grid(geometry);
  OccupancyMapper mapper(grid);
  LaserSimulator laser(model, LaserOptions{}, 3);
  ExplorationRateCounter counter(truth);
  for (const Pose2& pose :
       {Pose2{2.0, 2.5, 0.0}, Pose2{5.0, 2.5, 0.0}, Pose2{7.0, 2.5, 0.0}, Pose2{10.0, 1.0, 0.0}}) {
    CellRect changed;
    for (int i = 0; i < 2; ++i) changed.unite(mapper.integrate(laser.scan(pose), pose));
    counter.update(grid, changed);
    EXPECT_DOUBLE_EQ(counter.rate(), truth.explorationRate(grid));
  }
  EXPECT_GT(counter.rate(), 0.9);
}

}  // namespace
}  // namespace roomscout::sim

namespace roomscout::sim {
namespace {

/// Scans of the two rooms with the TurtleBot3's laser noise, from poses along three lines
/// through both rooms, each line driven `passes` times back and forth.
OccupancyGrid mapTwoRoomsWithTb3Noise(const WorldModel& model, int passes,
                                      const OccupancyGridOptions& cells = {}) {
  OccupancyGrid grid(mapGeometryFor(model, 0.05), cells);
  OccupancyMapper mapper(grid);
  LaserSimulator laser(model, LaserOptions{}, 7, NoiseProfile::named("tb3").laser);
  for (int pass = 0; pass < passes; ++pass) {
    const double heading = pass % 2 == 0 ? 0.3 : M_PI - 0.3;
    for (double x = 1.0; x <= 11.0; x += 0.25) {
      for (double y : {1.5, 2.5, 3.5}) {
        if (std::abs(x - 6.0) < 0.5 && y != 2.5) continue;  // only the door line passes it
        const Pose2 pose{pass % 2 == 0 ? x : 12.0 - x, y, heading};
        mapper.integrate(laser.scan(pose), pose);
      }
    }
  }
  return grid;
}

void expectTheDoorOpen(const OccupancyGrid& grid) {
  // The door (x 5.9-6.1, y 2.0-3.0) is open: every cell of its middle 0.6 m is free.
  const GridGeometry& g = grid.geometry();
  for (double x = 5.875; x < 6.13; x += 0.05)
    for (double y = 2.225; y < 2.8; y += 0.05)
      EXPECT_TRUE(grid.isFree(g.index(g.cellOf({x, y})))) << x << ", " << y;
}

// The default updates (a hit worth about four misses) keep every wall, and some of the cells
// in front of it that range noise hit: at 3 m the LDS-01's 2.5 % noise is 1.5 cells, and a
// third of the beams end a cell short of the wall.
TEST(OccupancyMapping, WallsScannedManyTimesWithTb3NoiseStayWhereTheyAreAndTheDoorOpen) {
  const WorldModel model(testing::twoRooms());
  const OccupancyGrid grid = mapTwoRoomsWithTb3Noise(model, 10);
  const ExplorationTruth truth(model, grid.geometry(), 0.105);
  const MapAccuracy a = mapAccuracy(grid, truth, model);
  EXPECT_GE(a.occupied_precision, 0.95);
  EXPECT_GE(a.occupied_recall, 0.99);
  EXPECT_LE(a.false_occupied, 0.06);
  EXPECT_LE(a.false_free, 0.01);
  EXPECT_GE(truth.explorationRate(grid), 0.99);
  expectTheDoorOpen(grid);
}

// Updates closer to Cartographer's (p = 0.65 and 0.38) settle the walls to their true cells
// (docs/maps.md: on whole runs they also wear walls seen from afar into dotted bands).
TEST(OccupancyMapping, WithEvenUpdatesNoisyWallsSettleToTheirTrueCells) {
  const WorldModel model(testing::twoRooms());
  OccupancyGridOptions even;
  even.log_odds_hit = 0.63;
  even.log_odds_miss = -0.5;
  const OccupancyGrid grid = mapTwoRoomsWithTb3Noise(model, 10, even);
  const ExplorationTruth truth(model, grid.geometry(), 0.105);
  const MapAccuracy a = mapAccuracy(grid, truth, model);
  EXPECT_GE(a.occupied_precision, 0.99);
  EXPECT_GE(a.occupied_recall, 0.99);
  EXPECT_LE(a.false_occupied, 0.03);
  EXPECT_LE(a.false_free, 0.01);
  expectTheDoorOpen(grid);
}

}  // namespace
}  // namespace roomscout::sim
