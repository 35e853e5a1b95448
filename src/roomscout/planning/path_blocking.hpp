#pragma once
// Whether newly mapped obstacles block the path ahead of the robot: the test a driver runs on
// each new map before it replans. Shared by the Explorer's goal watchdog and the simulated
// move_base of the ROS sim node, so that both replan on the same evidence.

#include <cstddef>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout {

/// Offsets of the cells whose centres lie strictly within `radius_cells` of a cell's centre.
std::vector<Cell> discOffsets(double radius_cells);

/// How far along the path from the robot a new scan can have blocked it: the sensor's range,
/// plus the lethal radius around a waypoint, plus half a metre of slack [m].
inline double blockingHorizon_m(double sensor_range_m, double lethal_radius_m) {
  return sensor_range_m + lethal_radius_m + 0.5;
}

/// True when an occupied cell of `grid` lies within `disc` (cell offsets, e.g. the robot's
/// lethal radius) of a waypoint at index `from` or later that is within `horizon_m` of the
/// robot: beyond the laser's range a new scan cannot have blocked the path.
bool pathBlockedAhead(const OccupancyGrid& grid, const std::vector<Vec2>& waypoints_m,
                      std::size_t from, const Vec2& robot_m, double horizon_m,
                      const std::vector<Cell>& disc);

}  // namespace roomscout
