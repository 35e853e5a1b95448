#include "roomscout/sim/robot.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout::sim {

void RobotOptions::validate() const {
  if (!(radius_m > 0.0)) throw OptionError("robot.radius_m must be > 0");
  if (!(max_linear_speed_mps > 0.0)) throw OptionError("robot.max_linear_speed_mps must be > 0");
  if (!(max_angular_speed_radps > 0.0))
    throw OptionError("robot.max_angular_speed_radps must be > 0");
}

std::vector<ParameterRef> RobotOptions::parameters() {
  return {
      {"radius_m", &radius_m, "footprint radius [m]"},
      {"max_linear_speed_mps", &max_linear_speed_mps, "linear speed limit [m/s]"},
      {"max_angular_speed_radps", &max_angular_speed_radps, "angular speed limit [rad/s]"},
  };
}

Robot::Robot(const WorldModel& world, const RobotOptions& options, const Pose2& start)
    : world_(world), options_(options), pose_(start) {
  options_.validate();
}

bool Robot::step(const VelocityCommand& command, double dt_s) {
  const double v =
      std::clamp(command.linear_mps, -options_.max_linear_speed_mps, options_.max_linear_speed_mps);
  const double w = std::clamp(command.angular_radps, -options_.max_angular_speed_radps,
                              options_.max_angular_speed_radps);
  // Exact unicycle integration over the step (arc when turning).
  const double th = pose_.yaw_rad;
  double dx, dy;
  if (std::abs(w) < 1e-9) {
    dx = v * dt_s * std::cos(th);
    dy = v * dt_s * std::sin(th);
  } else {
    dx = v / w * (std::sin(th + w * dt_s) - std::sin(th));
    dy = -v / w * (std::cos(th + w * dt_s) - std::cos(th));
  }
  pose_.yaw_rad = wrapAngle(th + w * dt_s);
  if (v == 0.0) return true;
  const Vec2 next(pose_.x_m + dx, pose_.y_m + dy);
  // Allow moves that increase clearance even when already touching (so the robot can back off).
  const double clearance_now = world_.clearance_m(pose_.position());
  const double clearance_next = world_.clearance_m(next);
  if (clearance_next < options_.radius_m && clearance_next <= clearance_now) return false;
  pose_.x_m = next.x();
  pose_.y_m = next.y();
  odometer_m_ += std::abs(v) * dt_s;
  return true;
}

}  // namespace roomscout::sim
