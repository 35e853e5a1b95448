// Random start poses: drawn from the seed alone, clear of obstacles, never where the robot
// could not leave (an enclosed space), spread over the reachable floor.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "roomscout/sim/start_pose.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

/// Two rooms joined by a door, with a closed 2 x 2 m box standing in the east room: its
/// inside is free floor no robot can reach.
World twoRoomsWithClosedBox() {
  World w = testing::twoRooms();
  const double t = 0.2;
  w.walls.push_back({{8.5, 0.8}, {10.5, 0.8}, t, 0.0, 2.5});
  w.walls.push_back({{10.5, 0.8}, {10.5, 2.8}, t, 0.0, 2.5});
  w.walls.push_back({{10.5, 2.8}, {8.5, 2.8}, t, 0.0, 2.5});
  w.walls.push_back({{8.5, 2.8}, {8.5, 0.8}, t, 0.0, 2.5});
  return w;
}

TEST(RandomStartPose, SameSeedSamePoseClearOfWallsAndNeverInsideTheClosedBox) {
  const WorldModel model(twoRoomsWithClosedBox());
  int west = 0, east = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const Pose2 p = randomStartPose(model, seed);
    const Pose2 again = randomStartPose(model, seed);
    EXPECT_EQ(p.x_m, again.x_m);
    EXPECT_EQ(p.y_m, again.y_m);
    EXPECT_EQ(p.yaw_rad, again.yaw_rad);
    // 0.4 m from anything solid, up to the raster's cell (0.025 m).
    EXPECT_GE(model.clearance_m(p.position()), 0.4 - 0.03) << p.x_m << ", " << p.y_m;
    const bool in_box = p.x_m > 8.5 && p.x_m < 10.5 && p.y_m > 0.8 && p.y_m < 2.8;
    EXPECT_FALSE(in_box) << p.x_m << ", " << p.y_m;
    EXPECT_GE(p.yaw_rad, -std::numbers::pi);
    EXPECT_LT(p.yaw_rad, std::numbers::pi);
    (p.x_m < 6.0 ? west : east) += 1;
  }
  // Both rooms are reachable and hold starts (about half each: the rooms are the same size
  // but for the box).
  EXPECT_GT(west, 60);
  EXPECT_GT(east, 40);
  EXPECT_NE(randomStartPose(model, 1).x_m, randomStartPose(model, 2).x_m);
}

TEST(RandomStartPose, WorldsStartWhenNoPlaceIsClearEnough) {
  const WorldModel model(testing::twoRooms());
  const Pose2 p = randomStartPose(model, 7, 10.0);
  EXPECT_EQ(p.x_m, model.start().x_m);
  EXPECT_EQ(p.y_m, model.start().y_m);
  EXPECT_EQ(p.yaw_rad, model.start().yaw_rad);
}

}  // namespace
}  // namespace roomscout::sim
