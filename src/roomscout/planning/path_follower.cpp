#include "roomscout/planning/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"

namespace roomscout {

namespace {

/// Slowest forward speed used near the goal, so that the robot does arrive [m/s].
constexpr double kMinApproachSpeed_mps = 0.05;
/// Time over which the robot would cover the remaining distance at the capped speed [s].
constexpr double kApproachTime_s = 1.0;

bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

void PathFollowerOptions::validate() const {
  if (!positiveFinite(max_linear_speed_mps)) {
    throw OptionError("follower.max_linear_speed_mps must be a finite number > 0");
  }
  if (!positiveFinite(max_angular_speed_radps)) {
    throw OptionError("follower.max_angular_speed_radps must be a finite number > 0");
  }
  if (!positiveFinite(lookahead_m)) {
    throw OptionError("follower.lookahead_m must be a finite number > 0");
  }
  if (!positiveFinite(goal_tolerance_m)) {
    throw OptionError("follower.goal_tolerance_m must be a finite number > 0");
  }
  if (!(positiveFinite(rotate_in_place_rad) && rotate_in_place_rad <= M_PI)) {
    throw OptionError("follower.rotate_in_place_rad must be in (0, pi]");
  }
  if (!positiveFinite(heading_gain)) {
    throw OptionError("follower.heading_gain must be a finite number > 0");
  }
}

std::vector<ParameterRef> PathFollowerOptions::parameters() {
  return {
      {"max_linear_speed_mps", &max_linear_speed_mps,
       "forward speed limit (TurtleBot3 Burger) [m/s]"},
      {"max_angular_speed_radps", &max_angular_speed_radps,
       "turn rate limit (TurtleBot3 Burger) [rad/s]"},
      {"lookahead_m", &lookahead_m,
       "distance from the robot to the pure-pursuit carrot on the path ahead [m]"},
      {"goal_tolerance_m", &goal_tolerance_m,
       "distance to the path's last waypoint that counts as reached [m]"},
      {"rotate_in_place_rad", &rotate_in_place_rad,
       "heading error above which the robot stops and turns on the spot [rad]"},
      {"heading_gain", &heading_gain, "angular speed per radian of heading error [1/s]"},
  };
}

PathFollower::PathFollower(const PathFollowerOptions& options)
    : options_(options), progress_(2.0 * options.lookahead_m) {
  options_.validate();
}

void PathFollower::setPath(const Path& path) { progress_.reset(path); }

void PathFollower::clear() { setPath(Path{}); }

bool PathFollower::reached(const Pose2& robot) const {
  return arrived(path(), robot.position(), options_.goal_tolerance_m);
}

Vec2 PathFollower::carrot(const Vec2& robot_m) const {
  const std::vector<Vec2>& w = path().waypoints_m;
  const std::vector<double>& arc_m = progress_.arcLength_m();
  const std::size_t segment = progress_.segment();
  const double progress_m = progress_.progress_m();
  const double lookahead2 = options_.lookahead_m * options_.lookahead_m;
  for (std::size_t i = segment; i + 1 < w.size(); ++i) {
    const double length_m = arc_m[i + 1] - arc_m[i];
    if (!(length_m > 0.0)) continue;
    // The part of the segment beyond the progress point.
    const double t0 = i == segment ? std::clamp((progress_m - arc_m[i]) / length_m, 0.0, 1.0) : 0.0;
    const Vec2 a = w[i] + t0 * (w[i + 1] - w[i]);
    const Vec2 d = w[i + 1] - a;
    const Vec2 f = a - robot_m;
    if (f.squaredNorm() >= lookahead2) return a;
    // Where |f + t d| grows past the lookahead: the larger root of the quadratic in t.
    const double dd = d.squaredNorm();
    if (dd == 0.0) continue;
    const double fd = f.dot(d);
    const double t = (-fd + std::sqrt(fd * fd - dd * (f.squaredNorm() - lookahead2))) / dd;
    if (t <= 1.0) return a + t * d;
  }
  return w.back();
}

VelocityCommand PathFollower::compute(const Pose2& robot) {
  if (!hasPath() || reached(robot)) return {};
  const Vec2 position = robot.position();
  progress_.update(position);

  const Vec2 to_carrot = carrot(position) - position;
  if (to_carrot.norm() < 1e-9) return {};
  const double error_rad = wrapAngle(std::atan2(to_carrot.y(), to_carrot.x()) - robot.yaw_rad);

  VelocityCommand command;
  const double max_w = options_.max_angular_speed_radps;
  if (std::abs(error_rad) > options_.rotate_in_place_rad) {
    command.angular_radps =
        std::copysign(std::min(max_w, options_.heading_gain * std::abs(error_rad)), error_rad);
    return command;
  }
  command.angular_radps = std::clamp(options_.heading_gain * error_rad, -max_w, max_w);
  const double remaining_m = std::max((path().waypoints_m.back() - position).norm(),
                                      progress_.arcLength_m().back() - progress_.progress_m());
  const double approach_mps = std::max(kMinApproachSpeed_mps, remaining_m / kApproachTime_s);
  command.linear_mps =
      std::min(options_.max_linear_speed_mps * std::max(0.0, std::cos(error_rad)), approach_mps);
  return command;
}

}  // namespace roomscout
