#pragma once
// Navigation costs derived from an OccupancyGrid: obstacle clearance, lethal inflation by the
// robot radius, and a soft cost that keeps paths away from walls.

#include <cstdint>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout {

struct CostmapOptions {
  double robot_radius_m = 0.105;          ///< TurtleBot3 Burger footprint radius [m]
  double inflation_margin_m = 0.05;       ///< extra lethal clearance beyond the radius [m]
  double cost_scaling_distance_m = 0.35;  ///< clearance [m] under which the soft cost rises
  double max_soft_cost = 8.0;             ///< soft cost at the lethal boundary (per cell step)
  double unknown_cost = 1.0;              ///< extra cost of stepping into unknown space (per cell)

  /// Lethal clearance: a cell centre closer than this to an occupied cell centre is lethal [m].
  double lethalRadius_m() const { return robot_radius_m + inflation_margin_m; }
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Traversal costs of every cell of a grid. Occupied cells and cells closer than
/// lethalRadius_m() to one are lethal; unknown cells are traversable (optimistic planning,
/// as move_base with allow_unknown), at a small extra cost.
/// Built in one pass from the grid (a distance transform); call update() after map changes.
class Costmap {
 public:
  explicit Costmap(const CostmapOptions& options = {});

  /// Recomputes every cell from `grid`.
  void update(const OccupancyGrid& grid);

  const GridGeometry& geometry() const { return geometry_; }
  const CostmapOptions& options() const { return options_; }

  bool isLethal(std::size_t index) const { return lethal_[index] != 0; }
  bool isLethal(Cell c) const {
    return geometry_.contains(c) ? isLethal(geometry_.index(c)) : true;
  }
  bool isUnknown(std::size_t index) const { return unknown_[index] != 0; }
  /// Cost of entering the cell, >= 1 for traversable cells (meaningless when lethal).
  float stepCost(std::size_t index) const { return step_cost_[index]; }
  /// Distance from the cell centre to the nearest occupied cell centre [m] (large when none).
  float clearance_m(std::size_t index) const { return clearance_m_[index]; }

 private:
  CostmapOptions options_;
  GridGeometry geometry_;
  std::vector<std::uint8_t> lethal_;
  std::vector<std::uint8_t> unknown_;
  std::vector<float> step_cost_;
  std::vector<float> clearance_m_;
};

}  // namespace roomscout
