#pragma once
// The ground truth that exploration is scored against, at the map's resolution: which cells
// are truly free and reachable by the robot from its start (DESIGN: the opening of the free
// space by the robot's disc, connected component of the start).

#include <cstdint>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {

class ExplorationTruth {
 public:
  /// @param map_geometry the grid the mapper fills; must share the raster's origin
  /// @param robot_radius_m footprint radius used for the opening [m]
  ExplorationTruth(const WorldModel& world, const GridGeometry& map_geometry,
                   double robot_radius_m);

  const GridGeometry& geometry() const { return geometry_; }
  /// Map cells that are free in the ground truth (every raster cell they overlap is free).
  const std::vector<std::uint8_t>& trulyFree() const { return truly_free_; }
  /// Indices of the truly free cells the robot's disc can cover from the start.
  const std::vector<std::uint32_t>& reachableCells() const { return reachable_; }
  double reachableArea_m2() const;

  /// The exploration rate as the paper defines it, "the ratio of the explored region to the
  /// whole environment": the fraction of reachable cells that `grid` knows, as free or as
  /// occupied, in [0, 1]. Whether the map is right about them is MapAccuracy's business.
  double explorationRate(const OccupancyGrid& grid) const;

 private:
  GridGeometry geometry_;
  std::vector<std::uint8_t> truly_free_;
  std::vector<std::uint32_t> reachable_;
};

/// The exploration rate kept up to date from the map's changed rectangles, so that sampling
/// it costs the size of what changed rather than of the whole building.
class ExplorationRateCounter {
 public:
  explicit ExplorationRateCounter(const ExplorationTruth& truth);
  /// Recounts the cells of `changed` (cells outside it must not have changed since the last
  /// call).
  void update(const OccupancyGrid& grid, const CellRect& changed);
  /// Same value as ExplorationTruth::explorationRate() on the grid last passed to update().
  double rate() const;

 private:
  const ExplorationTruth& truth_;
  std::vector<std::uint8_t> reachable_;  ///< 1 for reachable cells
  std::vector<std::uint8_t> counted_;    ///< 1 for reachable cells counted as known
  std::size_t known_ = 0;
};

/// The map grid matching a world: same origin as the raster, covering it, at `resolution_m`.
/// Throws InputError naming the world's source when it would have more than kMaxGridCells.
GridGeometry mapGeometryFor(const WorldModel& world, double resolution_m);

}  // namespace roomscout::sim
