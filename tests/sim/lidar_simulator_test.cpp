#include "roomscout/sim/lidar_simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "roomscout/core/errors.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
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
  for (const Vec2& c : {Vec2(6.05, 4.55), Vec2(6.95, 4.55), Vec2(6.95, 5.45), Vec2(6.05, 5.45)}) {
    const Vec2 h(0.025, 0.025);
    w.furniture.push_back(
        {"leg",
         {c - h, Vec2(c.x() + h.x(), c.y() - h.y()), c + h, Vec2(c.x() - h.x(), c.y() + h.y())},
         0.0,
         0.71});
  }
  return w;
}

/// One beam's first hit, cast the plain way (the DDA of the first LidarSimulator: every raster
/// cell visited, every span of every non-empty cell tested): the reference the optimised
/// caster must match bit for bit. Returns the horizontal distance and height above the sensor
/// of the hit and its surface, or a negative distance for no return.
struct ReferenceHit {
  double t_m = -1.0, dz_m = 0.0;
  LidarSurface surface = LidarSurface::kObject;
};

ReferenceHit referenceCast(const ColumnWorld& world, const Eigen::Vector2d& origin_m, double z_m,
                           double cos_az, double sin_az, double elevation_rad, double max_range_m) {
  const double inf = std::numeric_limits<double>::infinity();
  const double slope = std::tan(elevation_rad), cos_elev = std::cos(elevation_rad);
  double t_plane = inf;
  LidarSurface plane_surface = LidarSurface::kObject;
  if (slope > 0.0) {
    t_plane = (world.ceiling_m() - z_m) / slope;
    plane_surface = LidarSurface::kCeiling;
  } else if (slope < 0.0) {
    t_plane = (world.floor_m() - z_m) / slope;
    plane_surface = LidarSurface::kFloor;
  }
  const double t_range = max_range_m * cos_elev;
  const bool plane_hit = t_plane <= t_range;
  const double limit_m = std::max(0.0, std::min(t_plane, t_range));
  const GridGeometry& g = world.geometry();
  const double res = g.resolution_m();
  const Eigen::Vector2d p = (origin_m - g.origin_m()) / res;
  int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
  const int step_x = cos_az > 0 ? 1 : -1, step_y = sin_az > 0 ? 1 : -1;
  const double t_delta_x = cos_az != 0 ? std::abs(1.0 / cos_az) : inf;
  const double t_delta_y = sin_az != 0 ? std::abs(1.0 / sin_az) : inf;
  double t_max_x = cos_az != 0 ? (step_x > 0 ? (x + 1 - p.x()) : (p.x() - x)) * t_delta_x : inf;
  double t_max_y = sin_az != 0 ? (step_y > 0 ? (y + 1 - p.y()) : (p.y() - y)) * t_delta_y : inf;
  double t_in = 0.0;
  while (x >= 0 && y >= 0 && x < g.width() && y < g.height()) {
    const double t_out = std::min(t_max_x, t_max_y);
    const double t_in_m = t_in * res, t_out_m = t_out * res;
    const double t_end = std::min(t_out_m, limit_m);
    if (t_in_m <= t_end) {
      const double z_in = z_m + slope * t_in_m;
      double t_hit = inf, dz_hit = 0.0;
      for (const ZInterval& s : world.intervals(static_cast<std::size_t>(y) * g.width() + x)) {
        if (s.z_min_m <= z_in && z_in <= s.z_max_m) {
          t_hit = t_in_m;
          dz_hit = z_in - z_m;
          break;
        }
        if (slope > 0.0 && z_in < s.z_min_m && (s.z_min_m - z_m) / slope < t_hit) {
          t_hit = (s.z_min_m - z_m) / slope;
          dz_hit = s.z_min_m - z_m;
        } else if (slope < 0.0 && z_in > s.z_max_m && (s.z_max_m - z_m) / slope < t_hit) {
          t_hit = (s.z_max_m - z_m) / slope;
          dz_hit = s.z_max_m - z_m;
        }
      }
      if (t_hit <= t_end) return {t_hit, dz_hit, LidarSurface::kObject};
    }
    if (limit_m <= t_out_m) {
      if (!plane_hit) return {};
      return {limit_m,
              (plane_surface == LidarSurface::kFloor ? world.floor_m() : world.ceiling_m()) - z_m,
              plane_surface};
    }
    if (t_max_x < t_max_y) {
      t_max_x += t_delta_x;
      x += step_x;
    } else {
      t_max_y += t_delta_y;
      y += step_y;
    }
    t_in = t_out;
  }
  return {};
}

/// Random beams from free places of a world: castRay (one ring) and every point of scan()
/// (16 rings sharing a column's DDA, cells and rings skipped by bounds, empty squares
/// jumped) equal the plain cast bit for bit.
void expectSameAsReference(const World& w, int poses, std::uint32_t seed) {
  const WorldModel model(w);
  const ColumnWorld columns(model);
  LidarSimulator lidar(columns, {}, 1);
  const LidarOptions& o = lidar.options();
  const GridGeometry& g = columns.geometry();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(g.origin_m().x(),
                                            g.origin_m().x() + g.width() * g.resolution_m());
  std::uniform_real_distribution<double> uy(g.origin_m().y(),
                                            g.origin_m().y() + g.height() * g.resolution_m());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tested = 0;
  while (tested < poses) {
    const Pose2 pose{ux(rng), uy(rng), 2.0 * M_PI * unit(rng)};
    if (!model.robotFits(pose.position())) continue;
    ++tested;
    const Eigen::Vector3d origin = lidar.sensorPose(pose).translation();
    // Single beams at any elevation.
    for (int i = 0; i < 50; ++i) {
      const double az = 2.0 * M_PI * unit(rng), el = (unit(rng) - 0.5) * 40.0 * kDeg;
      const ReferenceHit ref = referenceCast(columns, origin.head<2>(), origin.z(), std::cos(az),
                                             std::sin(az), el, 100.0);
      const auto hit = lidar.castRay(origin, az, el, 100.0);
      ASSERT_EQ(hit.has_value(), ref.t_m >= 0.0)
          << pose.x_m << " " << pose.y_m << " az " << az << " el " << el;
      if (hit) {
        EXPECT_EQ(hit->range_m, ref.t_m / std::cos(el));
        EXPECT_EQ(hit->surface, ref.surface);
      }
    }
    // A whole revolution, point by point.
    const LidarScan scan = lidar.scan(pose);
    std::size_t next = 0;
    const double cy = std::cos(pose.yaw_rad), sy = std::sin(pose.yaw_rad);
    for (int c = 0; c < lidar.columns(); ++c) {
      const double a = 2.0 * M_PI * c / lidar.columns(), ca = std::cos(a), sa = std::sin(a);
      for (int k = 0; k < o.num_rings; ++k) {
        const double e = (o.elevation_min_deg +
                          (o.elevation_max_deg - o.elevation_min_deg) * k / (o.num_rings - 1)) *
                         (M_PI / 180.0);
        const ReferenceHit ref =
            referenceCast(columns, origin.head<2>(), origin.z(), cy * ca - sy * sa,
                          sy * ca + cy * sa, e, o.range_max_m);
        if (ref.t_m < 0.0) continue;
        const double r = ref.t_m / std::cos(e);
        if (r < o.range_min_m || r > o.range_max_m) continue;
        ASSERT_LT(next, scan.points_sensor.size());
        const Eigen::Vector3f expected(static_cast<float>(1.0 * ref.t_m * ca),
                                       static_cast<float>(1.0 * ref.t_m * sa),
                                       static_cast<float>(1.0 * ref.dz_m));
        ASSERT_EQ(scan.points_sensor[next], expected) << "column " << c << " ring " << k;
        ASSERT_EQ(scan.surfaces[next], ref.surface);
        ++next;
      }
    }
    EXPECT_EQ(next, scan.points_sensor.size());
  }
}

TEST(LidarSimulator, SameHitsAsThePlainCastInAFurnishedRoom) {
  World w = furnishedRoom();
  w.walls.push_back({{10, 4.5}, {10, 5.5}, 0.2, 2.0, 2.5});  // a lintel over nothing: spans above
  expectSameAsReference(w, 3, 5);
}

TEST(LidarSimulator, SameHitsAsThePlainCastWithMoreKindsOfColumnThanItsTable) {
  // 48 boxes of 48 different heights (plus walls, lintel, table, legs): more kinds of column
  // than the caster's table holds, so the rarest ones are read from the columns themselves.
  World w = furnishedRoom();
  w.walls.push_back({{10, 4.5}, {10, 5.5}, 0.2, 2.0, 2.5});
  for (int i = 0; i < 48; ++i) {
    const double x = 1.0 + (i % 8) * 0.6, y = 1.0 + (i / 8) * 0.5, top = 0.3 + 0.04 * i;
    w.furniture.push_back(
        {"box", {{x, y}, {x + 0.2, y}, {x + 0.2, y + 0.2}, {x, y + 0.2}}, 0.1, top});
  }
  expectSameAsReference(w, 4, 11);
}

TEST(LidarSimulator, SameHitsAsThePlainCastInTheLargeOffice) {
  expectSameAsReference(sim::loadBuiltinWorld("large_office"), 3, 9);
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
    const LidarOptions options;
    LidarSimulator lidar(columns, options, 7, RangeNoise{.sd_near_m = noise_m});
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
  const LidarOptions options;
  const RangeNoise noise{.sd_near_m = 0.03};
  LidarSimulator a(columns, options, 11, noise), b(columns, options, 11, noise),
      c(columns, options, 12, noise);
  const Pose2 pose{5.0, 5.0, 0.0};
  const LidarScan sa = a.scan(pose), sb = b.scan(pose), sc = c.scan(pose);
  ASSERT_EQ(sa.points_sensor.size(), sb.points_sensor.size());
  for (std::size_t i = 0; i < sa.points_sensor.size(); ++i)
    ASSERT_EQ(sa.points_sensor[i], sb.points_sensor[i]);
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
