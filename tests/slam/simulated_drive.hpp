#pragma once
// A robot driven through a simulated world for SLAM tests: straight legs between waypoints,
// turning on the spot between them, one laser scan and one SLAM update per step.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/sensor_noise.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/slam/slam.hpp"

namespace roomscout::slam::testing {

/// One entry per scan.
struct SimulatedDrive {
  std::vector<Pose2> truth;
  std::vector<Pose2> online;          ///< the SLAM's estimate right after the scan
  std::vector<Pose2> odometry;        ///< where the odometry put the robot
  std::vector<std::size_t> leg_ends;  ///< per waypoint: the scans taken up to reaching it
};

/// Drives from the world's start through `waypoints`, turning in steps of at most
/// `turn_step_rad` and driving in steps of 5 cm. The laser is seeded with `seed`, the odometry
/// with `seed + 1`.
inline SimulatedDrive driveThrough(Slam& slam, const sim::WorldModel& world,
                                   const std::vector<Vec2>& waypoints,
                                   const sim::OdometryNoise& odometry_noise,
                                   const sim::RangeNoise& range_noise, std::uint64_t seed,
                                   double turn_step_rad) {
  sim::LaserSimulator laser(world, sim::LaserOptions{}, seed, range_noise);
  Pose2 truth = world.start();
  sim::OdometrySimulator odometry(odometry_noise, truth, seed + 1);
  SimulatedDrive d;
  auto sense = [&] {
    slam.update(laser.scan(truth), odometry.pose());
    d.truth.push_back(truth);
    d.online.push_back(slam.pose(odometry.pose()));
    d.odometry.push_back(odometry.pose());
  };
  sense();
  for (const Vec2& target : waypoints) {
    const double heading = std::atan2(target.y() - truth.y_m, target.x() - truth.x_m);
    while (std::abs(wrapAngle(heading - truth.yaw_rad)) > 1e-9) {
      const double turn =
          std::clamp(wrapAngle(heading - truth.yaw_rad), -turn_step_rad, turn_step_rad);
      const Pose2 before = truth;
      truth.yaw_rad = wrapAngle(truth.yaw_rad + turn);
      odometry.step(before, truth);
      sense();
    }
    while ((target - truth.position()).norm() > 1e-9) {
      const Vec2 delta = target - truth.position();
      const Vec2 step = delta.norm() > 0.05 ? Vec2(delta.normalized() * 0.05) : delta;
      const Pose2 before = truth;
      truth.x_m += step.x();
      truth.y_m += step.y();
      odometry.step(before, truth);
      sense();
    }
    d.leg_ends.push_back(d.truth.size());
  }
  return d;
}

}  // namespace roomscout::slam::testing
