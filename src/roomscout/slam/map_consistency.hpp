#pragma once
// How well a map agrees with the scans it was made from: a real log has no ground truth, but
// a bent or doubled map leaves scan points away from its walls.

#include <cstddef>
#include <optional>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::slam {

/// The consistency figure of one map.
struct MapConsistency {
  /// Mean distance from each scan point to the nearest occupied cell of the map [m] (cell
  /// centre to cell centre, Euclidean); empty when no point was counted or the map has no
  /// occupied cell.
  std::optional<double> mean_distance_m;
  std::size_t points = 0;          ///< points counted in the mean
  std::size_t outside_points = 0;  ///< points off the map, left out of the mean
};

/// Every return of every scan (a finite range in [range_min_m, min(range_max_m,
/// max_range_m)]), placed at its scan's pose T_map_sensor[i], measured against `map`'s
/// occupied cells with a distance transform. Throws InvalidArgument when the two vectors differ
/// in length or max_range_m is not positive.
MapConsistency mapConsistency(const OccupancyGrid& map, const std::vector<LaserScan>& scans,
                              const std::vector<Pose2>& T_map_sensor, double max_range_m);

}  // namespace roomscout::slam
