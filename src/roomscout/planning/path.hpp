#pragma once
// A planned path: waypoints in the map frame.

#include <vector>

#include "roomscout/core/geometry.hpp"

namespace roomscout {

struct Path {
  std::vector<Vec2> waypoints_m;  ///< from the start to the goal, one per grid cell or fewer
  double length_m = 0.0;          ///< sum of the segment lengths [m]
};

/// Whether a robot at `robot_m` has arrived at the end of `path`: within `tolerance_m` of its
/// last waypoint. False for an empty path. The one arrival test of the follower and the
/// Explorer.
inline bool arrived(const Path& path, const Vec2& robot_m, double tolerance_m) {
  return !path.waypoints_m.empty() && (path.waypoints_m.back() - robot_m).norm() <= tolerance_m;
}

}  // namespace roomscout
