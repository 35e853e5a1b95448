#pragma once
// Rigid 2D transforms on Pose2 (a pose is the transform from its frame to its parent's).

#include <cmath>

#include "roomscout/core/geometry.hpp"

namespace roomscout::slam::detail {

/// a then b, with b expressed in a's frame.
inline Pose2 compose(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.yaw_rad), s = std::sin(a.yaw_rad);
  return {a.x_m + c * b.x_m - s * b.y_m, a.y_m + s * b.x_m + c * b.y_m,
          wrapAngle(a.yaw_rad + b.yaw_rad)};
}

inline Pose2 inverse(const Pose2& a) {
  const double c = std::cos(a.yaw_rad), s = std::sin(a.yaw_rad);
  return {-c * a.x_m - s * a.y_m, s * a.x_m - c * a.y_m, wrapAngle(-a.yaw_rad)};
}

/// b in a's frame: inverse(a) then b.
inline Pose2 between(const Pose2& a, const Pose2& b) { return compose(inverse(a), b); }

/// A point of `frame` in the parent frame.
inline Vec2 apply(const Pose2& frame, const Vec2& p) {
  const double c = std::cos(frame.yaw_rad), s = std::sin(frame.yaw_rad);
  return {frame.x_m + c * p.x() - s * p.y(), frame.y_m + s * p.x() + c * p.y()};
}

inline bool isFinite(const Pose2& p) {
  return std::isfinite(p.x_m) && std::isfinite(p.y_m) && std::isfinite(p.yaw_rad);
}

}  // namespace roomscout::slam::detail
