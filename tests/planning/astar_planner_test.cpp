#include "roomscout/planning/astar_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>

#include "roomscout/core/errors.hpp"

namespace roomscout {
namespace {

constexpr double kResolution_m = 0.05;
const double kSqrt2 = std::sqrt(2.0);

OccupancyGrid makeGrid(int width, int height, CellState fill, const Vec2& origin_m = {0, 0}) {
  OccupancyGrid grid(GridGeometry(origin_m, kResolution_m, width, height));
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) grid.setState(i, fill);
  return grid;
}

void fillRect(OccupancyGrid& grid, int x0, int y0, int x1, int y1, CellState state) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) grid.setState(grid.geometry().index({x, y}), state);
  }
}

Costmap makeCostmap(const OccupancyGrid& grid, CostmapOptions options = {}) {
  Costmap costmap(options);
  costmap.update(grid);
  return costmap;
}

double octile_m(Cell a, Cell b) {
  const int dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
  return kResolution_m * (std::max(dx, dy) - std::min(dx, dy) + kSqrt2 * std::min(dx, dy));
}

double polylineLength_m(const std::vector<Vec2>& w) {
  double length_m = 0.0;
  for (std::size_t i = 1; i < w.size(); ++i) length_m += (w[i] - w[i - 1]).norm();
  return length_m;
}

// Checks what every found path must satisfy: waypoints on traversable cells, 8-connected
// steps, no corner cutting, and a consistent length.
void expectWellFormed(const Costmap& costmap, const Path& path, bool allow_unknown = true) {
  const GridGeometry& g = costmap.geometry();
  ASSERT_FALSE(path.waypoints_m.empty());
  EXPECT_TRUE(AStarPlanner::pathIsClear(costmap, path));
  EXPECT_NEAR(path.length_m, polylineLength_m(path.waypoints_m), 1e-9);
  for (std::size_t i = 0; i < path.waypoints_m.size(); ++i) {
    const Cell c = g.cellOf(path.waypoints_m[i]);
    ASSERT_TRUE(g.contains(c));
    EXPECT_FALSE(costmap.isLethal(c)) << "waypoint " << i << " on a lethal cell";
    if (!allow_unknown) {
      EXPECT_FALSE(costmap.isUnknown(g.index(c))) << "waypoint " << i;
    }
    if (i == 0) continue;
    const Cell p = g.cellOf(path.waypoints_m[i - 1]);
    const int dx = c.x - p.x, dy = c.y - p.y;
    EXPECT_TRUE(std::abs(dx) <= 1 && std::abs(dy) <= 1 && (dx != 0 || dy != 0))
        << "step " << i << " is not to an 8-neighbour";
    if (dx != 0 && dy != 0) {
      EXPECT_FALSE(costmap.isLethal(Cell{p.x + dx, p.y})) << "corner cut at step " << i;
      EXPECT_FALSE(costmap.isLethal(Cell{p.x, p.y + dy})) << "corner cut at step " << i;
    }
  }
}

// Cost of a path as the planner defines it: step cost of the entered cell times step length.
double pathCost(const Costmap& costmap, const Path& path) {
  const GridGeometry& g = costmap.geometry();
  double cost = 0.0;
  for (std::size_t i = 1; i < path.waypoints_m.size(); ++i) {
    const Cell p = g.cellOf(path.waypoints_m[i - 1]);
    const Cell c = g.cellOf(path.waypoints_m[i]);
    const double step = (p.x != c.x && p.y != c.y) ? kSqrt2 : 1.0;
    cost += costmap.stepCost(g.index(c)) * step * kResolution_m;
  }
  return cost;
}

// Plain Dijkstra with the same move rules, as a reference for optimality.
double referenceCost(const Costmap& costmap, Cell start, Cell goal) {
  const GridGeometry& g = costmap.geometry();
  std::vector<double> dist(g.cellCount(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  dist[g.index(start)] = 0.0;
  open.push({0.0, g.index(start)});
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[i]) continue;
    const Cell c = g.cellAt(i);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const Cell n{c.x + dx, c.y + dy};
        if (costmap.isLethal(n)) continue;
        if (dx != 0 && dy != 0 &&
            (costmap.isLethal(Cell{c.x + dx, c.y}) || costmap.isLethal(Cell{c.x, c.y + dy}))) {
          continue;
        }
        const double nd =
            d + costmap.stepCost(g.index(n)) * (dx && dy ? kSqrt2 : 1.0) * kResolution_m;
        if (nd < dist[g.index(n)]) {
          dist[g.index(n)] = nd;
          open.push({nd, g.index(n)});
        }
      }
    }
  }
  return dist[g.index(goal)];
}

TEST(AStarPlannerTest, EmptyGridPathsHaveTheOctileLength) {
  for (const CellState fill : {CellState::kFree, CellState::kUnknown}) {
    const OccupancyGrid grid = makeGrid(60, 50, fill, {-1.0, 2.5});
    const Costmap costmap = makeCostmap(grid);
    AStarPlanner planner;
    const Cell start{5, 5};
    for (const Cell goal : {Cell{45, 5}, Cell{5, 44}, Cell{40, 40}, Cell{50, 20}, Cell{12, 45},
                            Cell{0, 0}, Cell{6, 5}, Cell{59, 49}}) {
      const PlanResult r =
          planner.plan(costmap, grid.geometry().centerOf(start), grid.geometry().centerOf(goal));
      ASSERT_EQ(r.status, PlanStatus::kFound);
      expectWellFormed(costmap, r.path);
      EXPECT_NEAR(r.path.length_m, octile_m(start, goal), 1e-6)
          << "goal " << goal.x << "," << goal.y;
      EXPECT_TRUE(grid.geometry().cellOf(r.path.waypoints_m.front()) == start);
      EXPECT_TRUE(grid.geometry().cellOf(r.path.waypoints_m.back()) == goal);
    }
  }
}

TEST(AStarPlannerTest, EndpointsAreTheExactStartAndGoal) {
  const OccupancyGrid grid = makeGrid(40, 40, CellState::kFree);
  const Costmap costmap = makeCostmap(grid);
  AStarPlanner planner;
  const Vec2 start{0.512, 0.333}, goal{1.401, 1.777};
  const PlanResult r = planner.plan(costmap, start, goal);
  ASSERT_EQ(r.status, PlanStatus::kFound);
  EXPECT_EQ(r.path.waypoints_m.front(), start);
  EXPECT_EQ(r.path.waypoints_m.back(), goal);
  // Start and goal in the same cell: a single waypoint.
  const PlanResult same = planner.plan(costmap, {1.01, 1.01}, {1.04, 1.02});
  ASSERT_EQ(same.status, PlanStatus::kFound);
  ASSERT_EQ(same.path.waypoints_m.size(), 1u);
  EXPECT_EQ(same.path.length_m, 0.0);
}

TEST(AStarPlannerTest, PathThroughGapInWallIsNearTheAnalyticShortest) {
  // 12 m x 10 m; a 0.1 m wall at x = 6.0..6.1 m with a 0.9 m gap at y = 7.0..7.9 m.
  OccupancyGrid grid = makeGrid(240, 200, CellState::kFree);
  fillRect(grid, 120, 0, 122, 140, CellState::kOccupied);
  fillRect(grid, 120, 158, 122, 200, CellState::kOccupied);
  CostmapOptions options;
  options.max_soft_cost = 0.0;
  const Costmap costmap = makeCostmap(grid, options);
  const double r_m = options.lethalRadius_m();

  // For a point robot the lethal set is the union of discs of radius r around the obstacle
  // cell centres; the shortest path below-left to below-right runs tangent to the discs of the
  // gap's lower corner cells c1 and c2, over their tops, with arcs in between. Start and goal
  // lie near 45 degree lines, where the octile metric is close to Euclidean.
  const Vec2 c1{6.025, 6.975}, c2{6.075, 6.975};
  const Vec2 start = c1 + Vec2(-5.0, -5.0), goal = c2 + Vec2(5.0, -5.0);
  const auto tangent_m = [&](const Vec2& p, const Vec2& c) {
    return std::sqrt((p - c).squaredNorm() - r_m * r_m);
  };
  const auto tangentAngle = [&](const Vec2& p, const Vec2& c, double side) {
    const double a =
        std::atan2(p.y() - c.y(), p.x() - c.x()) + side * std::acos(r_m / (p - c).norm());
    return std::fmod(a + 4.0 * M_PI, 2.0 * M_PI);
  };
  const double arc1_m = r_m * (tangentAngle(start, c1, -1.0) - M_PI / 2);
  const double arc2_m = r_m * (M_PI / 2 - tangentAngle(goal, c2, +1.0));
  ASSERT_GT(arc1_m, 0.0);
  ASSERT_GT(arc2_m, 0.0);
  const double analytic_m =
      tangent_m(start, c1) + arc1_m + (c2 - c1).norm() + arc2_m + tangent_m(goal, c2);

  AStarPlanner planner;
  const PlanResult r = planner.plan(costmap, start, goal);
  ASSERT_EQ(r.status, PlanStatus::kFound);
  expectWellFormed(costmap, r.path);
  EXPECT_NEAR(r.path.length_m, analytic_m, 0.02 * analytic_m);
  EXPECT_GE(r.path.length_m, analytic_m - 0.02);
  bool crossed_in_gap = false;
  for (const Vec2& p : r.path.waypoints_m) {
    if (std::abs(p.x() - 6.05) < 0.03) crossed_in_gap = p.y() > 7.0 && p.y() < 7.9;
  }
  EXPECT_TRUE(crossed_in_gap);
}

TEST(AStarPlannerTest, ClosedWallGivesNoPath) {
  OccupancyGrid grid = makeGrid(80, 60, CellState::kFree);
  fillRect(grid, 40, 0, 42, 60, CellState::kOccupied);
  const Costmap costmap = makeCostmap(grid);
  AStarPlanner planner;
  EXPECT_EQ(planner.plan(costmap, {0.5, 1.5}, {3.5, 1.5}).status, PlanStatus::kNoPath);
  // The planner stays usable afterwards.
  const PlanResult same_side = planner.plan(costmap, {0.5, 1.5}, {1.5, 0.5});
  ASSERT_EQ(same_side.status, PlanStatus::kFound);
  expectWellFormed(costmap, same_side.path);
}

TEST(AStarPlannerTest, GoalInWallMovesToNearestFreeCellWithinTolerance) {
  OccupancyGrid grid = makeGrid(80, 60, CellState::kFree);
  fillRect(grid, 40, 0, 42, 45, CellState::kOccupied);
  const Costmap costmap = makeCostmap(grid);
  const GridGeometry& g = grid.geometry();
  const Vec2 goal = g.centerOf({40, 20}) + Vec2(0.01, 0.003);

  AStarOptions options;
  options.goal_tolerance_m = 0.3;
  AStarPlanner planner(options);
  const PlanResult r = planner.plan(costmap, {0.5, 0.5}, goal);
  ASSERT_EQ(r.status, PlanStatus::kFound);
  expectWellFormed(costmap, r.path);
  const Vec2 end = r.path.waypoints_m.back();
  EXPECT_LE((end - goal).norm(), 0.3);
  // No traversable cell is nearer the requested goal.
  double nearest_m = 1e9;
  for (std::size_t i = 0; i < g.cellCount(); ++i) {
    if (!costmap.isLethal(i))
      nearest_m = std::min(nearest_m, (g.centerOf(g.cellAt(i)) - goal).norm());
  }
  EXPECT_NEAR((end - goal).norm(), nearest_m, 1e-9);
  EXPECT_LT(end.x(), 2.0);  // the near side of the wall (0.01 m to the right is further)

  options.goal_tolerance_m = 0.0;
  EXPECT_EQ(AStarPlanner(options).plan(costmap, {0.5, 0.5}, goal).status, PlanStatus::kGoalBlocked);
  options.goal_tolerance_m = 0.1;  // the lethal band is ~0.16 m wide on each side
  EXPECT_EQ(AStarPlanner(options).plan(costmap, {0.5, 0.5}, goal).status, PlanStatus::kGoalBlocked);
}

TEST(AStarPlannerTest, StartInInflationStillFindsAPath) {
  OccupancyGrid grid = makeGrid(80, 60, CellState::kFree);
  fillRect(grid, 40, 0, 42, 45, CellState::kOccupied);
  const Costmap costmap = makeCostmap(grid);
  const GridGeometry& g = grid.geometry();
  const Vec2 start = g.centerOf({38, 20});  // 0.1 m from the wall: lethal
  ASSERT_TRUE(costmap.isLethal(g.cellOf(start)));
  AStarPlanner planner;
  const PlanResult r = planner.plan(costmap, start, {3.5, 2.0});
  ASSERT_EQ(r.status, PlanStatus::kFound);
  expectWellFormed(costmap, r.path);
  EXPECT_LE((r.path.waypoints_m.front() - start).norm(), 0.5);

  // Deep inside a large obstacle nothing traversable is within 0.5 m.
  OccupancyGrid block = makeGrid(80, 60, CellState::kFree);
  fillRect(block, 10, 10, 50, 50, CellState::kOccupied);
  const Costmap block_costmap = makeCostmap(block);
  EXPECT_EQ(planner.plan(block_costmap, block.geometry().centerOf({30, 30}), {3.5, 0.2}).status,
            PlanStatus::kStartBlocked);
}

TEST(AStarPlannerTest, OutsideOrNonFiniteEndpointsAreBlocked) {
  const OccupancyGrid grid = makeGrid(40, 40, CellState::kFree, {1.0, 1.0});
  const Costmap costmap = makeCostmap(grid);
  AStarPlanner planner;
  const Vec2 inside{2.0, 2.0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Vec2& bad : {Vec2(0.99, 2.0), Vec2(2.0, 3.0), Vec2(1e300, 2.0), Vec2(-1e300, -1e300),
                          Vec2(nan, 2.0), Vec2(2.0, inf)}) {
    EXPECT_EQ(planner.plan(costmap, bad, inside).status, PlanStatus::kStartBlocked);
    EXPECT_EQ(planner.plan(costmap, inside, bad).status, PlanStatus::kGoalBlocked);
  }
  Costmap empty;
  EXPECT_EQ(planner.plan(empty, inside, inside).status, PlanStatus::kStartBlocked);
}

TEST(AStarPlannerTest, AllowUnknownFalseAvoidsUnknownCells) {
  // An unknown band across the direct route, with a known free opening near the top.
  OccupancyGrid grid = makeGrid(80, 60, CellState::kFree);
  fillRect(grid, 30, 0, 50, 50, CellState::kUnknown);
  const Costmap costmap = makeCostmap(grid);
  const Vec2 start{0.525, 0.525}, goal{3.525, 0.525};  // cell centres

  AStarOptions options;
  const PlanResult optimistic = AStarPlanner(options).plan(costmap, start, goal);
  ASSERT_EQ(optimistic.status, PlanStatus::kFound);
  expectWellFormed(costmap, optimistic.path);
  EXPECT_NEAR(optimistic.path.length_m, 3.0, 1e-6);

  options.allow_unknown = false;
  const PlanResult cautious = AStarPlanner(options).plan(costmap, start, goal);
  ASSERT_EQ(cautious.status, PlanStatus::kFound);
  expectWellFormed(costmap, cautious.path, false);
  EXPECT_GT(cautious.path.length_m, 4.0);

  // With the band closing the map there is no known route.
  fillRect(grid, 30, 50, 50, 60, CellState::kUnknown);
  const Costmap closed = makeCostmap(grid);
  EXPECT_EQ(AStarPlanner(options).plan(closed, start, goal).status, PlanStatus::kNoPath);
  // A goal deep in unknown space is blocked for the cautious planner.
  EXPECT_EQ(AStarPlanner(options).plan(closed, start, {2.0, 1.5}).status, PlanStatus::kGoalBlocked);
}

TEST(AStarPlannerTest, RandomMapsGiveOptimalWellFormedPaths) {
  std::mt19937 rng(1234);
  AStarPlanner planner;  // reused across maps of different sizes
  int found = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const int w = 40 + trial % 7 * 5, h = 35 + trial % 5 * 6;
    OccupancyGrid grid = makeGrid(w, h, CellState::kFree);
    std::uniform_int_distribution<int> xs(0, w - 1), ys(0, h - 1), len(2, 15);
    for (int k = 0; k < 25; ++k) {
      const int x = xs(rng), y = ys(rng);
      const CellState s = k % 5 == 0 ? CellState::kUnknown : CellState::kOccupied;
      if (k % 2) {
        fillRect(grid, x, y, std::min(w, x + len(rng)), std::min(h, y + 1), s);
      } else {
        fillRect(grid, x, y, std::min(w, x + 1), std::min(h, y + len(rng)), s);
      }
    }
    const Costmap costmap = makeCostmap(grid);
    const GridGeometry& g = grid.geometry();
    const Cell start{xs(rng), ys(rng)}, goal{xs(rng), ys(rng)};
    if (costmap.isLethal(start) || costmap.isLethal(goal)) continue;
    const PlanResult r = planner.plan(costmap, g.centerOf(start), g.centerOf(goal));
    const double reference = referenceCost(costmap, start, goal);
    if (!std::isfinite(reference)) {
      EXPECT_EQ(r.status, PlanStatus::kNoPath) << "trial " << trial;
      continue;
    }
    ASSERT_EQ(r.status, PlanStatus::kFound) << "trial " << trial;
    expectWellFormed(costmap, r.path);
    EXPECT_NEAR(pathCost(costmap, r.path), reference, 1e-4 * reference + 1e-6) << "trial " << trial;
    ++found;
  }
  EXPECT_GT(found, 20);
}

TEST(AStarPlannerTest, PathIsClearNoticesNewObstacles) {
  OccupancyGrid grid = makeGrid(60, 20, CellState::kFree);
  const Costmap costmap = makeCostmap(grid);
  AStarPlanner planner;
  const PlanResult r = planner.plan(costmap, {0.2, 0.5}, {2.8, 0.5});
  ASSERT_EQ(r.status, PlanStatus::kFound);
  EXPECT_TRUE(AStarPlanner::pathIsClear(costmap, r.path));

  grid.setState(grid.geometry().index({30, 10}), CellState::kOccupied);
  const Costmap changed = makeCostmap(grid);
  EXPECT_FALSE(AStarPlanner::pathIsClear(changed, r.path));
  std::size_t past = 0;
  while (r.path.waypoints_m[past].x() < 1.8) ++past;
  EXPECT_TRUE(AStarPlanner::pathIsClear(changed, r.path, past));
  EXPECT_TRUE(AStarPlanner::pathIsClear(changed, r.path, r.path.waypoints_m.size()));
  Path outside;
  outside.waypoints_m = {{-5.0, 0.0}};
  EXPECT_FALSE(AStarPlanner::pathIsClear(changed, outside));
}

TEST(AStarPlannerTest, OptionsAreValidated) {
  AStarOptions options;
  EXPECT_NO_THROW(options.validate());
  options.goal_tolerance_m = -0.1;
  EXPECT_THROW(options.validate(), OptionError);
  EXPECT_THROW(AStarPlanner{options}, OptionError);
  options.goal_tolerance_m = std::nan("");
  EXPECT_THROW(options.validate(), OptionError);

  AStarOptions fresh;
  const std::vector<ParameterRef> parameters = fresh.parameters();
  ASSERT_EQ(parameters.size(), 2u);
  EXPECT_EQ(parameters[0].name, "goal_tolerance_m");
  EXPECT_EQ(std::get<double*>(parameters[0].value), &fresh.goal_tolerance_m);
  EXPECT_EQ(parameters[1].name, "allow_unknown");
  EXPECT_EQ(std::get<bool*>(parameters[1].value), &fresh.allow_unknown);
  for (const ParameterRef& p : parameters) EXPECT_FALSE(p.doc.empty());
}

}  // namespace
}  // namespace roomscout
