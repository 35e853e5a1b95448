#pragma once
// Frontier detection as in explore_lite (m-explore, Hörner 2016): a breadth-first search
// over the free space reachable from the robot collects frontier cells (unknown cells with a
// free 4-neighbour) and groups them into 8-connected frontiers.

#include <vector>

#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout {

/// One connected frontier.
struct Frontier {
  std::vector<Cell> cells;         ///< member cells
  Vec2 centroid_m = Vec2::Zero();  ///< mean of the member cell centres [m]
  Vec2 nearest_m = Vec2::Zero();   ///< member nearest the search start ("middle" in explore_lite)
  double min_distance_m = 0.0;     ///< Euclidean distance from the search start to nearest_m [m]
  std::size_t size() const { return cells.size(); }
};

/// Finds every frontier that touches the free region connected (4-neighbours) to `from_m`.
/// If the start cell is not free, the search starts at the nearest free cell within 1 m.
/// Frontiers with fewer than `min_cells` members are dropped.
std::vector<Frontier> searchFrontiers(const OccupancyGrid& grid, const Vec2& from_m,
                                      std::size_t min_cells = 1);

}  // namespace roomscout
