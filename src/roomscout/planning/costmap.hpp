#pragma once
// Navigation costs derived from an OccupancyGrid: obstacle clearance, lethal inflation by the
// robot radius, and a soft cost that keeps paths away from walls.

#include <cstdint>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct CostmapOptions {
  double robot_radius_m = 0.105;
  double inflation_margin_m = 0.05;
  double cost_scaling_distance_m = 0.35;
  double max_soft_cost = 8.0;
  double unknown_cost = 1.0;

  /// Lethal clearance: a cell centre closer than this to an occupied cell centre is lethal [m].
  double lethalRadius_m() const { return robot_radius_m + inflation_margin_m; }
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Traversal costs of every cell of a grid. Occupied cells and cells closer than
/// lethalRadius_m() to one are lethal; unknown cells are traversable (optimistic planning,
/// as move_base with allow_unknown), at a small extra cost.
/// Built from the grid by a distance transform; call update() after map changes. An update
/// on a grid of the same geometry only recomputes the window around the cells whose state
/// changed, so refreshing after a few laser scans costs a fraction of the first build.
class Costmap {
 public:
  explicit Costmap(const CostmapOptions& options = {});

  /// Brings every cell up to date with `grid` (the same result as a build from scratch).
  void update(const OccupancyGrid& grid);
  /// The same, when the caller knows that only cells inside `changed` may differ from the
  /// grid of the last update (e.g. the union of the mapper's changed rectangles).
  void update(const OccupancyGrid& grid, const CellRect& changed);

  const GridGeometry& geometry() const { return geometry_; }
  const CostmapOptions& options() const { return options_; }

  bool isLethal(std::size_t index) const { return lethal_[index] != 0; }
  bool isLethal(Cell c) const {
    return geometry_.contains(c) ? isLethal(geometry_.index(c)) : true;
  }
  bool isUnknown(std::size_t index) const { return unknown_[index] != 0; }
  /// One byte per cell, row-major: non-zero where lethal (for whole-grid operations).
  const std::vector<std::uint8_t>& lethalMask() const { return lethal_; }
  /// Cost of entering the cell, >= 1 for traversable cells (meaningless when lethal).
  float stepCost(std::size_t index) const { return step_cost_[index]; }
  /// Distance from the cell centre to the nearest occupied cell centre [m], capped at
  /// maxClearance_m(): farther obstacles change no cost.
  float clearance_m(std::size_t index) const {
    return static_cast<float>(clearance_px_[index] * geometry_.resolution_m());
  }
  double maxClearance_m() const { return options_.cost_scaling_distance_m; }

 private:
  CostmapOptions options_;
  GridGeometry geometry_;
  std::vector<std::uint8_t> lethal_;
  std::vector<std::uint8_t> unknown_;
  std::vector<float> step_cost_;
  std::vector<float> clearance_px_;  ///< clearance in cells, capped
  std::vector<CellState> states_;    ///< grid states this costmap was computed from

  void rebuild(const OccupancyGrid& grid);
  /// Recomputes clearance within `rect` from the obstacles of the current states_.
  void computeClearance(const CellRect& rect);
  /// Recomputes lethal_ and step_cost_ within `rect` from clearance_px_ and states_.
  void computeCosts(const CellRect& rect);
};

}  // namespace roomscout
