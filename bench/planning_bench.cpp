// Costmap rebuild and A* timings on a synthetic 40 m x 35 m office at 0.05 m resolution.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "roomscout/planning/astar_planner.hpp"
#include "roomscout/planning/costmap.hpp"

namespace {

using roomscout::Cell;
using roomscout::CellState;
using roomscout::GridGeometry;
using roomscout::OccupancyGrid;
using roomscout::Vec2;

constexpr double kResolution_m = 0.05;
constexpr double kWall_m = 0.15;
constexpr double kDoor_m = 0.9;

/// Builds the office: outer walls, a 2 m corridor across the middle, eight 5 m wide rooms on
/// each side opening onto it through 0.9 m doors, and the rooms below the corridor split into
/// a front and a back room joined by another door.
OccupancyGrid makeOffice() {
  const int width = 800, height = 700;  // 40 m x 35 m
  OccupancyGrid grid(GridGeometry({0.0, 0.0}, kResolution_m, width, height));
  // Sets every cell whose centre lies in [x0, x1] x [y0, y1] [m].
  const auto fill = [&](double x0_m, double y0_m, double x1_m, double y1_m, CellState state) {
    const auto first = [](double v_m) {
      return static_cast<int>(std::ceil(v_m / kResolution_m - 0.5));
    };
    const auto last = [](double v_m) {
      return static_cast<int>(std::floor(v_m / kResolution_m - 0.5));
    };
    for (int y = std::max(0, first(y0_m)); y <= std::min(height - 1, last(y1_m)); ++y) {
      for (int x = std::max(0, first(x0_m)); x <= std::min(width - 1, last(x1_m)); ++x) {
        grid.setState(grid.geometry().index(Cell{x, y}), state);
      }
    }
  };
  const auto wall = [&](double x0_m, double y0_m, double x1_m, double y1_m) {
    fill(x0_m - kWall_m / 2, y0_m - kWall_m / 2, x1_m + kWall_m / 2, y1_m + kWall_m / 2,
         CellState::kOccupied);
  };
  // An opening in a wall along x, centred on (x_m, y_m).
  const auto door = [&](double x_m, double y_m) {
    fill(x_m - kDoor_m / 2, y_m - kWall_m, x_m + kDoor_m / 2, y_m + kWall_m, CellState::kFree);
  };

  fill(0, 0, 40, 35, CellState::kFree);
  wall(0, 0, 40, 0);
  wall(0, 35, 40, 35);
  wall(0, 0, 0, 35);
  wall(40, 0, 40, 35);
  const double corridor_low_m = 16.5, corridor_high_m = 18.5, split_m = 8.25;
  wall(0, corridor_low_m, 40, corridor_low_m);
  wall(0, corridor_high_m, 40, corridor_high_m);
  wall(0, split_m, 40, split_m);
  for (int room = 0; room < 8; ++room) {
    const double x_m = 5.0 * room;
    if (room > 0) {
      wall(x_m, 0, x_m, corridor_low_m);
      wall(x_m, corridor_high_m, x_m, 35);
    }
    door(x_m + 2.5, corridor_low_m);
    door(x_m + 2.5, corridor_high_m);
    door(x_m + (room % 2 ? 1.0 : 4.0), split_m);  // back-room doors alternate sides
  }
  return grid;
}

void BM_CostmapUpdate(benchmark::State& state) {
  const OccupancyGrid grid = makeOffice();
  roomscout::Costmap costmap;
  costmap.update(grid);  // first call allocates; the loop measures rebuilds
  for (auto _ : state) {
    costmap.update(grid);
    benchmark::DoNotOptimize(costmap.stepCost(0));
  }
  state.counters["cells"] = static_cast<double>(grid.geometry().cellCount());
}
BENCHMARK(BM_CostmapUpdate)->Unit(benchmark::kMillisecond);

void BM_AStarAcrossOffice(benchmark::State& state) {
  const OccupancyGrid grid = makeOffice();
  roomscout::Costmap costmap;
  costmap.update(grid);
  roomscout::AStarPlanner planner;
  // From the back room in the bottom-left corner to the top-right room.
  const Vec2 start{1.5, 2.0}, goal{38.5, 33.0};
  double length_m = 0.0;
  for (auto _ : state) {
    const roomscout::PlanResult result = planner.plan(costmap, start, goal);
    if (result.status != roomscout::PlanStatus::kFound) {
      state.SkipWithError("no path across the office");
      break;
    }
    benchmark::DoNotOptimize(result);
    length_m = result.path.length_m;
  }
  state.counters["path_m"] = length_m;
}
BENCHMARK(BM_AStarAcrossOffice)->Unit(benchmark::kMillisecond);

}  // namespace
