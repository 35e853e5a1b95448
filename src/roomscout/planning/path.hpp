#pragma once
// A planned path: waypoints in the map frame.

#include <vector>

#include "roomscout/core/geometry.hpp"

namespace roomscout {

struct Path {
  std::vector<Vec2> waypoints_m;  ///< from the start to the goal, one per grid cell or fewer
  double length_m = 0.0;          ///< sum of the segment lengths [m]
};

}  // namespace roomscout
