#pragma once
// How right a robot's occupancy grid is, against the truth: whatever the exploration rate
// counts as explored, these figures say whether the map holds walls where walls are and free
// floor where the floor is.

#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::sim {

class ExplorationTruth;
class WorldModel;

/// A map's errors at its own resolution, in the world frame. A map cell is a true obstacle
/// when the world's laser-plane raster cell under its centre is solid; "within one cell" is
/// the cell's 3 x 3 neighbourhood. Every share is in [0, 1].
struct MapAccuracy {
  /// Reachable cells the map calls occupied, over the reachable cells.
  double false_occupied = 0.0;
  /// Occupied map cells within one cell of a true obstacle (any solid raster cell in the
  /// neighbourhood), over the occupied cells; 1 when none is occupied.
  double occupied_precision = 1.0;
  /// True obstacle cells next to reachable space with an occupied map cell within one cell,
  /// over those obstacle cells; 1 when there are none.
  double occupied_recall = 1.0;
  /// Free map cells that are true obstacles, over the free cells; 0 when none is free.
  double false_free = 0.0;
  /// Reachable cells the map calls free, over the reachable cells: the exploration rate
  /// counted over free cells only.
  double free_coverage = 0.0;
};

/// `map` must have the truth's geometry (the world frame at the map's resolution).
MapAccuracy mapAccuracy(const OccupancyGrid& map, const ExplorationTruth& truth,
                        const WorldModel& world);

}  // namespace roomscout::sim
