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

/// Area of a simple polygon [m^2] (absolute value of the shoelace sum).
double polygonArea(const Polygon& polygon);

}  // namespace roomscout
