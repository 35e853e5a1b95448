#pragma once
// What the square around a frontier point holds (unknown and occupied area, frontier cells), and
// when that makes the point a sliver of `semantic`: a point whose trip shows little, because
// its unknown space is small, lies behind walls already seen, or is an enclosed pocket (a
// cupboard, the inside of furniture). Shared by the scoring, the goal's persistence, the room's
// P_sem cells and the end phase of SemanticExplorer (semantic_explorer.hpp).

#include <string_view>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

/// The sliver thresholds of SemanticExplorerOptions (documented in its parameters()); 0 turns
/// each off.
struct SliverOptions {
  double min_unknown_m2 = 1.0;
  double min_frontier_m = 1.0;
  double pocket_area_m2 = 2.0;
  double pocket_area_fraction = 0.01;

  void validate() const;
  /// The frontier cells a square must hold not to be exhausted.
  int frontierCellsWanted(double resolution_m) const;
  /// The pocket threshold now: pocket_area_m2, or once idle pocket_area_fraction of the known
  /// free area if that is less.
  double pocketArea_m2(const OccupancyGrid& grid, bool idle) const;
};

/// Unknown space that reaches the known map's border through an opening this wide is no
/// pocket, whatever its area: it may go on beyond the map (improved_rrt's min_opening_m).
inline constexpr double kPocketOpening_m = EndTestPockets{}.min_opening_m;

/// A frontier cell as `semantic` counts them: known free, with an unknown 4-neighbour.
inline bool freeBesideUnknown(const OccupancyGrid& grid, int x, int y) {
  const int w = grid.geometry().width(), h = grid.geometry().height();
  const std::size_t i = static_cast<std::size_t>(y) * w + x;
  return grid.isFree(i) &&
         ((x > 0 && grid.isUnknown(i - 1)) || (x + 1 < w && grid.isUnknown(i + 1)) ||
          (y > 0 && grid.isUnknown(i - w)) || (y + 1 < h && grid.isUnknown(i + w)));
}

/// Unknown and occupied areas [m^2] in a square, and its frontier cells up to a cap.
struct SquareAreas {
  double unknown_m2 = 0.0;
  double occupied_m2 = 0.0;
  int frontier_cells = 0;
};

/// The areas in the square of half-side `half_m` centred on `p`'s cell, and its frontier cells
/// (freeBesideUnknown; the grid's border cells are not counted) up to `frontier_cap`: only
/// whether a square holds that many matters.
SquareAreas squareAreas(const OccupancyGrid& grid, const Vec2& p, double half_m,
                        int frontier_cap = 0);

/// Whether a square holds too little to see to be worth a trip: less than `min_unknown_m2` of
/// unknown space (the sliver threshold or the goal's), or less than min_frontier_m of frontier
/// (its unknown space lies behind walls already seen, e.g. outside a room corner, and cannot be
/// seen from there).
bool exhausted(const SquareAreas& a, const SliverOptions& o, double min_unknown_m2,
               double resolution_m);

}  // namespace roomscout
