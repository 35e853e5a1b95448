#include "roomscout/planning/costmap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <variant>

#include "roomscout/core/errors.hpp"

namespace roomscout {
namespace {

constexpr double kResolution_m = 0.05;

OccupancyGrid makeGrid(int width, int height, CellState fill) {
  OccupancyGrid grid(GridGeometry({-1.0, 2.0}, kResolution_m, width, height));
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) grid.setState(i, fill);
  return grid;
}

// Distance between two cell centres [m].
double cellDistance_m(Cell a, Cell b) {
  return kResolution_m * std::hypot(static_cast<double>(a.x - b.x), static_cast<double>(a.y - b.y));
}

TEST(CostmapTest, SingleObstacleMakesExactlyTheDiscWithinLethalRadiusLethal) {
  for (const double robot_radius_m : {0.105, 0.3}) {
    CostmapOptions options;
    options.robot_radius_m = robot_radius_m;
    options.inflation_margin_m = robot_radius_m > 0.2 ? 0.02 : 0.05;  // 3.1 and 6.4 cells
    options.cost_scaling_distance_m = 0.5;
    const double lethal_m = options.lethalRadius_m();
    OccupancyGrid grid = makeGrid(41, 37, CellState::kFree);
    const Cell obstacle{20, 17};
    grid.setState(grid.geometry().index(obstacle), CellState::kOccupied);

    Costmap costmap(options);
    costmap.update(grid);
    int lethal_count = 0;
    int expected_count = 0;
    for (int y = 0; y < 37; ++y) {
      for (int x = 0; x < 41; ++x) {
        const Cell c{x, y};
        const double d_m = cellDistance_m(c, obstacle);
        ASSERT_GT(std::abs(d_m - lethal_m), 1e-6) << "test geometry puts a cell on the boundary";
        const bool expected = d_m < lethal_m;
        EXPECT_EQ(costmap.isLethal(c), expected) << "cell " << x << "," << y << " d=" << d_m;
        lethal_count += costmap.isLethal(c);
        expected_count += expected;
      }
    }
    EXPECT_EQ(lethal_count, expected_count);
    EXPECT_GT(lethal_count, 1);
  }
}

TEST(CostmapTest, ClearanceMatchesBruteForceDistancesUpToTheCap) {
  OccupancyGrid grid = makeGrid(60, 45, CellState::kFree);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> xs(0, 59), ys(0, 44);
  std::vector<Cell> obstacles;
  for (int i = 0; i < 12; ++i) {
    const Cell c{xs(rng), ys(rng)};
    obstacles.push_back(c);
    grid.setState(grid.geometry().index(c), CellState::kOccupied);
  }
  // A few unknown cells must not count as obstacles.
  for (int i = 0; i < 30; ++i) {
    const Cell c{xs(rng), ys(rng)};
    if (grid.state(c) == CellState::kFree)
      grid.setState(grid.geometry().index(c), CellState::kUnknown);
  }
  Costmap costmap;
  costmap.update(grid);
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) {
    const Cell c = grid.geometry().cellAt(i);
    double nearest_m = 1e9;
    for (const Cell& o : obstacles) nearest_m = std::min(nearest_m, cellDistance_m(c, o));
    EXPECT_NEAR(costmap.clearance_m(i), std::min(nearest_m, costmap.maxClearance_m()), 1e-3)
        << "cell " << c.x << "," << c.y;
  }
}

TEST(CostmapTest, GridWithoutObstaclesHasCappedClearanceAndUnitCost) {
  const OccupancyGrid grid = makeGrid(20, 10, CellState::kFree);
  Costmap costmap;
  costmap.update(grid);
  ASSERT_EQ(costmap.geometry(), grid.geometry());
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) {
    EXPECT_FLOAT_EQ(costmap.clearance_m(i), static_cast<float>(costmap.maxClearance_m()));
    EXPECT_FALSE(costmap.isLethal(i));
    EXPECT_FALSE(costmap.isUnknown(i));
    EXPECT_FLOAT_EQ(costmap.stepCost(i), 1.0f);
  }
}

TEST(CostmapTest, UnknownCellsAreTraversableButCostMore) {
  OccupancyGrid grid = makeGrid(30, 30, CellState::kFree);
  for (int y = 0; y < 30; ++y) {
    for (int x = 15; x < 30; ++x) grid.setState(grid.geometry().index({x, y}), CellState::kUnknown);
  }
  CostmapOptions options;
  options.unknown_cost = 1.5;
  Costmap costmap(options);
  costmap.update(grid);
  const std::size_t free_cell = grid.geometry().index({5, 10});
  const std::size_t unknown_cell = grid.geometry().index({25, 10});
  EXPECT_FALSE(costmap.isUnknown(free_cell));
  EXPECT_TRUE(costmap.isUnknown(unknown_cell));
  EXPECT_FALSE(costmap.isLethal(unknown_cell));
  EXPECT_GT(costmap.stepCost(unknown_cell), costmap.stepCost(free_cell));
  EXPECT_FLOAT_EQ(costmap.stepCost(unknown_cell), costmap.stepCost(free_cell) + 1.5f);
  // An all-unknown map has no lethal cell at all.
  Costmap unknown_costmap(options);
  unknown_costmap.update(makeGrid(10, 10, CellState::kUnknown));
  for (std::size_t i = 0; i < 100; ++i) EXPECT_FALSE(unknown_costmap.isLethal(i));
}

TEST(CostmapTest, SoftCostFollowsTheLinearRampBetweenLethalAndScalingDistance) {
  // A wall along x = 0 (column 0); clearance of column x is x cells.
  OccupancyGrid grid = makeGrid(30, 5, CellState::kFree);
  for (int y = 0; y < 5; ++y) grid.setState(grid.geometry().index({0, y}), CellState::kOccupied);
  CostmapOptions options;  // lethal 0.155 m, scaling 0.35 m, max soft cost 8
  Costmap costmap(options);
  costmap.update(grid);
  float previous = 1e9f;
  for (int x = 4; x < 30; ++x) {
    const std::size_t i = grid.geometry().index({x, 2});
    const double clearance_m = x * kResolution_m;
    const double ramp = (options.cost_scaling_distance_m - clearance_m) /
                        (options.cost_scaling_distance_m - options.lethalRadius_m());
    const double expected = 1.0 + options.max_soft_cost * std::clamp(ramp, 0.0, 1.0);
    EXPECT_NEAR(costmap.stepCost(i), expected, 1e-4) << "column " << x;
    EXPECT_LE(costmap.stepCost(i), previous);
    EXPECT_GE(costmap.stepCost(i), 1.0f);
    EXPECT_LE(costmap.stepCost(i), 1.0f + options.max_soft_cost);
    previous = costmap.stepCost(i);
  }
  EXPECT_GT(costmap.stepCost(grid.geometry().index({4, 2})), 1.0f);
  EXPECT_FLOAT_EQ(costmap.stepCost(grid.geometry().index({10, 2})), 1.0f);
}

TEST(CostmapTest, UpdateFollowsGridChangesAndSizes) {
  Costmap costmap;
  OccupancyGrid grid = makeGrid(20, 20, CellState::kFree);
  costmap.update(grid);
  EXPECT_FALSE(costmap.isLethal(Cell{10, 10}));
  grid.setState(grid.geometry().index({10, 10}), CellState::kOccupied);
  costmap.update(grid);
  EXPECT_TRUE(costmap.isLethal(Cell{10, 10}));
  EXPECT_TRUE(costmap.isLethal(Cell{11, 11}));

  const OccupancyGrid bigger = makeGrid(50, 7, CellState::kFree);
  costmap.update(bigger);
  EXPECT_EQ(costmap.geometry(), bigger.geometry());
  EXPECT_FALSE(costmap.isLethal(Cell{49, 6}));
  // Outside the grid counts as lethal.
  EXPECT_TRUE(costmap.isLethal(Cell{50, 0}));
  EXPECT_TRUE(costmap.isLethal(Cell{-1, 3}));

  costmap.update(OccupancyGrid(GridGeometry({0, 0}, 0.05, 0, 0)));
  EXPECT_EQ(costmap.geometry().cellCount(), 0u);
}

// Incremental updates (only the window around changed cells) must equal a build from scratch,
// whatever the sequence of changes: obstacles appearing, disappearing, unknown becoming free.
TEST(CostmapTest, IncrementalUpdatesEqualABuildFromScratch) {
  OccupancyGrid grid = makeGrid(120, 90, CellState::kUnknown);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> xs(0, 119), ys(0, 89), sizes(1, 25), kinds(0, 2);
  Costmap incremental, hinted;  // hinted: told the rectangle of each change
  incremental.update(grid);
  hinted.update(grid);
  for (int step = 0; step < 40; ++step) {
    // A random rectangle of cells takes a random state, as a laser scan changes a patch.
    const int x0 = xs(rng), y0 = ys(rng), w = sizes(rng), h = sizes(rng);
    const CellState s = static_cast<CellState>(kinds(rng));
    for (int y = y0; y < std::min(90, y0 + h); ++y) {
      for (int x = x0; x < std::min(120, x0 + w); ++x)
        grid.setState(grid.geometry().index(Cell{x, y}), s);
    }
    incremental.update(grid);
    hinted.update(grid, CellRect{x0, y0, x0 + w, y0 + h});
    Costmap fresh;
    fresh.update(grid);
    for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) {
      ASSERT_EQ(incremental.isLethal(i), fresh.isLethal(i)) << "step " << step << " cell " << i;
      ASSERT_EQ(incremental.isUnknown(i), fresh.isUnknown(i)) << "step " << step << " cell " << i;
      ASSERT_FLOAT_EQ(incremental.clearance_m(i), fresh.clearance_m(i))
          << "step " << step << " cell " << i;
      ASSERT_FLOAT_EQ(incremental.stepCost(i), fresh.stepCost(i))
          << "step " << step << " cell " << i;
      ASSERT_EQ(hinted.isLethal(i), fresh.isLethal(i)) << "step " << step << " cell " << i;
      ASSERT_FLOAT_EQ(hinted.stepCost(i), fresh.stepCost(i)) << "step " << step << " cell " << i;
    }
  }
}

// A SLAM map grows on every side and its origin moves as it grows (and may keep its size while
// it moves): an update on another geometry equals a build from scratch on it, even when the
// caller passes the rectangle of its last changes, which means nothing on a new geometry.
TEST(CostmapTest, AnUpdateOnAnotherGeometryEqualsABuildFromScratch) {
  OccupancyGrid grid = makeGrid(80, 60, CellState::kUnknown);
  const GridGeometry& g0 = grid.geometry();
  for (int y = 10; y < 50; ++y) {
    for (int x = 10; x < 70; ++x) grid.setState(g0.index(Cell{x, y}), CellState::kFree);
  }
  for (int x = 10; x < 70; ++x) grid.setState(g0.index(Cell{x, 30}), CellState::kOccupied);
  for (int y = 10; y < 50; ++y) grid.setState(g0.index(Cell{40, y}), CellState::kOccupied);
  const double r = kResolution_m;
  auto moved = [&](int dx, int dy, int dw, int dh) {
    return GridGeometry(g0.origin_m() + Vec2(dx * r, dy * r), r, g0.width() + dw, g0.height() + dh);
  };
  const GridGeometry frames[] = {
      moved(-7, -3, 19, 11),  // grown on every side
      moved(5, -4, 0, 0),     // moved without changing size (same cell count)
      moved(-12, 6, 30, -8),  // grown left and right, cropped below and above
      moved(9, 9, -20, -20),  // cropped on every side
  };
  for (const bool hinted : {false, true}) {
    Costmap costmap;
    costmap.update(grid);
    for (const GridGeometry& frame : frames) {
      const OccupancyGrid next = grid.reframed(frame);
      if (hinted) {
        costmap.update(next, CellRect{20, 20, 22, 22});
      } else {
        costmap.update(next);
      }
      Costmap fresh;
      fresh.update(next);
      ASSERT_EQ(costmap.geometry(), next.geometry());
      ASSERT_EQ(costmap.lethalMask().size(), next.geometry().cellCount());
      std::size_t lethal = 0;
      for (std::size_t i = 0; i < next.geometry().cellCount(); ++i) {
        ASSERT_EQ(costmap.isLethal(i), fresh.isLethal(i)) << "cell " << i;
        ASSERT_EQ(costmap.isUnknown(i), fresh.isUnknown(i)) << "cell " << i;
        ASSERT_EQ(costmap.clearance_m(i), fresh.clearance_m(i)) << "cell " << i;
        ASSERT_EQ(costmap.stepCost(i), fresh.stepCost(i)) << "cell " << i;
        lethal += costmap.isLethal(i);
      }
      EXPECT_GT(lethal, 0u);  // the walls came along
      // The walls stay where they are in the map frame.
      const Vec2 wall_m = g0.centerOf(Cell{40, 20});
      EXPECT_TRUE(costmap.isLethal(next.geometry().cellOf(wall_m)));
    }
  }
}

TEST(CostmapTest, OptionsAreValidated) {
  const auto throws = [](auto mutate) {
    CostmapOptions options;
    mutate(options);
    EXPECT_THROW(options.validate(), OptionError);
    EXPECT_THROW(Costmap{options}, OptionError);
  };
  throws([](CostmapOptions& o) { o.robot_radius_m = -0.1; });
  throws([](CostmapOptions& o) { o.inflation_margin_m = -0.01; });
  throws([](CostmapOptions& o) { o.cost_scaling_distance_m = o.lethalRadius_m(); });
  throws([](CostmapOptions& o) { o.max_soft_cost = -1.0; });
  throws([](CostmapOptions& o) { o.unknown_cost = std::nan(""); });
  throws([](CostmapOptions& o) { o.robot_radius_m = INFINITY; });
  EXPECT_NO_THROW(CostmapOptions{}.validate());
  try {
    CostmapOptions options;
    options.cost_scaling_distance_m = 0.1;
    options.validate();
    FAIL() << "expected OptionError";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("cost_scaling_distance_m"), std::string::npos);
  }
}

TEST(CostmapTest, ParametersListEveryFieldWithDocs) {
  CostmapOptions options;
  const std::vector<ParameterRef> parameters = options.parameters();
  ASSERT_EQ(parameters.size(), 5u);
  for (const ParameterRef& p : parameters) {
    EXPECT_FALSE(p.doc.empty()) << p.name;
    ASSERT_TRUE(std::holds_alternative<double*>(p.value)) << p.name;
    *std::get<double*>(p.value) = 42.0;
  }
  EXPECT_EQ(options.robot_radius_m, 42.0);
  EXPECT_EQ(options.inflation_margin_m, 42.0);
  EXPECT_EQ(options.cost_scaling_distance_m, 42.0);
  EXPECT_EQ(options.max_soft_cost, 42.0);
  EXPECT_EQ(options.unknown_cost, 42.0);
}

}  // namespace
}  // namespace roomscout
