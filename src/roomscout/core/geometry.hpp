#pragma once
// Planar geometry shared by every layer: points and poses in the map frame.

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace roomscout {

/// A point or vector in the map frame [m].
using Vec2 = Eigen::Vector2d;

/// A closed polygon in the map frame [m]; the last vertex connects back to the first.
using Polygon = std::vector<Vec2>;

/// Robot pose in the map frame: position [m] and heading [rad], counter-clockwise from +x.
struct Pose2 {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_rad = 0.0;

  Vec2 position() const { return {x_m, y_m}; }
};

/// Wraps an angle to (-pi, pi].
inline double wrapAngle(double angle_rad) {
  angle_rad = std::remainder(angle_rad, 2.0 * M_PI);
  return angle_rad <= -M_PI ? angle_rad + 2.0 * M_PI : angle_rad;
}

/// Rigid 2D transforms on poses: a pose is the transform from its frame to its parent's.
/// `a` then `b`, with `b` expressed in `a`'s frame.
inline Pose2 compose(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.yaw_rad), s = std::sin(a.yaw_rad);
  return {a.x_m + c * b.x_m - s * b.y_m, a.y_m + s * b.x_m + c * b.y_m,
          wrapAngle(a.yaw_rad + b.yaw_rad)};
}

inline Pose2 inverse(const Pose2& a) {
  const double c = std::cos(a.yaw_rad), s = std::sin(a.yaw_rad);
  return {-c * a.x_m - s * a.y_m, s * a.x_m - c * a.y_m, wrapAngle(-a.yaw_rad)};
}

/// `b` in `a`'s frame.
inline Pose2 between(const Pose2& a, const Pose2& b) { return compose(inverse(a), b); }

/// A point of `frame` in the parent frame.
inline Vec2 transformPoint(const Pose2& frame, const Vec2& p) {
  const double c = std::cos(frame.yaw_rad), s = std::sin(frame.yaw_rad);
  return {frame.x_m + c * p.x() - s * p.y(), frame.y_m + s * p.x() + c * p.y()};
}

inline bool isFinite(const Pose2& p) {
  return std::isfinite(p.x_m) && std::isfinite(p.y_m) && std::isfinite(p.yaw_rad);
}

/// Area of a simple polygon [m^2] (absolute value of the shoelace sum).
double polygonArea(const Polygon& polygon);

}  // namespace roomscout
