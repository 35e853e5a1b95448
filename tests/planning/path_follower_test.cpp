#include "roomscout/planning/path_follower.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"
#include "roomscout/planning/astar_planner.hpp"

namespace roomscout {
namespace {

constexpr double kDt_s = 0.05;

// A path along the polyline `corners` with a waypoint every `spacing_m` (as the planner gives).
Path densePath(const std::vector<Vec2>& corners, double spacing_m = 0.05) {
  Path path;
  path.waypoints_m.push_back(corners.front());
  for (std::size_t i = 1; i < corners.size(); ++i) {
    const Vec2 d = corners[i] - corners[i - 1];
    const int steps = std::max(1, static_cast<int>(std::ceil(d.norm() / spacing_m - 1e-9)));
    for (int k = 1; k <= steps; ++k) path.waypoints_m.push_back(corners[i - 1] + d * k / steps);
    path.length_m += d.norm();
  }
  return path;
}

double distanceToPolyline(const Vec2& p, const std::vector<Vec2>& w) {
  if (w.size() == 1) return (p - w[0]).norm();
  double best = 1e9;
  for (std::size_t i = 1; i < w.size(); ++i) {
    const Vec2 d = w[i] - w[i - 1];
    const double t = std::clamp((p - w[i - 1]).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
    best = std::min(best, (p - (w[i - 1] + t * d)).norm());
  }
  return best;
}

struct SimResult {
  bool reached = false;
  double time_s = 0.0;
  double max_linear_mps = 0.0;
  double min_linear_mps = 0.0;
  double max_abs_angular_radps = 0.0;
  double max_deviation_m = 0.0;
  Pose2 final_pose;
};

// Drives an ideal unicycle with the follower's commands until it reports the goal reached.
SimResult simulate(PathFollower& follower, Pose2 pose, double max_time_s) {
  SimResult result;
  std::size_t last_progress = 0;
  for (double t = 0.0; t < max_time_s; t += kDt_s) {
    if (follower.reached(pose)) {
      result.reached = true;
      result.time_s = t;
      break;
    }
    const VelocityCommand cmd = follower.compute(pose);
    EXPECT_GE(follower.progressIndex(), last_progress) << "progress went back at t=" << t;
    last_progress = follower.progressIndex();
    result.max_linear_mps = std::max(result.max_linear_mps, cmd.linear_mps);
    result.min_linear_mps = std::min(result.min_linear_mps, cmd.linear_mps);
    result.max_abs_angular_radps =
        std::max(result.max_abs_angular_radps, std::abs(cmd.angular_radps));
    pose.x_m += cmd.linear_mps * std::cos(pose.yaw_rad) * kDt_s;
    pose.y_m += cmd.linear_mps * std::sin(pose.yaw_rad) * kDt_s;
    pose.yaw_rad = wrapAngle(pose.yaw_rad + cmd.angular_radps * kDt_s);
    result.max_deviation_m = std::max(
        result.max_deviation_m, distanceToPolyline(pose.position(), follower.path().waypoints_m));
  }
  result.final_pose = pose;
  return result;
}

void expectGoodRun(const SimResult& r, const PathFollowerOptions& options, const Path& path,
                   double max_time_s) {
  EXPECT_TRUE(r.reached) << "not reached after " << max_time_s << " s";
  EXPECT_LE(r.time_s, max_time_s);
  // It did drive the path rather than finding itself at the end early.
  EXPECT_GE(r.time_s, 0.6 * path.length_m / options.max_linear_speed_mps);
  EXPECT_LE((r.final_pose.position() - path.waypoints_m.back()).norm(), options.goal_tolerance_m);
  EXPECT_LE(r.max_linear_mps, options.max_linear_speed_mps + 1e-12);
  EXPECT_GE(r.min_linear_mps, 0.0);
  EXPECT_LE(r.max_abs_angular_radps, options.max_angular_speed_radps + 1e-12);
  EXPECT_LE(r.max_deviation_m, 0.25);
}

// Generous time bound: the path at full speed, plus time for turning and slowing down.
double timeBound_s(const Path& path, const PathFollowerOptions& options) {
  return 1.5 * path.length_m / options.max_linear_speed_mps + 10.0;
}

TEST(PathFollowerTest, FollowsAnLShapedPath) {
  const std::vector<Vec2> corners{{0, 0}, {3, 0}, {3, 2}};
  for (const Path& path : {densePath(corners), densePath(corners, 10.0)}) {
    for (const double yaw_rad : {0.0, M_PI / 2, M_PI, -2.5}) {
      PathFollowerOptions options;
      PathFollower follower(options);
      follower.setPath(path);
      const SimResult r = simulate(follower, {0.0, 0.0, yaw_rad}, 60.0);
      SCOPED_TRACE(testing::Message()
                   << "yaw " << yaw_rad << ", " << path.waypoints_m.size() << " waypoints");
      expectGoodRun(r, options, path, timeBound_s(path, options));
      EXPECT_GT(r.max_linear_mps, 0.9 * options.max_linear_speed_mps);  // it does speed up
    }
  }
}

TEST(PathFollowerTest, FollowsAUTurnPath) {
  for (const double width_m : {0.6, 0.3}) {
    const Path path = densePath({{0, 0}, {2, 0}, {2, width_m}, {0, width_m}});
    PathFollowerOptions options;
    PathFollower follower(options);
    follower.setPath(path);
    const SimResult r = simulate(follower, {0.0, 0.0, 0.0}, 60.0);
    SCOPED_TRACE(testing::Message() << "width " << width_m);
    expectGoodRun(r, options, path, timeBound_s(path, options));
  }
}

TEST(PathFollowerTest, FollowsAHairpinThatDoublesBack) {
  // Into a dead end and straight back out along the same line, then off to the side.
  const std::vector<Vec2> corners{{0, 0}, {3, 0}, {2, 0}, {2, 1}};
  for (const Path& path : {densePath(corners), densePath(corners, 10.0)}) {
    PathFollowerOptions options;
    PathFollower follower(options);
    follower.setPath(path);
    const SimResult r = simulate(follower, {0.0, 0.0, 0.0}, 60.0);
    SCOPED_TRACE(testing::Message() << path.waypoints_m.size() << " waypoints");
    expectGoodRun(r, options, path, timeBound_s(path, options));
  }
}

TEST(PathFollowerTest, RespectsOtherLimits) {
  PathFollowerOptions options;
  options.max_linear_speed_mps = 0.5;
  options.max_angular_speed_radps = 0.7;
  options.heading_gain = 4.0;
  options.lookahead_m = 0.3;
  options.goal_tolerance_m = 0.05;
  const Path path = densePath({{0, 0}, {1.5, 0}, {1.5, 1.5}, {3, 1.5}});
  PathFollower follower(options);
  follower.setPath(path);
  const SimResult r = simulate(follower, {0.0, 0.0, M_PI}, 60.0);
  expectGoodRun(r, options, path, timeBound_s(path, options));
}

TEST(PathFollowerTest, FollowsAPlannedPathAroundAWall) {
  OccupancyGrid grid(GridGeometry({0, 0}, 0.05, 100, 80));
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) {
    const Cell c = grid.geometry().cellAt(i);
    const bool wall = c.x >= 48 && c.x < 52 && c.y < 55;
    grid.setState(i, wall ? CellState::kOccupied : CellState::kFree);
  }
  Costmap costmap;
  costmap.update(grid);
  AStarPlanner planner;
  const PlanResult plan = planner.plan(costmap, {1.0, 0.5}, {4.0, 0.5});
  ASSERT_EQ(plan.status, PlanStatus::kFound);
  PathFollowerOptions options;
  PathFollower follower(options);
  follower.setPath(plan.path);
  const SimResult r = simulate(follower, {1.0, 0.5, 0.0}, 120.0);
  expectGoodRun(r, options, plan.path, timeBound_s(plan.path, options));
}

TEST(PathFollowerTest, RotatesInPlaceWhenThePathIsBehind) {
  PathFollowerOptions options;
  PathFollower follower(options);
  follower.setPath(densePath({{0, 0}, {2, 0}}));
  for (const double yaw_rad : {2.0, -2.0, 1.0, -1.0}) {
    const VelocityCommand cmd = follower.compute({0.0, 0.0, yaw_rad});
    EXPECT_EQ(cmd.linear_mps, 0.0) << yaw_rad;
    EXPECT_LT(cmd.angular_radps * yaw_rad, 0.0) << "should turn back towards +x";
    EXPECT_LE(std::abs(cmd.angular_radps), options.max_angular_speed_radps);
    EXPECT_NEAR(std::abs(cmd.angular_radps),
                std::min(options.max_angular_speed_radps, options.heading_gain * std::abs(yaw_rad)),
                1e-9);
  }
  const VelocityCommand behind = follower.compute({0.0, 0.0, M_PI});
  EXPECT_EQ(behind.linear_mps, 0.0);
  EXPECT_NEAR(std::abs(behind.angular_radps), options.max_angular_speed_radps, 1e-9);
  const VelocityCommand small = follower.compute({0.0, 0.0, 0.3});
  EXPECT_GT(small.linear_mps, 0.0);
  EXPECT_NEAR(small.linear_mps, options.max_linear_speed_mps * std::cos(0.3), 1e-9);
  EXPECT_NEAR(small.angular_radps, -options.heading_gain * 0.3, 1e-9);
}

TEST(PathFollowerTest, SlowsDownNearTheGoalButKeepsMoving) {
  PathFollowerOptions options;
  options.goal_tolerance_m = 0.02;
  PathFollower follower(options);
  follower.setPath(densePath({{0, 0}, {1, 0}}));
  EXPECT_NEAR(follower.compute({0.0, 0.0, 0.0}).linear_mps, options.max_linear_speed_mps, 1e-12);
  EXPECT_NEAR(follower.compute({0.4, 0.0, 0.0}).linear_mps, options.max_linear_speed_mps, 1e-12);
  EXPECT_NEAR(follower.compute({0.8, 0.0, 0.0}).linear_mps, 0.2, 1e-9);
  EXPECT_NEAR(follower.compute({0.9, 0.0, 0.0}).linear_mps, 0.1, 1e-9);
  EXPECT_NEAR(follower.compute({0.97, 0.0, 0.0}).linear_mps, 0.05, 1e-9);
  EXPECT_FALSE(follower.reached({0.97, 0.0, 0.0}));
  EXPECT_TRUE(follower.reached({0.99, 0.0, 0.0}));
  const VelocityCommand at_goal = follower.compute({0.99, 0.0, 0.0});
  EXPECT_EQ(at_goal.linear_mps, 0.0);
  EXPECT_EQ(at_goal.angular_radps, 0.0);
}

TEST(PathFollowerTest, ProgressTracksTheRobotAndNeverGoesBack) {
  PathFollower follower;
  const Path path = densePath({{0, 0}, {2, 0}});  // waypoint i at x = 0.05 i
  follower.setPath(path);
  EXPECT_EQ(follower.progressIndex(), 0u);
  follower.compute({0.52, 0.01, 0.0});
  EXPECT_EQ(follower.progressIndex(), 10u);
  follower.compute({0.2, 0.0, 0.0});  // the robot was pushed back
  EXPECT_EQ(follower.progressIndex(), 10u);
  follower.compute({5.0, 0.0, 0.0});  // far beyond the window ahead: no jump to the end
  EXPECT_LE(follower.progressIndex(), 25u);
  follower.setPath(path);
  EXPECT_EQ(follower.progressIndex(), 0u);
}

TEST(PathFollowerTest, NoPathMeansNoMotion) {
  PathFollower follower;
  EXPECT_FALSE(follower.hasPath());
  EXPECT_FALSE(follower.reached({}));
  VelocityCommand cmd = follower.compute({1.0, 1.0, 0.0});
  EXPECT_EQ(cmd.linear_mps, 0.0);
  EXPECT_EQ(cmd.angular_radps, 0.0);
  follower.setPath(densePath({{0, 0}, {1, 0}}));
  EXPECT_TRUE(follower.hasPath());
  follower.clear();
  EXPECT_FALSE(follower.hasPath());
  cmd = follower.compute({0.0, 0.0, 0.0});
  EXPECT_EQ(cmd.linear_mps, 0.0);
  // A single-waypoint path is a goal to drive to.
  Path single;
  single.waypoints_m = {{1.0, 0.0}};
  follower.setPath(single);
  EXPECT_GT(follower.compute({0.0, 0.0, 0.0}).linear_mps, 0.0);
}

TEST(PathFollowerTest, OptionsAreValidated) {
  const auto throws = [](auto mutate) {
    PathFollowerOptions options;
    mutate(options);
    EXPECT_THROW(options.validate(), OptionError);
    EXPECT_THROW(PathFollower{options}, OptionError);
  };
  throws([](PathFollowerOptions& o) { o.max_linear_speed_mps = 0.0; });
  throws([](PathFollowerOptions& o) { o.max_angular_speed_radps = -1.0; });
  throws([](PathFollowerOptions& o) { o.lookahead_m = std::nan(""); });
  throws([](PathFollowerOptions& o) { o.goal_tolerance_m = 0.0; });
  throws([](PathFollowerOptions& o) { o.rotate_in_place_rad = 4.0; });
  throws([](PathFollowerOptions& o) { o.heading_gain = INFINITY; });
  EXPECT_NO_THROW(PathFollowerOptions{}.validate());

  PathFollowerOptions options;
  const std::vector<ParameterRef> parameters = options.parameters();
  ASSERT_EQ(parameters.size(), 6u);
  for (const ParameterRef& p : parameters) {
    EXPECT_FALSE(p.doc.empty()) << p.name;
    *std::get<double*>(p.value) = 7.0;
  }
  EXPECT_EQ(options.max_linear_speed_mps, 7.0);
  EXPECT_EQ(options.max_angular_speed_radps, 7.0);
  EXPECT_EQ(options.lookahead_m, 7.0);
  EXPECT_EQ(options.goal_tolerance_m, 7.0);
  EXPECT_EQ(options.rotate_in_place_rad, 7.0);
  EXPECT_EQ(options.heading_gain, 7.0);
}

}  // namespace
}  // namespace roomscout
