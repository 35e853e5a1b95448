#include "roomscout/experiment/oracle_tour.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "roomscout/core/errors.hpp"
#include "roomscout/sim/episode.hpp"

#include "../sim/test_worlds.hpp"

namespace roomscout::experiment {
namespace {

using sim::EpisodeConfig;
using sim::WorldModel;
namespace testing = sim::testing;

double polylineLength(const std::vector<Vec2>& points) {
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) length += (points[k] - points[k - 1]).norm();
  return length;
}

TEST(OracleTour, RoomSeenWholeFromTheStartNeedsNoViewpoint) {
  // A 4 m room: every inner point is within 2.7 m of the centre, inside the 3.5 m range.
  const WorldModel model(testing::squareRoom(4.0, 0.2));
  const OracleTour tour = planOracleTour(model);
  EXPECT_EQ(tour.viewpointCount(), 0u);
  EXPECT_DOUBLE_EQ(tour.length_m, 0.0);
  EXPECT_GE(tour.coverage, 0.98);
  EXPECT_NEAR(tour.reachable_area_m2, 3.8 * 3.8, 0.5);
}

TEST(OracleTour, TwoRoomsTourCoversBothRoomsWithinHandComputedBounds) {
  const WorldModel model(testing::twoRooms());
  const OracleTour tour = planOracleTour(model);
  ASSERT_GE(tour.viewpointCount(), 1u);
  EXPECT_GE(tour.coverage, 0.98);
  EXPECT_LE(tour.coverage, 1.0);

  // Lower bound. The strip 11.5 <= x <= 11.9 along the east room's far wall holds 1.9 m^2,
  // 3.4 % of the ~56 m^2 of free floor, so part of it must be seen: some viewpoint lies
  // within 3.5 m of it (x >= 8.0, less 0.1 m for the visibility cells). From the start
  // (2, 2.5) through the door at (6, 2.5) that is at least 5.9 m of driving.
  EXPECT_GE(tour.length_m, 5.9);
  // Upper bound. Driving to (4.5, 2.5), then through the door to (9, 2.5) is 7 m and sees
  // all but the east room's four corners farther than 3.5 m from (9, 2.5): 4 x 0.07 m^2,
  // 0.5 % of the floor. Greedy cover and the TSP heuristic may miss that tour; allow 50 %
  // more.
  EXPECT_LE(tour.length_m, 10.5);
  // It goes into the east room.
  bool east = false;
  for (const Vec2& p : tour.viewpoints_m) east |= p.x() > 6.5;
  EXPECT_TRUE(east);

  // The legs add up, and the polyline is the tour.
  double legs = 0.0;
  for (double leg : tour.leg_lengths_m) legs += leg;
  EXPECT_EQ(tour.leg_lengths_m.size(), tour.viewpointCount());
  EXPECT_NEAR(legs, tour.length_m, 1e-9);
  EXPECT_NEAR(polylineLength(tour.path_m), tour.length_m, 1e-6);
  ASSERT_FALSE(tour.path_m.empty());
  EXPECT_LT((tour.path_m.front() - model.start().position()).norm(), 0.05);
  EXPECT_LT((tour.path_m.back() - tour.viewpoints_m.back()).norm(), 1e-9);
}

TEST(OracleTour, PathKeepsTheRobotClearOfWalls) {
  const WorldModel model(testing::twoRooms());
  const OracleTour tour = planOracleTour(model);
  for (std::size_t k = 1; k < tour.path_m.size(); ++k) {
    const Vec2 a = tour.path_m[k - 1], b = tour.path_m[k];
    const int samples = static_cast<int>(std::ceil((b - a).norm() / 0.02)) + 1;
    for (int s = 0; s <= samples; ++s) {
      const Vec2 p = a + (b - a) * (static_cast<double>(s) / samples);
      ASSERT_TRUE(model.robotFits(p))
          << "segment " << k << " at (" << p.x() << ", " << p.y() << ")";
    }
  }
}

TEST(OracleTour, IsDeterministic) {
  const WorldModel model(testing::twoRooms());
  const OracleTour a = planOracleTour(model);
  const OracleTour b = planOracleTour(model);
  EXPECT_EQ(a.length_m, b.length_m);
  EXPECT_EQ(a.coverage, b.coverage);
  EXPECT_EQ(a.viewpoints_m, b.viewpoints_m);
  EXPECT_EQ(a.path_m, b.path_m);
}

TEST(OracleTour, UnsmoothedLegsAreNotShorter) {
  const WorldModel model(testing::twoRooms());
  OracleTourOptions options;
  options.smooth_legs = false;
  const OracleTour grid = planOracleTour(model, options);
  const OracleTour smooth = planOracleTour(model);
  EXPECT_EQ(grid.viewpoints_m, smooth.viewpoints_m);
  EXPECT_GE(grid.length_m, smooth.length_m - 1e-9);
  EXPECT_LE(grid.length_m, smooth.length_m * 1.09);  // octile paths: at most 8.2 % longer
}

TEST(OracleTour, LongerRangeNeedsNoLongerTour) {
  const WorldModel model(testing::twoRooms());
  OracleTourOptions options;
  options.sensor_range_m = 20.0;  // everything in line of sight: one look through the door
  const OracleTour tour = planOracleTour(model, options);
  EXPECT_GE(tour.coverage, 0.98);
  EXPECT_LE(tour.length_m, planOracleTour(model).length_m);
}

TEST(OracleTour, OptionsFollowTheEpisodeConfig) {
  EpisodeConfig config;
  config.robot.radius_m = 0.2;
  config.explorer.costmap.inflation_margin_m = 0.1;
  config.laser.range_max_m = 6.0;
  config.mapping.resolution_m = 0.1;
  const OracleTourOptions options = oracleTourOptionsFor(config);
  EXPECT_DOUBLE_EQ(options.lethal_radius_m, 0.3);
  EXPECT_DOUBLE_EQ(options.sensor_range_m, 6.0);
  EXPECT_DOUBLE_EQ(options.map_resolution_m, 0.1);
  EXPECT_NO_THROW(options.validate());
}

TEST(OracleTour, RejectsInvalidOptions) {
  const auto invalid = [](auto change) {
    OracleTourOptions options;
    change(options);
    return options;
  };
  EXPECT_THROW(invalid([](auto& o) { o.visibility_cell_m = 0.07; }).validate(), OptionError);
  EXPECT_THROW(invalid([](auto& o) { o.target_coverage = 0.0; }).validate(), OptionError);
  EXPECT_THROW(invalid([](auto& o) { o.sensor_range_m = -1.0; }).validate(), OptionError);
  EXPECT_THROW(invalid([](auto& o) { o.rays_per_viewpoint = 2; }).validate(), OptionError);
  EXPECT_THROW(invalid([](auto& o) { o.viewpoint_spacing_m = 0.01; }).validate(), OptionError);
  const WorldModel model(testing::squareRoom(4.0, 0.2));
  EXPECT_THROW(planOracleTour(model, invalid([](auto& o) { o.map_resolution_m = 0.0; })),
               OptionError);
}

}  // namespace
}  // namespace roomscout::experiment
