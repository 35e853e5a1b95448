#pragma once
// A simulated differential-drive robot (TurtleBot3 Burger profile): unicycle kinematics with
// velocity limits, blocked by the world's solid objects.

#include "roomscout/core/parameters.hpp"
#include "roomscout/planning/path_follower.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct RobotOptions {
  double radius_m = 0.105;
  double max_linear_speed_mps = 0.22;
  double max_angular_speed_radps = 2.84;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

class Robot {
 public:
  Robot(const WorldModel& world, const RobotOptions& options, const Pose2& start);

  const Pose2& pose() const { return pose_; }
  const RobotOptions& options() const { return options_; }
  /// Distance driven so far [m].
  double odometer_m() const { return odometer_m_; }

  /// Applies a command for dt_s seconds (clamped to the limits). A move that would make the
  /// footprint touch a solid object is not carried out (the robot turns but stays put); the
  /// return value says whether the commanded translation happened.
  bool step(const VelocityCommand& command, double dt_s);

 private:
  const WorldModel& world_;
  RobotOptions options_;
  Pose2 pose_;
  double odometer_m_ = 0.0;
};

}  // namespace roomscout::sim
