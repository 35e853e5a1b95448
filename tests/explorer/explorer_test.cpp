// The Explorer driven as a robot drives it: a hand-made map that grows and moves, goal
// outcomes reported back, bad input rejected with the value named.

#include "roomscout/explorer/explorer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"

namespace roomscout {
namespace {

/// Three rooms in a row, 4 x 4 m each, joined by 1 m doors; walls 0.1 m thick.
bool isWall(const Vec2& p) {
  if (p.x() < 0.0 || p.x() > 12.0 || p.y() < 0.0 || p.y() > 4.0) return true;
  const bool border = p.x() < 0.1 || p.x() > 11.9 || p.y() < 0.1 || p.y() > 3.9;
  const bool partition =
      (std::abs(p.x() - 4.0) < 0.05 || std::abs(p.x() - 8.0) < 0.05) && std::abs(p.y() - 2.0) > 0.5;
  return border || partition;
}

LaserScan measure(const Pose2& pose) {
  LaserScan scan;
  scan.angle_increment_rad = 2.0 * M_PI / 360;
  for (int i = 0; i < 360; ++i) {
    const double a = pose.yaw_rad + i * scan.angle_increment_rad;
    float range = std::numeric_limits<float>::infinity();
    for (double r = 0.0; r <= scan.range_max_m; r += 0.02) {
      if (isWall(pose.position() + r * Vec2(std::cos(a), std::sin(a)))) {
        range = static_cast<float>(r);
        break;
      }
    }
    scan.ranges_m.push_back(range);
  }
  return scan;
}

/// A toy robot: maps into a large grid as SLAM would, shows the Explorer the known part plus
/// a 1 m margin, and hops 0.1 m along the commanded path per 0.25 s cycle.
struct ToyRobot {
  OccupancyGrid slam{GridGeometry(Vec2(-3.0, -3.0), 0.05, 360, 200)};
  OccupancyMapper mapper{slam};
  CellRect known;
  Pose2 pose{1.0, 2.0, 0.0};

  OccupancyGrid sense() {
    known.unite(mapper.integrate(measure(pose), pose));
    const CellRect crop =
        CellRect{known.min_x - 20, known.min_y - 20, known.max_x + 20, known.max_y + 20}.clippedTo(
            slam.geometry().width(), slam.geometry().height());
    const GridGeometry& g = slam.geometry();
    const Vec2 origin = g.origin_m() + Vec2(crop.min_x, crop.min_y) * g.resolution_m();
    return slam.reframed(
        GridGeometry(origin, g.resolution_m(), crop.max_x - crop.min_x, crop.max_y - crop.min_y));
  }
  /// Hops 0.1 m toward the first waypoint at least that far beyond the one nearest the robot.
  void drive(const Path& path) {
    const std::vector<Vec2>& w = path.waypoints_m;
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < w.size(); ++i) {
      if ((w[i] - pose.position()).norm() < (w[nearest] - pose.position()).norm()) nearest = i;
    }
    for (std::size_t i = nearest; i < w.size(); ++i) {
      const Vec2 step = w[i] - pose.position();
      if (step.norm() < 0.1 && i + 1 < w.size()) continue;
      const Vec2 next = pose.position() + step.normalized() * std::min(0.1, step.norm());
      pose = Pose2{next.x(), next.y(), std::atan2(step.y(), step.x())};
      return;
    }
  }
};

/// Free cells of the toy world the map knows to be free, over all its free cells.
double knownFreeFraction(const OccupancyGrid& map) {
  int free = 0, known = 0;
  for (double y = 0.325; y < 4.0; y += 0.05) {
    for (double x = 0.325; x < 12.0; x += 0.05) {
      const Vec2 p(x, y);
      bool near_wall = false;
      for (double dx = -0.2; dx <= 0.2 && !near_wall; dx += 0.1)
        for (double dy = -0.2; dy <= 0.2 && !near_wall; dy += 0.1)
          near_wall = isWall(p + Vec2(dx, dy));
      if (near_wall) continue;
      ++free;
      const Cell c = map.geometry().cellOf(p);
      known += map.geometry().contains(c) && map.state(c) == CellState::kFree;
    }
  }
  return static_cast<double>(known) / free;
}

struct LoopResult {
  bool done = false;
  int geometry_changes = 0;
  int goals_outside = 0;
  double known_free = 0.0;
  OccupancyGrid last_map;
};

LoopResult explore(const std::string& method) {
  ToyRobot robot;
  Explorer explorer(createStrategy(method, 1));
  LoopResult r;
  GridGeometry last;
  for (double t = 0.0; t < 900.0; t += 0.25) {
    const OccupancyGrid map = robot.sense();
    if (map.geometry() != last) ++r.geometry_changes;
    last = map.geometry();
    const ExplorerCommand c = explorer.update({map, robot.pose, t});
    r.last_map = map;
    if (c.kind == ExplorerCommand::Kind::kDone) {
      r.done = true;
      break;
    }
    if (c.kind != ExplorerCommand::Kind::kDrive) continue;
    EXPECT_NE(c.path, nullptr);
    if (!map.geometry().contains(c.goal_m)) ++r.goals_outside;
    robot.drive(*c.path);
  }
  explorer.finish(r.last_map);
  r.known_free = knownFreeFraction(r.last_map);
  return r;
}

TEST(Explorer, ExploresAHandMadeMapThatGrowsAndMoves) {
  for (const std::string method : {"nearest_frontier", "semantic"}) {
    const LoopResult r = explore(method);
    EXPECT_TRUE(r.done) << method;
    EXPECT_GE(r.known_free, 0.95) << method;
    EXPECT_GT(r.geometry_changes, 10) << method << ": the map should have grown many times";
    EXPECT_EQ(r.goals_outside, 0) << method;
  }
}

TEST(Explorer, BuildsRoomsThatKeepTheirIdsAndColoursAsTheMapGrows) {
  ToyRobot robot;
  robot.pose = Pose2{10.0, 2.0, M_PI};  // the east room: the map grows west, its origin moves
  Explorer explorer(createStrategy("nearest_frontier", 1));
  ASSERT_NE(explorer.roomMap(), nullptr);
  ASSERT_NE(explorer.skeletonMap(), nullptr);
  const SemanticMap& rooms = *explorer.roomMap()->semanticMap();
  int first_room = 0;
  std::array<std::uint8_t, 3> first_colour{};
  GridGeometry first_geometry;
  OccupancyGrid map;
  bool done = false;
  for (double t = 0.0; t < 900.0 && !done; t += 0.25) {
    map = robot.sense();
    const ExplorerCommand c = explorer.update({map, robot.pose, t});
    if (first_room == 0 && rooms.roomAt(Vec2(10.0, 2.0)) != 0) {
      first_room = rooms.roomAt(Vec2(10.0, 2.0));
      first_colour = rooms.region(first_room)->rgb;
      first_geometry = rooms.geometry();
    }
    done = c.kind == ExplorerCommand::Kind::kDone;
    if (c.kind == ExplorerCommand::Kind::kDrive) robot.drive(*c.path);
  }
  ASSERT_TRUE(done);
  explorer.finish(map);
  ASSERT_NE(first_room, 0);
  EXPECT_EQ(rooms.geometry(), map.geometry());
  EXPECT_NE(first_geometry.origin_m(), map.geometry().origin_m()) << "the map should have moved";
  EXPECT_GT(map.geometry().width(), first_geometry.width());
  EXPECT_EQ(rooms.roomAt(Vec2(10.0, 2.0)), first_room);
  EXPECT_EQ(rooms.region(first_room)->rgb, first_colour);
  // Three rooms, three ids.
  EXPECT_NE(rooms.roomAt(Vec2(6.0, 2.0)), first_room);
  EXPECT_NE(rooms.roomAt(Vec2(6.0, 2.0)), 0);
  EXPECT_NE(rooms.roomAt(Vec2(2.0, 2.0)), rooms.roomAt(Vec2(6.0, 2.0)));
  EXPECT_NE(rooms.roomAt(Vec2(2.0, 2.0)), 0);
  EXPECT_FALSE(explorer.skeletonMap()->topologicalMap().nodes().empty());
}

TEST(Explorer, ABlockedRobotBacksOffThenGetsANewGoal) {
  ToyRobot robot;
  robot.pose = Pose2{6.0, 2.0, 0.0};  // the middle room: a door to explore on either side
  ExplorerOptions options;
  options.goals.recovery_time_s = 1.0;
  Explorer explorer(createStrategy("nearest_frontier", 1), options);
  const OccupancyGrid map = robot.sense();
  const ExplorerCommand first = explorer.update({map, robot.pose, 10.0});
  ASSERT_EQ(first.kind, ExplorerCommand::Kind::kDrive);
  explorer.report(GoalOutcome::kBlocked, 10.0);
  EXPECT_EQ(explorer.stats().recoveries, 1);
  EXPECT_EQ(explorer.stats().goal_failures, 1);
  EXPECT_FALSE(explorer.goal().has_value());
  EXPECT_EQ(explorer.update({map, robot.pose, 10.5}).kind, ExplorerCommand::Kind::kBackOff);
  const ExplorerCommand after = explorer.update({map, robot.pose, 11.0});
  ASSERT_EQ(after.kind, ExplorerCommand::Kind::kDrive);
  EXPECT_TRUE(after.new_path);
  EXPECT_GT((after.goal_m - first.goal_m).norm(), 2.0)
      << "the failed goal's door should be given up";
  explorer.report(GoalOutcome::kReached, 11.0);
  EXPECT_FALSE(explorer.goal().has_value());
}

TEST(Explorer, AGoalWithoutProgressFails) {
  ToyRobot robot;
  ExplorerOptions options;
  options.goals.no_progress_timeout_s = 5.0;
  Explorer explorer(createStrategy("nearest_frontier", 1), options);
  const OccupancyGrid map = robot.sense();
  // The robot never moves: after the timeout its goal fails and it is given another. The
  // watchdog measures at the call where the timeout has passed and fails the goal at the next
  // one, so the first failure falls in (5 s, 5.5 s].
  int drives = 0;
  double first_failure_s = -1.0;
  for (double t = 0.0; t < 7.0; t += 0.25) {
    drives +=
        explorer.update({map, robot.pose, t, CellRect{}}).kind == ExplorerCommand::Kind::kDrive;
    if (first_failure_s < 0.0 && explorer.stats().goal_failures > 0) first_failure_s = t;
  }
  EXPECT_GE(drives, 20);
  EXPECT_GT(first_failure_s, 5.0);
  EXPECT_LE(first_failure_s, 5.5);
}

/// Always the same goal.
class FixedGoal final : public ExplorationStrategy {
 public:
  explicit FixedGoal(const Vec2& goal_m) : goal_m_(goal_m) {}
  std::string_view name() const override { return "fixed_goal"; }
  Decision decide(const ExplorationInput& /*input*/) override { return Decision::goal(goal_m_); }

 private:
  Vec2 goal_m_;
};

/// A map 10 x 4 m, unknown but for a free strip from x = 0.5 m to x = 0.5 m + `free_length_m`
/// along y in [0.5, 1.5] m: its known free area is `free_length_m` square metres.
OccupancyGrid stripMap(double free_length_m) {
  OccupancyGrid grid(GridGeometry(Vec2::Zero(), 0.05, 200, 80));
  const GridGeometry& g = grid.geometry();
  for (int y = 10; y < 30; ++y) {
    for (int x = 10; x < 10 + static_cast<int>(std::lround(free_length_m / 0.05)); ++x)
      grid.setState(g.index(Cell{x, y}), CellState::kFree);
  }
  return grid;
}

/// Drives the stall watchdog for `duration_s` with a fixed goal the robot never reaches (the
/// no-progress watchdog is out of the way): the map's free strip is `length_m(t)` long and the
/// robot stands at `robot_at(t)`. Returns the times at which a goal stalled.
template <class Length, class Position>
std::vector<double> stallTimes(ExplorerOptions options, double duration_s, Length length_m,
                               Position robot_at) {
  options.goals.no_progress_timeout_s = 1000.0;
  options.goals.stall_timeout_s = 10.0;
  FixedGoal strategy(Vec2(1.5, 1.0));
  Explorer explorer(strategy, options);
  std::vector<double> stalls;
  for (double t = 0.0; t <= duration_s + 1e-9; t += 0.25) {
    const OccupancyGrid map = stripMap(length_m(t));
    const Vec2 p = robot_at(t);
    explorer.update({map, Pose2{p.x(), p.y(), 0.0}, t});
    if (explorer.stats().stalls > static_cast<int>(stalls.size())) stalls.push_back(t);
  }
  return stalls;
}

TEST(Explorer, StallWatchdogFailsTheGoalOfARobotThatStaysAndSeesNothingNew) {
  // Checked once a second over windows of stall_timeout_s (10 s) from the first call: the goal
  // stalls at the end of each window, at 10 s and 20 s.
  const auto still = [](double) { return Vec2(1.0, 1.0); };
  const std::vector<double> stalls = stallTimes(
      ExplorerOptions{}, 25.0, [](double) { return 3.0; }, still);
  ASSERT_EQ(stalls.size(), 2u);
  EXPECT_DOUBLE_EQ(stalls[0], 10.0);
  EXPECT_DOUBLE_EQ(stalls[1], 20.0);
  // The map loses free cells (noise blurring walls): still no growth, still stalled.
  EXPECT_EQ(stallTimes(
                ExplorerOptions{}, 25.0, [](double t) { return 6.0 - 0.1 * t; }, still)
                .size(),
            2u);
}

TEST(Explorer, StallWatchdogSparesARobotThatSeesNewSpaceOrTravels) {
  const auto still = [](double) { return Vec2(1.0, 1.0); };
  // 0.2 m^2 of new free space a second: 2 m^2 a window, more than stall_min_new_area_m2 (1).
  EXPECT_TRUE(stallTimes(
                  ExplorerOptions{}, 25.0, [](double t) { return 2.0 + 0.2 * t; }, still)
                  .empty());
  // Shuttling 2 m back and forth, farther than a 1 m stall radius, in a map that never grows.
  ExplorerOptions small_radius;
  small_radius.goals.stall_radius_m = 1.0;
  const auto shuttle = [](double t) {
    return Vec2(1.0 + 2.0 * std::abs(std::fmod(t, 8.0) - 4.0) / 4.0, 1.0);
  };
  EXPECT_TRUE(stallTimes(
                  small_radius, 25.0, [](double) { return 3.0; }, shuttle)
                  .empty());
  // stall_min_new_area_m2: 0 never stalls, even in a map that loses free cells.
  ExplorerOptions off;
  off.goals.stall_min_new_area_m2 = 0.0;
  EXPECT_TRUE(stallTimes(
                  off, 25.0, [](double t) { return 6.0 - 0.1 * t; }, still)
                  .empty());
}

TEST(Explorer, ProgressIsMeasuredAlongTheDriversPathWhenItReportsOne) {
  // The driver takes a detour: 1.5 m away from the goal first. Along the Explorer's own path
  // the robot loses ground and the goal fails; along the driver's it makes progress.
  ToyRobot robot;
  robot.pose = Pose2{6.0, 2.0, 0.0};
  const OccupancyGrid map = robot.sense();
  const Vec2 start = robot.pose.position(), goal(9.0, 2.0), away(4.5, 2.0);
  Path detour;
  for (double s = 0.0; s <= 1.5 + 1e-9; s += 0.05)
    detour.waypoints_m.push_back(start + Vec2(-s, 0));
  for (double s = 0.05; s <= 4.5 + 1e-9; s += 0.05) detour.waypoints_m.push_back(away + Vec2(s, 0));
  ExplorerOptions options;
  options.goals.no_progress_timeout_s = 5.0;
  auto failures = [&](bool report_driver_path) {
    FixedGoal strategy(goal);
    Explorer explorer(strategy, options);
    for (double t = 0.0; t <= 7.5; t += 0.25) {
      const Vec2 p = start + Vec2(-0.2 * t, 0.0);
      ExplorerInput in(map, Pose2{p.x(), p.y(), M_PI}, t, CellRect{});
      if (report_driver_path) in.driver_path = &detour;
      EXPECT_EQ(explorer.update(in).kind, ExplorerCommand::Kind::kDrive) << t;
    }
    return explorer.stats().goal_failures;
  };
  EXPECT_GE(failures(false), 1);
  EXPECT_EQ(failures(true), 0);
}

TEST(Explorer, RejectsBadInputNamingTheValue) {
  ToyRobot robot;
  const OccupancyGrid map = robot.sense();
  Explorer explorer(createStrategy("nearest_frontier", 1));
  const OccupancyGrid empty(GridGeometry(Vec2::Zero(), 0.05, 0, 10));
  try {
    explorer.update({empty, robot.pose, 0.0});
    FAIL() << "an empty grid was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("0 x 10"), std::string::npos) << e.what();
  }
  try {
    explorer.update({map, Pose2{NAN, 1.0, 0.0}, 0.0});
    FAIL() << "a NaN pose was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("nan"), std::string::npos) << e.what();
  }
  EXPECT_THROW(explorer.update({map, robot.pose, INFINITY}), InvalidArgument);
  EXPECT_NO_THROW(explorer.update({map, robot.pose, 100.0}));
  try {
    explorer.update({map, robot.pose, 99.0});
    FAIL() << "time going backwards was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("99.0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(explorer.report(GoalOutcome::kFailed, 50.0), InvalidArgument);
  // A resolution <= 0 cannot even make a grid.
  EXPECT_THROW(GridGeometry(Vec2::Zero(), 0.0, 10, 10), InvalidArgument);
  EXPECT_THROW(GridGeometry(Vec2::Zero(), -0.05, 10, 10), InvalidArgument);
  // A robot outside the map waits until the map covers it.
  const ExplorerCommand outside = explorer.update({map, Pose2{50.0, 50.0, 0.0}, 101.0});
  EXPECT_EQ(outside.kind, ExplorerCommand::Kind::kWait);
  EXPECT_EQ(outside.reason, "robot outside the map");
  EXPECT_NE(explorer.update({map, robot.pose, 102.0}).kind, ExplorerCommand::Kind::kWait);
}

TEST(Explorer, OptionsComeFromTheConfigGroupsAndAreChecked) {
  ExplorerOptions options;
  std::vector<std::string> names;
  for (const ParameterGroup& g : options.groups()) names.push_back(g.name);
  for (const char* group : {"costmap", "planner", "explorer", "maps", "segmentation", "topology"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), group), names.end()) << group;
  }
  options.goals.no_progress_timeout_s = 0.0;
  EXPECT_THROW(Explorer(createStrategy("nearest_frontier", 1), options), OptionError);
}

}  // namespace
}  // namespace roomscout
