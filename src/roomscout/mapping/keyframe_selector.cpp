#include "roomscout/mapping/keyframe_selector.hpp"

#include <cmath>
#include <cstdio>

#include "roomscout/core/errors.hpp"

namespace roomscout {

void KeyframeOptions::validate() const {
  if (!(distance_m > 0.0)) throw OptionError("keyframes.distance_m must be > 0");
  if (!(angle_rad > 0.0)) throw OptionError("keyframes.angle_rad must be > 0");
}

std::vector<ParameterRef> KeyframeOptions::parameters() {
  return {
      {"every_scan", &every_scan, "insert every scan instead of keyframes only"},
      {"distance_m", &distance_m, "translation that makes a new keyframe [m]"},
      {"angle_rad", &angle_rad, "rotation that makes a new keyframe [rad]"},
  };
}

std::string KeyframeOptions::describe() const {
  if (every_scan) return "keyframes: every scan";
  char buf[128];
  std::snprintf(buf, sizeof buf, "keyframes: every %g m or %g rad (LIO-SAM rule)", distance_m, angle_rad);
  return buf;
}

KeyframeSelector::KeyframeSelector(const KeyframeOptions& options) : options_(options) { options_.validate(); }

bool KeyframeSelector::accept(const Pose2& T_map_robot) {
  bool key = options_.every_scan || !last_;
  if (!key) {
    const double moved = (T_map_robot.position() - last_->position()).norm();
    const double turned = std::abs(wrapAngle(T_map_robot.yaw_rad - last_->yaw_rad));
    key = moved >= options_.distance_m || turned >= options_.angle_rad;
  }
  if (key) {
    last_ = T_map_robot;
    ++keyframes_;
  }
  return key;
}

}  // namespace roomscout
