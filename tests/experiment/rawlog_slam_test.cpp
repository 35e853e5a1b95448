// A SLAM run over a log made here (no file): a drive in a box-shaped room, scanned exactly.

#include "roomscout/experiment/rawlog_slam.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"

namespace roomscout::experiment {
namespace {

/// Walls at x = kWall_m, kWall_m + kRoomX_m and y = kWall_m, kWall_m + kRoomY_m: in the middle
/// of a row of cells, as a wall on a cell border would put its points in either of two cells.
constexpr double kRoomX_m = 8.0, kRoomY_m = 6.0, kWall_m = 0.025;
constexpr int kBeams = 181;

/// The distance from `p` along `angle` to the room's walls.
float rangeToWalls(const Vec2& p, double angle) {
  const double dx = std::cos(angle), dy = std::sin(angle);
  double t = std::numeric_limits<double>::infinity();
  if (dx > 1e-9) t = std::min(t, (kWall_m + kRoomX_m - p.x()) / dx);
  if (dx < -1e-9) t = std::min(t, (kWall_m - p.x()) / dx);
  if (dy > 1e-9) t = std::min(t, (kWall_m + kRoomY_m - p.y()) / dy);
  if (dy < -1e-9) t = std::min(t, (kWall_m - p.y()) / dy);
  return static_cast<float>(t);
}

/// The robot's true poses: along y = 1.5 from x = 1.5 to 6.5, a quarter turn, up to y = 4.5.
std::vector<Pose2> truePath() {
  std::vector<Pose2> path;
  for (double x = 1.5; x <= 6.5 + 1e-9; x += 0.1) path.push_back({x, 1.5, 0.0});
  for (int k = 1; k <= 9; ++k) path.push_back({6.5, 1.5, k * M_PI / 18});
  for (double y = 1.6; y <= 4.5 + 1e-9; y += 0.1) path.push_back({6.5, y, M_PI / 2});
  return path;
}

/// The log of truePath(): a laser 0.2 m ahead of the robot's centre, exact ranges, the
/// odometry's heading wrong by `yaw_drift_rad` more at each scan, and every 10th scan from
/// the 5th on without a single return.
slam::Rawlog boxLog(double yaw_drift_rad) {
  const Pose2 T_robot_laser{0.2, 0.0, 0.0};
  const std::vector<Pose2> path = truePath();
  slam::Rawlog log;
  Pose2 odometry = path.front();
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (k > 0) {
      // The true increment, then the drift on top.
      Pose2 increment = between(path[k - 1], path[k]);
      increment.yaw_rad += yaw_drift_rad;
      odometry = compose(odometry, increment);
    }
    slam::RawlogScan scan;
    scan.T_robot_laser = T_robot_laser;
    scan.T_odom_robot = {odometry.x_m - path.front().x_m, odometry.y_m - path.front().y_m,
                         odometry.yaw_rad};
    scan.scan.angle_min_rad = -M_PI / 2;
    scan.scan.angle_increment_rad = M_PI / (kBeams - 1);
    scan.scan.range_min_m = 0.01;
    scan.scan.range_max_m = 10.0;
    const Pose2 laser = compose(path[k], T_robot_laser);
    const bool no_returns = k % 10 == 5;
    for (int i = 0; i < kBeams; ++i) {
      scan.scan.ranges_m.push_back(
          no_returns ? std::numeric_limits<float>::infinity()
                     : rangeToWalls(laser.position(), laser.yaw_rad + scan.scan.angle_min_rad +
                                                          i * scan.scan.angle_increment_rad));
    }
    log.scans_without_returns += no_returns;
    log.scans.push_back(std::move(scan));
  }
  return log;
}

/// The largest position error of `poses` against truePath(), both with the start at the origin.
double maxError_m(const std::vector<Pose2>& poses) {
  const std::vector<Pose2> path = truePath();
  double worst = 0.0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    worst = std::max(worst, std::hypot(poses[k].x_m - (path[k].x_m - path[0].x_m),
                                       poses[k].y_m - (path[k].y_m - path[0].y_m)));
  }
  return worst;
}

slam::SlamOptions icp() {
  slam::SlamOptions options;
  options.mode = "icp";
  return options;
}

TEST(RawlogSlamTest, ExactOdometryGivesPosesAndMapsThatFitTheScans) {
  const slam::Rawlog log = boxLog(0.0);
  const RawlogSlamResult r = runRawlogSlam(log, icp(), OccupancyGridOptions{}, 1, "box");
  ASSERT_EQ(r.T_map_robot.size(), log.scans.size());
  ASSERT_EQ(r.T_odom_robot.size(), log.scans.size());
  EXPECT_EQ(r.slam_updates, log.scans.size() - log.scans_without_returns);
  EXPECT_EQ(r.update.count, r.slam_updates);
  EXPECT_LT(maxError_m(r.T_odom_robot), 1e-9);
  EXPECT_LT(maxError_m(r.T_map_robot), 0.05);
  ASSERT_TRUE(r.slam_map.consistency.mean_distance_m);
  ASSERT_TRUE(r.odometry_map.consistency.mean_distance_m);
  EXPECT_LT(*r.odometry_map.consistency.mean_distance_m, 0.01);
  EXPECT_LT(*r.slam_map.consistency.mean_distance_m, 0.01);
  // The map covers the room (8 m x 6 m) and a metre around what the laser saw, no more.
  const GridGeometry& g = r.slam_map.grid.geometry();
  EXPECT_DOUBLE_EQ(g.resolution_m(), 0.05);
  EXPECT_NEAR(g.width() * 0.05, kRoomX_m + 2.0, 0.2);
  EXPECT_NEAR(g.height() * 0.05, kRoomY_m + 2.0, 0.2);
}

TEST(RawlogSlamTest, TheSlamMapFitsTheScansBetterThanDriftingOdometry) {
  const slam::Rawlog log = boxLog(0.01);  // 0.57 degrees more at every scan: 47 degrees in all
  const RawlogSlamResult r = runRawlogSlam(log, icp(), OccupancyGridOptions{}, 1, "box");
  EXPECT_GT(maxError_m(r.T_odom_robot), 1.0);
  EXPECT_LT(maxError_m(r.T_map_robot), 0.2);
  ASSERT_TRUE(r.slam_map.consistency.mean_distance_m);
  ASSERT_TRUE(r.odometry_map.consistency.mean_distance_m);
  EXPECT_LT(*r.slam_map.consistency.mean_distance_m,
            0.5 * *r.odometry_map.consistency.mean_distance_m);
  // A scan without returns follows the scan before it by odometry: its step is the odometry's.
  const std::size_t k = 15;
  ASSERT_EQ(k % 10, 5u);
  EXPECT_NEAR(std::hypot(r.T_map_robot[k].x_m - r.T_map_robot[k - 1].x_m,
                         r.T_map_robot[k].y_m - r.T_map_robot[k - 1].y_m),
              0.1, 1e-6);
}

TEST(RawlogSlamTest, RefusesModeNone) {
  slam::SlamOptions none;
  EXPECT_THROW(runRawlogSlam(boxLog(0.0), none, OccupancyGridOptions{}, 1, "box"), OptionError);
}

}  // namespace
}  // namespace roomscout::experiment
