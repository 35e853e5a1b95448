// The inverse sensor model against walls seen at grazing angles: scans are computed by hand
// for straight walls, so the expected map is known exactly.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "roomscout/mapping/occupancy_mapper.hpp"

namespace roomscout {
namespace {

constexpr double kWallY = 1.01;  // the wall's face lies 1 cm into the cell row [1.00, 1.05)

/// A 360-beam scan from `pose` of the half-plane y >= kWallY, with an opening (no wall) for
/// x in [gap_from, gap_to]; beyond the opening a second wall at y = 3.
LaserScan scanOfWall(const Pose2& pose, std::optional<std::pair<double, double>> gap = {}) {
  LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi;
  scan.angle_increment_rad = 2.0 * std::numbers::pi / 360.0;
  scan.range_min_m = 0.12;
  scan.range_max_m = 3.5;
  for (int i = 0; i < 360; ++i) {
    const double a = pose.yaw_rad + scan.angle_min_rad + i * scan.angle_increment_rad;
    double r = std::numeric_limits<double>::infinity();
    if (std::sin(a) > 1e-9) {
      r = (kWallY - pose.y_m) / std::sin(a);
      const double x = pose.x_m + r * std::cos(a);
      if (gap && x > gap->first && x < gap->second) r = (3.0 - pose.y_m) / std::sin(a);
    }
    scan.ranges_m.push_back(
        static_cast<float>(r <= scan.range_max_m ? r : std::numeric_limits<double>::infinity()));
  }
  return scan;
}

class GrazingWall : public ::testing::Test {
 protected:
  GridGeometry geometry{Vec2(0.0, 0.0), 0.05, 200, 80};
  OccupancyGrid grid{geometry};
  OccupancyMapper mapper{grid};
  const int wall_row = static_cast<int>(std::floor(kWallY / 0.05));

  /// Drives along the wall 0.25 m from it, as in a 0.5 m corridor, from x0 to x1 at 0.044 m
  /// a scan (0.22 m/s, 5 Hz).
  void drive(double x0, double x1, std::optional<std::pair<double, double>> gap = {}) {
    const double step = x1 > x0 ? 0.044 : -0.044;
    for (double x = x0; (x1 - x) * step > 0.0; x += step) {
      const Pose2 pose{x, kWallY - 0.25, 0.0};
      mapper.integrate(scanOfWall(pose, gap), pose);
    }
  }
  int occupiedInRow(double x0, double x1) const {
    int n = 0;
    for (long x = std::lround(x0 / 0.05); x < std::lround(x1 / 0.05); ++x)
      n += grid.isOccupied(geometry.index({static_cast<int>(x), wall_row})) ? 1 : 0;
    return n;
  }
};

TEST_F(GrazingWall, StaysAWallWhenSeenAlongItsFace) {
  drive(0.5, 3.5);
  // Every cell of the stretch driven past was hit from close by.
  ASSERT_EQ(occupiedInRow(1.0, 3.0), 40);
  // Now the wall ends at x = 3.5 and the robot stands beyond its end, in line with its face,
  // 2 cm inside the wall's cell row: in open space, its beams return nothing, and those running
  // west cross the free part of the row's cells, beside the face.
  const Pose2 beyond{5.5, kWallY + 0.02, 0.0};
  LaserScan open = scanOfWall(beyond);
  std::fill(open.ranges_m.begin(), open.ranges_m.end(), std::numeric_limits<float>::infinity());
  for (int i = 0; i < 30; ++i) mapper.integrate(open, beyond);
  // Without the rule, 30 scans of misses would wear the reachable stretch (x > 2.0) down to free.
  EXPECT_EQ(occupiedInRow(1.0, 3.0), 40);
}

TEST_F(GrazingWall, AnOpeningSeenSquareOnIsCleared) {
  drive(0.5, 3.5);
  ASSERT_EQ(occupiedInRow(1.8, 2.2), 8);
  // The wall between x = 1.8 and 2.2 is gone (a door opened): beams cross the row there.
  for (int i = 0; i < 10; ++i) {
    const Pose2 pose{2.0, kWallY - 0.25, 0.0};
    mapper.integrate(scanOfWall(pose, std::pair{1.8, 2.2}), pose);
  }
  EXPECT_TRUE(grid.isFree(geometry.index({static_cast<int>(2.0 / 0.05), wall_row})));
  // The wall beside the opening stays.
  EXPECT_EQ(occupiedInRow(1.4, 1.8), 8);
}

}  // namespace
}  // namespace roomscout

namespace roomscout {
namespace {

TEST(OccupancyMapper, ScansWithoutValidReturnsAddNoWallAndNoFreeSpace) {
  const GridGeometry geometry{Vec2(-5.0, -5.0), 0.05, 200, 200};
  const Pose2 pose{0.0, 0.0, 0.3};
  LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi;
  scan.angle_increment_rad = 2.0 * std::numbers::pi / 360.0;
  scan.range_min_m = 0.12;
  scan.range_max_m = 3.5;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const float bad : {nan, -inf, 0.0f, 0.05f, 3.6f, 20.0f}) {
    OccupancyGrid grid(geometry);
    OccupancyMapper mapper(grid);
    scan.ranges_m.assign(360, bad);
    for (int i = 0; i < 3; ++i) mapper.integrate(scan, pose);
    for (std::size_t i = 0; i < geometry.cellCount(); ++i)
      ASSERT_TRUE(grid.isUnknown(i)) << "reading " << bad << " changed cell " << i;
  }
  // +inf is "nothing within range": free space up to range_max_m, no wall.
  OccupancyGrid grid(geometry);
  OccupancyMapper mapper(grid);
  scan.ranges_m.assign(360, inf);
  mapper.integrate(scan, pose);
  EXPECT_TRUE(grid.isFree(geometry.index(geometry.cellOf({3.3, 0.0}))));
  EXPECT_TRUE(grid.isUnknown(geometry.index(geometry.cellOf({3.7, 0.0}))));
  for (std::size_t i = 0; i < geometry.cellCount(); ++i) ASSERT_FALSE(grid.isOccupied(i));
}

}  // namespace
}  // namespace roomscout
