// Strategies on a map that grows as a SLAM map does (slam_toolbox, gmapping, Cartographer): the
// grid handed to decide() covers the known cells plus a margin, so it grows on every side while
// the robot explores and its origin moves by whole cells; the margin also changes, so that a
// grid sometimes shrinks on every side too. Every goal must lie inside the grid of its call and
// outside the lethal zone of its costmap, and the strategy must explore the whole plan.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "../maps/synthetic_maps.hpp"
#include "roomscout/core/grid_remap.hpp"
#include "roomscout/exploration/detail/improved_rrt.hpp"
#include "roomscout/exploration/detail/rrt_exploration.hpp"
#include "roomscout/exploration/detail/rrt_tree.hpp"
#include "roomscout/exploration/detail/semantic_explorer.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/maps/grid_image.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "roomscout/planning/astar_planner.hpp"

namespace roomscout {
namespace {

constexpr double kRes = test::kRes;

/// test::threeRoomsAndCorridor (16.4 x 10.4 m, origin (0, 0)) seen little by little: a cell is
/// known (with its true state) once the robot has been within a sight radius of it. Walls do
/// not block the sight: this is about the map's frame, not about the sensor.
class GrowingMap {
 public:
  GrowingMap()
      : plan_(test::threeRoomsAndCorridor()),
        seen_(GridGeometry(Vec2::Zero(), kRes, plan_.cols, plan_.rows)) {}

  const GridGeometry& planGeometry() const { return seen_.geometry(); }

  void reveal(const Vec2& p_m, double radius_m) {
    const GridGeometry& g = seen_.geometry();
    const Cell c = g.cellOf(p_m);
    const int r = static_cast<int>(std::ceil(radius_m / kRes));
    for (int y = std::max(0, c.y - r); y <= std::min(g.height() - 1, c.y + r); ++y) {
      for (int x = std::max(0, c.x - r); x <= std::min(g.width() - 1, c.x + r); ++x) {
        if ((g.centerOf(Cell{x, y}) - p_m).norm() > radius_m) continue;
        const std::size_t i = g.index(Cell{x, y});
        if (seen_.isUnknown(i)) seen_.setState(i, truth(Cell{x, y}));
      }
    }
  }

  CellState truth(Cell c) const {
    if (!seen_.geometry().contains(c)) return CellState::kOccupied;
    return static_cast<CellState>(plan_.at<std::uint8_t>(c.y, c.x));
  }
  CellState truth(const Vec2& p_m) const { return truth(seen_.geometry().cellOf(p_m)); }

  /// The geometry of the SLAM map: the box of the known cells grown by `pad` cells on each side
  /// (beyond the plan too, as a SLAM map is not bounded by the building).
  GridGeometry frame(int pad) const {
    const cv::Rect known = maps::knownBounds(maps::stateView(seen_), 0);
    const Vec2 origin = Vec2((known.x - pad) * kRes, (known.y - pad) * kRes);
    return GridGeometry(origin, kRes, known.width + 2 * pad, known.height + 2 * pad);
  }
  OccupancyGrid grid(int pad) const { return seen_.reframed(frame(pad)); }
  /// The known box grown by at least `pad` cells, its corners on even cells of the plan's
  /// lattice: cells grouped by two (mmpf's coarse grid, semantic's path search) stay grouped
  /// as on a grid whose origin is on an even cell.
  GridGeometry evenFrame(int pad) const {
    const cv::Rect known = maps::knownBounds(maps::stateView(seen_), 0);
    const auto down = [](int v) { return v >= 0 ? v / 2 * 2 : -((-v + 1) / 2 * 2); };
    const int x0 = down(known.x - pad), y0 = down(known.y - pad);
    const int x1 = -down(-(known.br().x + pad)), y1 = -down(-(known.br().y + pad));
    return GridGeometry(Vec2(x0 * kRes, y0 * kRes), kRes, x1 - x0, y1 - y0);
  }
  const OccupancyGrid& seen() const { return seen_; }
  /// The same map at another resolution: each cell takes the state at its centre.
  OccupancyGrid grid(int pad, double resolution_m) const {
    if (resolution_m == kRes) return grid(pad);
    const GridGeometry f = frame(pad);
    const GridGeometry g(f.origin_m(), resolution_m,
                         static_cast<int>(std::ceil(f.width() * kRes / resolution_m)),
                         static_cast<int>(std::ceil(f.height() * kRes / resolution_m)));
    OccupancyGrid out(g);
    for (std::size_t i = 0; i < g.cellCount(); ++i) {
      const Cell c = seen_.geometry().cellOf(g.centerOf(g.cellAt(i)));
      if (seen_.geometry().contains(c)) out.setState(i, seen_.state(c));
    }
    return out;
  }

  /// Known share of the plan's free cells.
  double coverage() const {
    std::size_t free = 0, known = 0;
    for (int y = 0; y < plan_.rows; ++y) {
      for (int x = 0; x < plan_.cols; ++x) {
        if (truth(Cell{x, y}) != CellState::kFree) continue;
        ++free;
        known += !seen_.isUnknown(seen_.geometry().index(Cell{x, y}));
      }
    }
    return static_cast<double>(known) / static_cast<double>(free);
  }

 private:
  cv::Mat plan_;
  OccupancyGrid seen_;  ///< on the plan's frame
};

/// What a run on a growing map did.
struct GrowingRun {
  int decisions = 0;
  int goals = 0;
  int goals_off_grid = 0;
  int goals_lethal = 0;
  int geometry_changes = 0;
  /// Changes that moved the grid's sides: left and bottom outwards (origin decreasing), right
  /// and top outwards, and inwards (a smaller margin).
  int grew_left = 0, grew_down = 0, grew_right = 0, grew_up = 0, shrank = 0;
  bool done = false;
  double coverage = 0.0;
};

constexpr double kSight_m = 2.5;
constexpr double kStep_m = 1.5;  ///< the robot drives at most this far between decisions

/// The margin of the grid at decision `k`: mostly 10 cells, every fifth decision 16 (the grid
/// grows on every side) and every seventh 3 (it shrinks on every side).
int marginAt(int k) { return k % 7 == 6 ? 3 : (k % 5 == 4 ? 16 : 10); }

/// What one leg of driving toward a goal came to.
enum class Leg { kReached, kStopped, kDriving };

/// Drives the robot along `path` up to kStep_m, stopping short of a truly occupied cell, each
/// waypoint shifted by `off`, and reveals the map around where it ends.
Leg driveLeg(GrowingMap& map, Pose2& robot, const std::vector<Vec2>& path,
             const Vec2& off = Vec2::Zero()) {
  Vec2 at = robot.position();
  double driven = 0.0;
  std::size_t i = 0;
  for (; i < path.size(); ++i) {
    if (map.truth(path[i]) != CellState::kFree) break;
    driven += (path[i] - at).norm();
    at = path[i] + off;
    if (driven >= kStep_m) break;
  }
  const bool moved = (at - robot.position()).norm() > 1e-9;
  if (moved) robot = Pose2{at.x(), at.y(), std::atan2(at.y() - robot.y_m, at.x() - robot.x_m)};
  map.reveal(robot.position(), kSight_m);
  if (i + 1 >= path.size() && (path.empty() || map.truth(path.back()) == CellState::kFree))
    return Leg::kReached;
  return moved ? Leg::kDriving : Leg::kStopped;
}

/// Drives `strategy` through a growing map from the middle room until it ends or `max_steps`
/// decisions (1 s apart) were taken. The robot follows an A* path through the costmap toward each
/// goal, up to kStep_m per decision, and stops short of a truly occupied cell (the path may cross
/// unknown space).
GrowingRun runOnGrowingMap(
    ExplorationStrategy& strategy, int max_steps,
    double (*resolutionAt)(int) = [](int) { return kRes; }) {
  GrowingMap map;
  Pose2 robot{8.2, 6.0, -M_PI / 2};
  map.reveal(robot.position(), kSight_m);
  Costmap costmap;
  AStarPlanner planner;
  SemanticMap rooms;
  GrowingRun run;
  GridGeometry last;
  for (int k = 0; k < max_steps; ++k) {
    const OccupancyGrid grid = map.grid(marginAt(k), resolutionAt(k));
    const GridGeometry& g = grid.geometry();
    if (k > 0 && !(g == last)) {
      ++run.geometry_changes;
      run.grew_left += g.origin_m().x() < last.origin_m().x() - 1e-9;
      run.grew_down += g.origin_m().y() < last.origin_m().y() - 1e-9;
      run.grew_right += farCorner(g).x() > farCorner(last).x() + 1e-9;
      run.grew_up += farCorner(g).y() > farCorner(last).y() + 1e-9;
      run.shrank += g.origin_m().x() > last.origin_m().x() + 1e-9 &&
                    farCorner(g).x() < farCorner(last).x() - 1e-9;
    }
    last = g;
    costmap.update(grid);
    // The rooms lag behind the grid (a runner segments about once a second, in the background):
    // every third decision, so that the rooms' geometry is often not the grid's.
    if (strategy.readsRooms() && k % 3 == 0) {
      rooms.update(g, RoomSegmenter().segment(grid).labels, maps::stateView(grid));
    }
    const ExplorationInput input{grid, costmap, robot, static_cast<double>(k),
                                 strategy.readsRooms() ? &rooms : nullptr};
    const Decision d = strategy.decide(input);
    ++run.decisions;
    if (d.status == Decision::Status::kDone) {
      run.done = true;
      break;
    }
    ++run.goals;
    const Cell c = g.cellOf(d.goal_m);
    if (!g.contains(c)) {
      ++run.goals_off_grid;
      strategy.onGoalFailed(d.goal_m);
      continue;
    }
    if (costmap.isLethal(g.index(c)) || grid.isOccupied(g.index(c))) ++run.goals_lethal;

    const PlanResult plan = planner.plan(costmap, robot.position(), d.goal_m);
    if (plan.status != PlanStatus::kFound) {
      strategy.onGoalFailed(d.goal_m);
      continue;
    }
    const Leg leg = driveLeg(map, robot, plan.path.waypoints_m);
    if (leg == Leg::kReached) {
      strategy.onGoalReached(d.goal_m);
    } else if (leg == Leg::kStopped) {
      strategy.onGoalFailed(d.goal_m);
    }
  }
  run.coverage = map.coverage();
  return run;
}

class GrowingMapTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GrowingMapTest, ExploresTheWholePlanWithGoalsInsideEachGrid) {
  auto strategy = createStrategy(GetParam(), 5);
  const GrowingRun run = runOnGrowingMap(*strategy, 260);
  // The grids did change, on every side and both ways.
  EXPECT_GT(run.geometry_changes, 20);
  EXPECT_GT(run.grew_left, 0);
  EXPECT_GT(run.grew_down, 0);
  EXPECT_GT(run.grew_right, 0);
  EXPECT_GT(run.grew_up, 0);
  EXPECT_GT(run.shrank, 0);
  EXPECT_GT(run.goals, 10);
  EXPECT_EQ(run.goals_off_grid, 0) << "of " << run.goals;
  EXPECT_EQ(run.goals_lethal, 0) << "of " << run.goals;
  // Exploration went on into the parts of the plan each new grid added.
  EXPECT_GE(run.coverage, 0.97) << run.decisions << " decisions, done " << run.done;
}

// The resolution of a map normally stays, but a strategy given another one must go on: its
// per-cell state is laid on the new cells (or reset) and nothing is read out of bounds.
TEST_P(GrowingMapTest, GoesOnWhenTheResolutionChanges) {
  auto strategy = createStrategy(GetParam(), 5);
  const GrowingRun run = runOnGrowingMap(
      *strategy, 40, [](int k) { return k % 10 < 5 ? kRes : (k % 20 < 10 ? 0.1 : 0.04); });
  EXPECT_GT(run.geometry_changes, 5);
  EXPECT_GT(run.goals, 5);
  EXPECT_EQ(run.goals_off_grid, 0) << "of " << run.goals;
  EXPECT_EQ(run.goals_lethal, 0) << "of " << run.goals;
  // Each change of resolution costs the strategy its per-cell state (laid on the new cells or
  // reset), so some goals, but not the exploration: it covers most of what the same 40
  // decisions cover at one resolution (measured: 0.78 to 1.12 times as much, every method).
  auto same_strategy = createStrategy(GetParam(), 5);
  const GrowingRun one_resolution = runOnGrowingMap(*same_strategy, 40);
  EXPECT_GE(run.coverage, 0.7 * one_resolution.coverage)
      << "one resolution: " << one_resolution.coverage;
}

INSTANTIATE_TEST_SUITE_P(Registered, GrowingMapTest, ::testing::ValuesIn(strategyNames()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

/// Drives two copies of a strategy (same seed) through the same exploration: one on a constant
/// grid that holds every map of the run (the plan with 3 m around it), the other on the same
/// maps framed as a growing SLAM map with a margin of 24 to 40 cells. The robot follows the
/// first copy's goals (as runOnGrowingMap does) and both are told the same outcomes. Returns
/// the first decision at which they differ, -1 when none does; `decisions` gets their number.
int firstDifference(const std::string& name, int max_steps, int& decisions) {
  GrowingMap map;
  // Off the cell centres, so that no two cells lie at exactly the same distance from the robot
  // (the choice between such twins turns on the last bit of their centres, which depends on the
  // grid's origin).
  const Vec2 off(0.0123, 0.0071);
  Pose2 robot{8.2 + off.x(), 6.0 + off.y(), -M_PI / 2};
  map.reveal(robot.position(), kSight_m);
  const int around = 60;
  const GridGeometry constant(Vec2(-around * kRes, -around * kRes), kRes,
                              map.planGeometry().width() + 2 * around,
                              map.planGeometry().height() + 2 * around);
  auto fixed = createStrategy(name, 11), growing = createStrategy(name, 11);
  Costmap fixed_costmap, growing_costmap;
  SemanticMap fixed_rooms, growing_rooms;
  AStarPlanner planner;
  decisions = 0;
  for (int k = 0; k < max_steps; ++k) {
    const OccupancyGrid a = map.seen().reframed(constant);
    const OccupancyGrid b = map.seen().reframed(map.evenFrame(k % 3 == 2 ? 40 : (k % 2 ? 24 : 30)));
    fixed_costmap.update(a);
    growing_costmap.update(b);
    if (fixed->readsRooms() && k % 3 == 0) {
      fixed_rooms.update(a.geometry(), RoomSegmenter().segment(a).labels, maps::stateView(a));
      growing_rooms.update(b.geometry(), RoomSegmenter().segment(b).labels, maps::stateView(b));
    }
    const double t = static_cast<double>(k);
    const Decision da =
        fixed->decide({a, fixed_costmap, robot, t, fixed->readsRooms() ? &fixed_rooms : nullptr});
    const Decision db = growing->decide(
        {b, growing_costmap, robot, t, growing->readsRooms() ? &growing_rooms : nullptr});
    ++decisions;
    if (da.status != db.status) return k;
    if (da.status == Decision::Status::kDone) return -1;
    if ((da.goal_m - db.goal_m).norm() > 1e-6) return k;
    const PlanResult plan = planner.plan(fixed_costmap, robot.position(), da.goal_m);
    if (plan.status != PlanStatus::kFound) {
      fixed->onGoalFailed(da.goal_m);
      growing->onGoalFailed(db.goal_m);
      continue;
    }
    const Leg leg = driveLeg(map, robot, plan.path.waypoints_m, off);
    if (leg == Leg::kReached) {
      fixed->onGoalReached(da.goal_m);
      growing->onGoalReached(db.goal_m);
    } else if (leg == Leg::kStopped) {
      fixed->onGoalFailed(da.goal_m);
      growing->onGoalFailed(db.goal_m);
    }
  }
  return -1;
}

// What a strategy keeps between calls (marks on cells, frontier points, tree nodes) it keeps by
// map position, so on a growing map it decides as on a constant grid holding the same maps.
// Not for the strategies whose choice depends on the grid's extent by design: rrt's detectors
// sample over the whole grid (as the original's over the map it is given), topo clips its goal
// (6 m past a frontier) to the grid, and mmpf's goal is snapped from the centre of a cell of its
// coarse grid, which lies on a corner of four map cells: which one it falls in turns on the last
// bit of the grid's origin.
TEST_P(GrowingMapTest, DecidesAsOnAConstantGridHoldingTheSameMaps) {
  for (const char* extent_bound : {"rrt", "topo", "mmpf"}) {
    if (GetParam() == extent_bound) GTEST_SKIP() << "its choice depends on the grid's extent";
  }
  int decisions = 0;
  const int k = firstDifference(GetParam(), 120, decisions);
  EXPECT_EQ(k, -1) << "the decisions differ at decision " << k;
  EXPECT_GT(decisions, 20);
}

/// Whether `p_m` lies inside the grid of `g`.
bool inside(const GridGeometry& g, const Vec2& p_m) { return g.contains(g.cellOf(p_m)); }

std::size_t pointsOutside(const SemanticExplorer& s, const GridGeometry& g) {
  return static_cast<std::size_t>(std::count_if(s.frontierPoints().begin(),
                                                s.frontierPoints().end(),
                                                [&](const auto& f) { return !inside(g, f.p); }));
}
std::size_t nodesOutside(const RrtTree& tree, const GridGeometry& g) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < tree.size(); ++i) n += !inside(g, tree.node(i));
  return n;
}

// The semantic strategy keeps frontier points (with a byte per cell marking where they lie) and
// a tree over the map. A grid that loses part of the map drops the points and nodes there (a
// point off the grid once wrote its mark outside the array); a grid that grows has its new part
// explored: tree, points and goals follow it.
TEST(SemanticExplorerOnGrowingMap, DropsWhatACroppedGridLosesAndExploresWhatAGrownOneAdds) {
  GrowingMap map;
  const Pose2 west{2.7, 6.0, 0.0};
  map.reveal(west.position(), 3.0);
  SemanticExplorerOptions options;
  options.tree.iterations_per_s = 1000.0;
  SemanticExplorer s(3, options);
  Costmap costmap;
  SemanticMap rooms;
  auto decideOn = [&](const OccupancyGrid& grid, const Pose2& robot, double t) {
    costmap.update(grid);
    rooms.update(grid.geometry(), RoomSegmenter().segment(grid).labels, maps::stateView(grid));
    const Decision d = s.decide({grid, costmap, robot, t, &rooms});
    if (d.status == Decision::Status::kGoal) {
      const GridGeometry& g = grid.geometry();
      EXPECT_TRUE(inside(g, d.goal_m)) << "t " << t;
      EXPECT_FALSE(costmap.isLethal(g.cellOf(d.goal_m)))
          << "t " << t;  // off the grid counts as lethal
    }
    return d;
  };

  const OccupancyGrid a = map.grid(10);
  decideOn(a, west, 0.0);
  decideOn(a, west, 10.0);
  ASSERT_NE(s.tree(), nullptr);
  ASSERT_FALSE(s.frontierPoints().empty());
  const std::size_t points_before = s.frontierPoints().size();

  // B: the same map without its southern 2 m (the origin moves north, the grid shrinks).
  const GridGeometry& ga = a.geometry();
  const int cut = static_cast<int>(std::lround(2.0 / kRes));
  const OccupancyGrid b = a.reframed(
      GridGeometry(ga.origin_m() + Vec2(0.0, cut * kRes), kRes, ga.width(), ga.height() - cut));
  const GridGeometry& gb = b.geometry();
  ASSERT_GT(pointsOutside(s, gb), 0u) << "the crop must cut off some points";
  ASSERT_GT(nodesOutside(*s.tree(), gb), 0u) << "and some tree nodes";
  decideOn(b, west, 11.0);
  EXPECT_EQ(pointsOutside(s, gb), 0u);
  EXPECT_EQ(nodesOutside(*s.tree(), gb), 0u);
  EXPECT_GT(s.tree()->size(), 1u);
  EXPECT_LT(s.frontierPoints().size(), points_before);
  decideOn(b, west, 15.0);
  EXPECT_EQ(pointsOutside(s, gb), 0u);
  EXPECT_EQ(nodesOutside(*s.tree(), gb), 0u);

  // C: the robot went south through the door into the corridor and east along it; the map
  // grew on every side (a wider margin too) and its origin moved south-west.
  for (const Vec2& p : {Vec2(2.6, 3.5), Vec2(2.6, 1.2), Vec2(5.0, 1.2), Vec2(8.2, 1.2)})
    map.reveal(p, 2.5);
  const OccupancyGrid c = map.grid(20);
  const GridGeometry& gc = c.geometry();
  ASSERT_LT(gc.origin_m().x(), ga.origin_m().x());
  ASSERT_LT(gc.origin_m().y(), gb.origin_m().y());
  ASSERT_GT(farCorner(gc).x(), farCorner(ga).x());
  const double grown_east_of_m = farCorner(ga).x();
  const Pose2 corridor{8.2, 1.2, 0.0};
  int goals_in_new_part = 0;
  for (int k = 0; k < 20; ++k) {
    const Decision d = decideOn(c, corridor, 16.0 + 2.0 * k);
    ASSERT_EQ(d.status, Decision::Status::kGoal) << "k " << k;
    goals_in_new_part += d.goal_m.x() > grown_east_of_m;
    s.onGoalReached(d.goal_m);  // whatever is left unknown there cannot be seen from there
    EXPECT_EQ(pointsOutside(s, gc), 0u);
  }
  EXPECT_GE(goals_in_new_part, 5);
  const auto east = [&](const Vec2& p) { return p.x() > grown_east_of_m; };
  EXPECT_TRUE(std::any_of(s.frontierPoints().begin(), s.frontierPoints().end(),
                          [&](const auto& f) { return east(f.p); }));
  std::size_t east_nodes = 0;
  for (std::size_t i = 0; i < s.tree()->size(); ++i) east_nodes += east(s.tree()->node(i));
  EXPECT_GT(east_nodes, 10u);
}

// rrt's detectors sample over the grid they were first given; improved_rrt's over the known
// box. On a grid cut short their trees keep only the nodes on it, and on a grid grown past the
// first one they grow into the new part.
template <class Strategy>
void treesFollowTheGrid(Strategy& s, const std::function<std::vector<const RrtTree*>()>& trees) {
  GrowingMap map;
  const Pose2 west{2.7, 6.0, 0.0};
  map.reveal(west.position(), 3.0);
  Costmap costmap;
  const auto decideOn = [&](const OccupancyGrid& grid, const Pose2& robot, double t) {
    costmap.update(grid);
    const Decision d = s.decide({grid, costmap, robot, t});
    if (d.status == Decision::Status::kGoal) {
      EXPECT_FALSE(costmap.isLethal(grid.geometry().cellOf(d.goal_m))) << "t " << t;
      s.onGoalReached(d.goal_m);
    }
  };
  const auto nodesOff = [&](const GridGeometry& g) {
    std::size_t n = 0;
    for (const RrtTree* tree : trees()) n += nodesOutside(*tree, g);
    return n;
  };
  const OccupancyGrid a = map.grid(10);
  decideOn(a, west, 0.0);
  decideOn(a, west, 20.0);
  const GridGeometry& ga = a.geometry();
  const int cut = static_cast<int>(std::lround(2.0 / kRes));
  const OccupancyGrid b = a.reframed(
      GridGeometry(ga.origin_m() + Vec2(0.0, cut * kRes), kRes, ga.width(), ga.height() - cut));
  ASSERT_GT(nodesOff(b.geometry()), 0u) << "the crop must cut off some nodes";
  decideOn(b, west, 21.0);
  EXPECT_EQ(nodesOff(b.geometry()), 0u);
  for (const RrtTree* tree : trees()) EXPECT_FALSE(tree->empty());

  for (const Vec2& p : {Vec2(2.6, 3.5), Vec2(2.6, 1.2), Vec2(5.0, 1.2), Vec2(8.2, 1.2)})
    map.reveal(p, 2.5);
  const OccupancyGrid c = map.grid(20);
  const Pose2 corridor{8.2, 1.2, 0.0};
  for (int k = 0; k < 10; ++k) decideOn(c, corridor, 22.0 + 2.0 * k);
  EXPECT_EQ(nodesOff(c.geometry()), 0u);
  std::size_t east = 0;
  for (const RrtTree* tree : trees()) {
    for (std::size_t i = 0; i < tree->size(); ++i) east += tree->node(i).x() > farCorner(ga).x();
  }
  EXPECT_GT(east, 10u);
}

TEST(RrtOnGrowingMap, TreesKeepToTheGridAndGrowIntoItsNewPart) {
  RrtExploration rrt(4);
  treesFollowTheGrid(rrt, [&] {
    return std::vector<const RrtTree*>{rrt.globalTree(), rrt.localTree()};
  });
  ImprovedRrt improved(4);
  treesFollowTheGrid(improved, [&] { return std::vector<const RrtTree*>{improved.tree()}; });
}

}  // namespace
}  // namespace roomscout
