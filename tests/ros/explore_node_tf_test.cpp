// roomscout_explore_node against a hand-driven ROS graph: this test publishes the clock, a map
// and the robot's tf, and serves move_base itself, so it controls how old the pose is.

#include <actionlib/server/action_server.h>
#include <gtest/gtest.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_msgs/TFMessage.h>

#include <chrono>
#include <string>

#include "ros_test_support.hpp"

namespace roomscout::ros1::test {
namespace {

using std::chrono::seconds;

std::string exploreNode() {
  return std::string(ROOMSCOUT_ROS_PACKAGE_DIR) + "/bin/roomscout_explore_node";
}

/// A 6 x 6 m map: a 4 x 4 m free room in the middle, open to unknown space on its east side.
nav_msgs::OccupancyGrid roomMap() {
  nav_msgs::OccupancyGrid m;
  m.header.frame_id = "map";
  m.info.resolution = 0.05f;
  m.info.width = m.info.height = 120;
  m.info.origin.orientation.w = 1.0;
  m.data.assign(120 * 120, -1);
  for (int y = 18; y < 102; ++y) {
    for (int x = 18; x < 102; ++x) {
      const bool wall = x < 20 || y < 20 || y >= 100;
      m.data[static_cast<std::size_t>(y) * 120 + x] = wall ? 100 : 0;
    }
  }
  return m;
}

TEST(ExploreNodeTf, APoseOlderThanTheToleranceSendsNoGoal) {
  RosMaster master;
  master.initClient("explore_tf_test");
  ros::param::set("/use_sim_time", true);
  ros::NodeHandle nh;
  ros::Publisher clock = nh.advertise<rosgraph_msgs::Clock>("/clock", 10, true);
  ros::Publisher map = nh.advertise<nav_msgs::OccupancyGrid>("/map", 1, true);
  ros::Publisher tf = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
  int goals = 0;
  actionlib::ActionServer<move_base_msgs::MoveBaseAction> move_base(
      nh, "move_base",
      [&](actionlib::ActionServer<move_base_msgs::MoveBaseAction>::GoalHandle goal) {
        goal.setAccepted();
        ++goals;
      },
      false);
  move_base.start();
  map.publish(roomMap());
  auto explore =
      master.node(exploreNode(), "explore",
                  {"_method:=nearest_frontier", "_save_dir:=", "_transform_tolerance:=0.3"});
  double t = 100.0;
  // Each tick: the clock 0.05 s on, and the robot's pose stamped `age_s` before it.
  auto tick = [&](double age_s) {
    t += 0.05;
    rosgraph_msgs::Clock c;
    c.clock = ros::Time(t);
    clock.publish(c);
    geometry_msgs::TransformStamped pose;
    pose.header.frame_id = "map";
    pose.header.stamp = ros::Time(t - age_s);
    pose.child_frame_id = "base_link";
    pose.transform.translation.x = 2.0;
    pose.transform.translation.y = 3.0;
    pose.transform.rotation.w = 1.0;
    tf2_msgs::TFMessage msg;
    msg.transforms.push_back(pose);
    tf.publish(msg);
    return false;
  };
  // A second old: no goal in 10 s of wall time (200 cycles of simulated time).
  spinUntil([&] { return tick(1.0); }, seconds(10), [&] { return !explore->poll(); });
  EXPECT_EQ(goals, 0) << explore->output();
  // A fresh pose: a goal follows.
  EXPECT_TRUE(spinUntil([&] { return tick(0.0) || goals > 0; }, seconds(30),
                        [&] { return !explore->poll(); }))
      << explore->output();
  EXPECT_EQ(explore->stop(), 0) << explore->output();
}

}  // namespace
}  // namespace roomscout::ros1::test
