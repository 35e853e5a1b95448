#include "roomscout/sim/laser_simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "roomscout/core/errors.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

// Distance from p along direction angle to the inside faces of the square room's walls.
double analyticSquare(const Vec2& p, double angle, double inner_lo, double inner_hi) {
  const double dx = std::cos(angle), dy = std::sin(angle);
  double t = std::numeric_limits<double>::infinity();
  if (dx > 1e-12) t = std::min(t, (inner_hi - p.x()) / dx);
  if (dx < -1e-12) t = std::min(t, (inner_lo - p.x()) / dx);
  if (dy > 1e-12) t = std::min(t, (inner_hi - p.y()) / dy);
  if (dy < -1e-12) t = std::min(t, (inner_lo - p.y()) / dy);
  return t;
}

TEST(LaserSimulator, RayDistancesMatchAnalyticWalls) {
  const WorldModel model(testing::squareRoom(10.0, 0.2));
  LaserOptions options;
  options.range_max_m = 20.0;
  LaserSimulator laser(model, options, 1);
  const double tolerance = 1.5 * model.geometry().resolution_m();
  for (const Vec2& origin : {Vec2(5.0, 5.0), Vec2(2.3, 7.71), Vec2(8.9, 1.05)}) {
    for (int k = 0; k < 720; ++k) {
      const double angle = k * M_PI / 360.0 + 0.0013;
      const double expected = analyticSquare(origin, angle, 0.1, 9.9);
      EXPECT_NEAR(laser.castRay(origin, angle, 20.0), expected, tolerance) << "angle " << angle;
    }
  }
}

TEST(LaserSimulator, ScanReportsNoReturnBeyondMaxRange) {
  const WorldModel model(testing::squareRoom(10.0, 0.2));
  LaserSimulator laser(model, LaserOptions{}, 1);
  const LaserScan scan = laser.scan({5.0, 5.0, 0.0});
  ASSERT_EQ(scan.ranges_m.size(), 360u);
  for (float r : scan.ranges_m) EXPECT_TRUE(std::isinf(r));  // walls are 4.9 m away, range 3.5 m

  const LaserScan near = laser.scan({1.0, 5.0, 0.0});
  // Beam i points at yaw + angle_min + i * increment; beam 0 points along -x: wall at 0.9 m.
  EXPECT_NEAR(near.ranges_m[0], 0.9, 0.04);
}

TEST(LaserSimulator, TableTopIsInvisibleButLegsAndBlocksAreNot) {
  World w = testing::squareRoom(10.0, 0.2);
  // A table top over (6..7, 4..6) at 0.7-0.75 m, one leg at (6.0..6.05, 4.95..5.05) and a box.
  w.furniture.push_back({"top", {{6, 4}, {7, 4}, {7, 6}, {6, 6}}, 0.7, 0.75});
  w.furniture.push_back({"box", {{5, 7}, {5.5, 7}, {5.5, 7.5}, {5, 7.5}}, 0.0, 0.5});
  const WorldModel model(w);
  LaserSimulator laser(model, LaserOptions{}, 1);
  // Looking +x from (5, 4.5): passes under the top, hits the east wall at 9.9 (range 20).
  EXPECT_NEAR(laser.castRay({5.0, 4.5}, 0.0, 20.0), 4.9, 0.04);
  // Looking +y from (5.25, 5): hits the box's south face at y = 7.
  EXPECT_NEAR(laser.castRay({5.25, 5.0}, M_PI / 2, 20.0), 2.0, 0.04);
}

TEST(LaserSimulator, NoiseIsDeterministicForASeed) {
  const WorldModel model(testing::squareRoom(4.0, 0.2));
  const LaserOptions options;
  const RangeNoise noise{.sd_near_m = 0.02};
  LaserSimulator a(model, options, 7, noise), b(model, options, 7, noise),
      c(model, options, 8, noise);
  const Pose2 pose{2.0, 2.0, 0.3};
  const LaserScan sa = a.scan(pose), sb = b.scan(pose), sc = c.scan(pose);
  EXPECT_EQ(sa.ranges_m, sb.ranges_m);
  EXPECT_NE(sa.ranges_m, sc.ranges_m);
}

TEST(WorldModel, RejectsStartInsideAWall) {
  World w = testing::squareRoom(10.0, 0.2);
  w.start = {0.0, 5.0, 0.0};
  EXPECT_THROW(WorldModel{w}, InputError);
  w.start = {50.0, 5.0, 0.0};
  EXPECT_THROW(WorldModel{w}, InputError);
}

TEST(WorldModel, FreeAreaOfASquareRoom) {
  const WorldModel model(testing::squareRoom(10.0, 0.2));
  EXPECT_NEAR(model.freeArea_m2(), 9.8 * 9.8, 9.8 * 4 * 0.03);
  EXPECT_EQ(model.roomAt({5, 5}), 1);
  EXPECT_EQ(model.roomAt({-3, 5}), 0);
}

}  // namespace
}  // namespace roomscout::sim
