// The exploration rate as the paper counts it and the map-accuracy figures, on hand-made maps
// with known errors.

#include "roomscout/sim/map_accuracy.hpp"

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/world_model.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

TEST(ExplorationRate, AnObservedWallBlurredIntoTheRoomIsExploredAnUnobservedRoomIsNot) {
  const WorldModel world(testing::twoRooms());  // [0,6]x[0,5] and [6,12]x[0,5]
  const GridGeometry g = mapGeometryFor(world, 0.05);
  const ExplorationTruth truth(world, g, 0.105);
  OccupancyGrid map(g);
  std::size_t left = 0, blurred = 0;
  for (std::uint32_t i : truth.reachableCells()) {
    const Vec2 p = g.centerOf(g.cellAt(i));
    if (p.x() > 6.0) continue;  // the right room is never observed
    ++left;
    // The left room's south wall blurred one cell into the room: occupied floor.
    const bool blur = p.y() < 0.15;
    blurred += blur;
    map.setState(i, blur ? CellState::kOccupied : CellState::kFree);
  }
  ASSERT_GT(blurred, 50u);
  const double n = static_cast<double>(truth.reachableCells().size());
  EXPECT_DOUBLE_EQ(truth.explorationRate(map), left / n);
  EXPECT_NEAR(truth.explorationRate(map), 0.5, 0.02);
  const MapAccuracy a = mapAccuracy(map, truth, world);
  EXPECT_DOUBLE_EQ(a.free_coverage, (left - blurred) / n);
  EXPECT_DOUBLE_EQ(a.false_occupied, blurred / n);

  ExplorationRateCounter counter(truth);
  counter.update(map, CellRect{0, 0, g.width(), g.height()});
  EXPECT_DOUBLE_EQ(counter.rate(), truth.explorationRate(map));
}

TEST(MapAccuracy, CountsEachKindOfErrorOnAHandMadeMap) {
  const WorldModel world(testing::squareRoom(10.0, 0.2));  // wall faces at 0.1 and 9.9 m
  const GridGeometry g = mapGeometryFor(world, 0.05);
  const ExplorationTruth truth(world, g, 0.105);
  OccupancyGrid map(g);
  const MapAccuracy empty = mapAccuracy(map, truth, world);
  EXPECT_EQ(empty.occupied_precision, 1.0);  // nothing occupied
  EXPECT_EQ(empty.occupied_recall, 0.0);     // no wall found
  EXPECT_EQ(empty.false_free, 0.0);          // nothing free
  EXPECT_EQ(empty.free_coverage, 0.0);

  for (std::uint32_t i : truth.reachableCells()) map.setState(i, CellState::kFree);
  auto set = [&](double x, double y, CellState s) { map.setState(g.index(g.cellOf({x, y})), s); };
  // The west wall's inner cells, x in [0.05, 0.1], from y = 1 to 9: 160 true walls found.
  for (int k = 0; k < 160; ++k) set(0.075, 1.025 + 0.05 * k, CellState::kOccupied);
  // 40 occupied cells mid-room: false walls on reachable floor.
  for (int k = 0; k < 40; ++k) set(5.025, 1.025 + 0.05 * k, CellState::kOccupied);
  // 20 cells inside the east wall called free.
  for (int k = 0; k < 20; ++k) set(9.975, 1.025 + 0.05 * k, CellState::kFree);

  const double n = static_cast<double>(truth.reachableCells().size());
  const MapAccuracy a = mapAccuracy(map, truth, world);
  EXPECT_DOUBLE_EQ(a.false_occupied, 40.0 / n);
  EXPECT_DOUBLE_EQ(a.occupied_precision, 160.0 / 200.0);
  EXPECT_DOUBLE_EQ(a.false_free, 20.0 / (n - 40.0 + 20.0));
  EXPECT_DOUBLE_EQ(a.free_coverage, (n - 40.0) / n);
  // The wall cells next to the floor: 4 sides of 196 cells and 4 corners; the 160 occupied
  // ones and one more at each end are within a cell of an occupied cell.
  EXPECT_NEAR(a.occupied_recall, 162.0 / 788.0, 0.003);
  EXPECT_DOUBLE_EQ(truth.explorationRate(map), 1.0);
}

TEST(MapAccuracy, RefusesAMapOffTheTruthsGrid) {
  const WorldModel world(testing::squareRoom(10.0, 0.2));
  const GridGeometry g = mapGeometryFor(world, 0.05);
  const ExplorationTruth truth(world, g, 0.105);
  const OccupancyGrid other(GridGeometry(g.origin_m(), 0.05, g.width() - 1, g.height()));
  EXPECT_THROW(mapAccuracy(other, truth, world), InvalidArgument);
}

}  // namespace
}  // namespace roomscout::sim
