#include "roomscout/mapping/keyframe_selector.hpp"

#include <cmath>
#include <cstdio>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"

namespace roomscout {

void KeyframeOptions::validate() const {
  if (!(distance_m > 0.0)) throw OptionError("keyframes.distance_m must be > 0");
  if (!(angle_rad > 0.0)) throw OptionError("keyframes.angle_rad must be > 0");
  if (!(turn_min_move_m >= 0.0 && turn_min_move_m < distance_m))
    throw OptionError("keyframes.turn_min_move_m must be >= 0 and below keyframes.distance_m");
}

std::vector<ParameterRef> KeyframeOptions::parameters() {
  return {
      {"every_scan", &every_scan, "insert every scan instead of keyframes only"},
      {"distance_m", &distance_m, "translation that makes a new keyframe [m]"},
      {"angle_rad", &angle_rad, "rotation that makes a new keyframe [rad]"},
      {"turn_min_move_m", &turn_min_move_m,
       "translation a rotation keyframe also needs [m]; 0: LIO-SAM's rule"},
  };
}

std::string KeyframeOptions::describe() const {
  if (every_scan) return "keyframes: every scan";
  if (turn_min_move_m == 0.0) {
    return formatString("keyframes: every %g m or %g rad (LIO-SAM rule)", distance_m, angle_rad);
  }
  return formatString(
      "keyframes: every %g m, or %g rad after %g m (LIO-SAM rule, no turns on the spot)",
      distance_m, angle_rad, turn_min_move_m);
}

KeyframeSelector::KeyframeSelector(const KeyframeOptions& options) : options_(options) {
  options_.validate();
}

bool KeyframeSelector::accept(const Pose2& T_map_robot) {
  bool key = options_.every_scan || !last_;
  if (!key) {
    const double moved = (T_map_robot.position() - last_->position()).norm();
    const double turned = std::abs(wrapAngle(T_map_robot.yaw_rad - last_->yaw_rad));
    key = moved >= options_.distance_m ||
          (turned >= options_.angle_rad && moved >= options_.turn_min_move_m);
  }
  if (key) {
    last_ = T_map_robot;
    ++keyframes_;
  }
  return key;
}

}  // namespace roomscout
