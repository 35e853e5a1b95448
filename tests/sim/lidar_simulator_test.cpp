#include "roomscout/sim/lidar_simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "roomscout/core/errors.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

/// The square room (inner faces at 0.1 and 9.9 m) with a 1 m square table (top 0.71-0.75 m,
/// four 0.05 m legs at its corners) centred at (6.5, 5) and a lintel over a gap in the east wall.
World furnishedRoom() {
  World w = testing::squareRoom(10.0, 0.2);
  FurniturePiece top{"table_top", {{6.0, 4.5}, {7.0, 4.5}, {7.0, 5.5}, {6.0, 5.5}}, 0.71, 0.75};
  w.furniture.push_back(top);
  for (const Vec2 c : {Vec2(6.05, 4.55), Vec2(6.95, 4.55), Vec2(6.95, 5.45), Vec2(6.05, 5.45)}) {
    const Vec2 h(0.025, 0.025);
    w.furniture.push_back({"leg", {c - h, Vec2(c.x() + h.x(), c.y() - h.y()), c + h, Vec2(c.x() - h.x(), c.y() + h.y())},
                           0.0, 0.71});
  }
  return w;
}

TEST(LidarSimulator, RingToAWallAtAKnownDistance) {
  const WorldModel model(testing::squareRoom(10.0, 0.2));
  const ColumnWorld columns(model);
  const LidarSimulator lidar(columns, {}, 1);
  const double tolerance = 1.5 * model.geometry().resolution_m();
  for (double elevation_deg : {-1.0, 1.0, 3.0, 7.0}) {
    const auto hit = lidar.castRay({5.0, 5.0, 0.5}, 0.0, elevation_deg * kDeg, 100.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->surface, LidarSurface::kObject);
    EXPECT_NEAR(hit->range_m * std::cos(elevation_deg * kDeg), 4.9, tolerance) << elevation_deg;
  }
  // Diagonal: the first wall face crossed, at 45 degrees.
  const auto diag = lidar.castRay({2.0, 3.0, 0.5}, 45.0 * kDeg, 0.0, 100.0);
  ASSERT_TRUE(diag);
  EXPECT_NEAR(diag->range_m, 6.9 * std::sqrt(2.0), tolerance * std::sqrt(2.0));
}

TEST(LidarSimulator, FloorAndCeilingAtKnownHeights) {
  const WorldModel model(testing::squareRoom(10.0, 0.2));
  const ColumnWorld columns(model);
  const LidarSimulator lidar(columns, {}, 1);
  const auto floor = lidar.castRay({5.0, 5.0, 0.5}, 0.3, -15.0 * kDeg, 100.0);
  ASSERT_TRUE(floor);
  EXPECT_EQ(floor->surface, LidarSurface::kFloor);
  EXPECT_NEAR(floor->range_m, 0.5 / std::sin(15.0 * kDeg), 1e-9);
  const auto ceiling = lidar.castRay({5.0, 5.0, 2.0}, 1.0, 15.0 * kDeg, 100.0);
  ASSERT_TRUE(ceiling);
  EXPECT_EQ(ceiling->surface, LidarSurface::kCeiling);
  EXPECT_NEAR(ceiling->range_m, 0.5 / std::sin(15.0 * kDeg), 1e-9);
  EXPECT_FALSE(lidar.castRay({5.0, 5.0, 0.5}, 0.3, -15.0 * kDeg, 1.0));  // beyond max range
}

TEST(LidarSimulator, TableTopAtAKnownHeightAndFreeUnderneath) {
  const WorldModel model(furnishedRoom());
  const ColumnWorld columns(model);
  const LidarSimulator lidar(columns, {}, 1);
  const double tolerance = 1e-6;
  // From 1 m high, down onto the top surface (z = 0.75) at x = 6.5.
  const double down = std::atan2(1.0 - 0.75, 1.5);
  auto hit = lidar.castRay({5.0, 5.0, 1.0}, 0.0, -down, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, std::hypot(1.5, 0.25), tolerance);
  // From 0.3 m, up onto the underside (z = 0.71) at x = 6.5.
  const double up = std::atan2(0.71 - 0.3, 1.5);
  hit = lidar.castRay({5.0, 5.0, 0.3}, 0.0, up, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, std::hypot(1.5, 0.41), tolerance);
  // Level at 0.3 m: between the legs, under the top, on to the wall.
  hit = lidar.castRay({5.0, 5.0, 0.3}, 0.0, 0.0, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, 4.9, 1.5 * model.geometry().resolution_m());
  // Level at 0.73 m: the top's edge face at x = 6.0.
  hit = lidar.castRay({5.0, 5.0, 0.73}, 0.0, 0.0, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m, 1.0, 1.5 * model.geometry().resolution_m());
}

TEST(LidarSimulator, DoorOpeningUnderALintel) {
  World w = testing::twoRooms();  // door in the x = 6 wall between y = 2 and 3
  w.walls.push_back({{6, 2.0}, {6, 3.0}, 0.2, 2.0, 2.5});  // the lintel
  const WorldModel model(w);
  const ColumnWorld columns(model);
  const LidarSimulator lidar(columns, {}, 1);
  const double tolerance = 1.5 * model.geometry().resolution_m();
  // Through the door at 0.5 m: to the east room's far wall (inner face 11.9).
  auto hit = lidar.castRay({3.0, 2.5, 0.5}, 0.0, 1.0 * kDeg, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m * std::cos(kDeg), 8.9, tolerance);
  // Aimed at 2.2 m on the door's face: the lintel (face at x = 5.9).
  const double elevation = std::atan2(2.2 - 0.5, 2.9);
  hit = lidar.castRay({3.0, 2.5, 0.5}, 0.0, elevation, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->range_m * std::cos(elevation), 2.9, tolerance);
}

TEST(LidarSimulator, ImageWorldsExtrudeSolidPixelsToTheWallHeight) {
  World w;
  w.name = "image";
  w.source = "test:image";
  ImageWorld img;
  img.resolution_m = 0.05;
  img.solid = cv::Mat::zeros(100, 100, CV_8U);
  img.solid.row(0).setTo(255);
  img.solid.row(99).setTo(255);
  img.solid.col(0).setTo(255);
  img.solid.col(99).setTo(255);
  w.image = img;
  const WorldModel model(w);
  const ColumnWorld columns(model);
  EXPECT_DOUBLE_EQ(columns.ceiling_m(), 2.5);
  const LidarSimulator lidar(columns, {}, 1);
  // Sensor at the centre (2.5, 2.5); the east wall's inner face is at x = 4.95.
  const auto hit = lidar.castRay({2.5, 2.5, 0.5}, 0.0, 3.0 * kDeg, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->surface, LidarSurface::kObject);
  EXPECT_NEAR(hit->range_m * std::cos(3.0 * kDeg), 2.45, 0.05);
  EXPECT_TRUE(columns.solidAt({4.97, 2.5, 2.4}));
  EXPECT_FALSE(columns.solidAt({2.5, 2.5, 2.4}));
}

TEST(LidarSimulator, ScanIsVlp16AndEveryPointLiesOnASurface) {
  const WorldModel model(furnishedRoom());
  const ColumnWorld columns(model);
  for (double noise_m : {0.0, 0.02}) {
    LidarOptions options;
    options.range_noise_m = noise_m;
    LidarSimulator lidar(columns, options, 7);
    EXPECT_EQ(lidar.columns(), 1800);
    const Pose2 pose{4.0, 3.0, 0.7};
    const LidarScan scan = lidar.scan(pose);
    // Closed room: every one of 16 x 1800 beams returns.
    EXPECT_EQ(scan.points_sensor.size(), 16u * 1800u);
    ASSERT_EQ(scan.surfaces.size(), scan.points_sensor.size());
    EXPECT_NEAR(scan.T_map_sensor.translation().z(), options.mount_height_m, 1e-12);
    const double tolerance = 5.0 * noise_m + 1e-3;
    int floor = 0, ceiling = 0;
    for (std::size_t i = 0; i < scan.points_sensor.size(); ++i) {
      const Eigen::Vector3d p_map = scan.T_map_sensor * scan.points_sensor[i].cast<double>();
      ASSERT_TRUE(columns.nearSurface(p_map, tolerance)) << p_map.transpose();
      if (scan.surfaces[i] == LidarSurface::kFloor) {
        ++floor;
        EXPECT_NEAR(p_map.z(), 0.0, tolerance);
      }
      if (scan.surfaces[i] == LidarSurface::kCeiling) {
        ++ceiling;
        EXPECT_NEAR(p_map.z(), 2.5, tolerance);
      }
    }
    EXPECT_GT(floor, 1000);
    EXPECT_GT(ceiling, 100);
  }
}

TEST(LidarSimulator, DeterministicForASeed) {
  const WorldModel model(testing::squareRoom(10.0, 0.2));
  const ColumnWorld columns(model);
  LidarOptions options;
  options.range_noise_m = 0.03;
  LidarSimulator a(columns, options, 11), b(columns, options, 11), c(columns, options, 12);
  const Pose2 pose{5.0, 5.0, 0.0};
  const LidarScan sa = a.scan(pose), sb = b.scan(pose), sc = c.scan(pose);
  ASSERT_EQ(sa.points_sensor.size(), sb.points_sensor.size());
  for (std::size_t i = 0; i < sa.points_sensor.size(); ++i) ASSERT_EQ(sa.points_sensor[i], sb.points_sensor[i]);
  bool differs = false;
  for (std::size_t i = 0; i < std::min(sa.points_sensor.size(), sc.points_sensor.size()); ++i) {
    differs |= sa.points_sensor[i] != sc.points_sensor[i];
  }
  EXPECT_TRUE(differs);
}

TEST(LidarSimulator, RejectsBadOptions) {
  LidarOptions o;
  o.num_rings = 0;
  EXPECT_THROW(o.validate(), OptionError);
  o = {};
  o.range_min_m = 200.0;
  EXPECT_THROW(o.validate(), OptionError);
  o = {};
  o.azimuth_step_deg = 0.0;
  EXPECT_THROW(o.validate(), OptionError);
  o = {};
  o.mount_height_m = -1.0;
  EXPECT_THROW(o.validate(), OptionError);
  EXPECT_NO_THROW(LidarOptions{}.validate());
}

}  // namespace
}  // namespace roomscout::sim
