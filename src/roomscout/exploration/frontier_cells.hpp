#pragma once
// Grid-cell helpers shared by the SMMR-Explore baselines (improved_rrt, mmpf) and the end test
// we add to rrt: SMMR-Explore's "reachable frontier cell" scan, and snapping a point to the
// nearest cell a goal may lie in. Every function taking a costmap reads it by the grid's cell
// index and throws InvalidArgument when it was computed for a grid of another size.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/planning/costmap.hpp"

namespace roomscout {

/// SMMR-Explore's frontier cells (rrt_node_tf.cpp and mmpf_node.cpp, Yu et al., ICRA 2021):
/// an unknown cell with a free 4-neighbour that has a further free neighbour (ahead or to
/// either side), not lethal in the costmap and with no occupied cell at an L1 distance below
/// `obstacle_l1_cells` (the originals: 4 in the rrt end test, 6 in mmpf). Cells within two
/// cells of the grid border are skipped, as in the originals. Row-major order.
/// Cells flagged non-zero in `exhausted` (one byte per cell, may be null) are skipped too.
/// With `robot_m`, a cell also needs a 4-neighbour in the known-free, non-lethal region
/// 4-connected to the robot's cell, or, when that cell is not such a cell, to the nearest one
/// within 1 m; without one, no cell qualifies. This is a deviation of our end tests: the
/// originals count frontier cells the robot's footprint can never approach, e.g. in a toilet
/// cubicle narrower than the robot, and then never end.
std::vector<Cell> reachableFrontierCells(const OccupancyGrid& grid, const Costmap& costmap,
                                         int obstacle_l1_cells,
                                         const std::vector<std::uint8_t>* exhausted = nullptr,
                                         const Vec2* robot_m = nullptr);

/// The number of cells reachableFrontierCells(grid, costmap, obstacle_l1_cells, exhausted,
/// &robot_m) would return, counted only up to `limit`: the flood fill from the robot stops as
/// soon as `limit` such cells border it, so the end tests cost little while frontiers are near.
std::size_t countReachableFrontierCells(const OccupancyGrid& grid, const Costmap& costmap,
                                        int obstacle_l1_cells,
                                        const std::vector<std::uint8_t>* exhausted,
                                        const Vec2& robot_m, std::size_t limit);

/// Bounding box [m] of the known (free or occupied) cells grown by `padding_cells` on each
/// side (clipped to the grid); the point `fallback_m` when nothing is known. The box RRT
/// detectors sample from. A frontier on the edge of the unpadded box (the open end of a
/// corridor that runs along an axis) has its unknown side outside it, where no sample and so
/// no edge ever goes.
/// Cartographer pads the map it publishes (its submap painter's kPaddingPixel): the map
/// SMMR-Explore's rrt node samples over.
inline constexpr int kCartographerPaddingCells = 5;
void knownCellsBox(const OccupancyGrid& grid, const Vec2& fallback_m, int padding_cells,
                   Vec2& min_m, Vec2& max_m);

/// Flags (sets to 1) the cells of `mask` (one byte per cell of `geometry`, resized if needed)
/// whose centres lie within `radius_m` of `p_m`.
///
/// Used for a deviation shared by the baselines' end tests: our simulated laser never marks a
/// few cells (faces of furniture seen only at grazing angles, slivers under the minimum range),
/// so "fewer than 2 reachable frontier cells" may never hold. A frontier cell that stayed
/// unknown while the robot was within this radius of it cannot be observed and is ignored.
void markDisc(std::vector<std::uint8_t>& mask, const GridGeometry& geometry, const Vec2& p_m,
              double radius_m);

/// The centre of the cell nearest to `p_m` (by squared cell distance, ties by row-major order)
/// that is inside the grid, not lethal and not occupied, within `max_radius_m`; none if there
/// is none. With `free_only`, only known-free cells count.
std::optional<Vec2> nearestGoalCell(const OccupancyGrid& grid, const Costmap& costmap,
                                    const Vec2& p_m, double max_radius_m, bool free_only = false);

/// Flags in `exhausted` (one byte per cell, resized if needed) the frontier cells among
/// `cells` that open onto a pocket: fewer than `min_area_m2` of unknown, non-lethal cells are
/// 4-connected to the cell within the bounding box of the known cells (one cell wider) and,
/// when `min_opening_m` > 0, fewer than `min_opening_m` of them lie on that box's border (more:
/// the unknown space may go on beyond the known map, as at a corridor's frontier).
///
/// Used by the end tests of rrt and improved_rrt (a deviation of ours): a frontier the robot's
/// footprint could drive into opens onto unknown, non-lethal space; a pocket is the unknown
/// interior of a piece of furniture or of a wall behind a face cell our laser never marked
/// (seen only at grazing angles or between table legs), or the outside of the building seen
/// through such a crack in an outer wall (hence the box). Neither detector sends the robot to
/// look into them, so without this the end test never passes on large_office.
void markUnknownPockets(std::vector<std::uint8_t>& exhausted, const OccupancyGrid& grid,
                        const Costmap& costmap, const std::vector<Cell>& cells, double min_area_m2,
                        double min_opening_m);

/// The pocket search of an end test (markUnknownPockets), as rrt, improved_rrt and
/// semantic_paper run it. Fields are documented in parameters().
struct EndTestPockets {
  double min_area_m2 = 4.0;
  double min_opening_m = 0.4;
  double period_s = 10.0;

  /// Throws OptionError naming `group` (the method) for a value out of range.
  void validate(std::string_view group) const;
  /// The three options, under the keys rrt and improved_rrt read them by.
  std::vector<ParameterRef> parameters();
};

/// The reachable frontier cells an end test counts: countReachableFrontierCells(grid, costmap,
/// obstacle_l1_cells, &exhausted, robot_m, enough). When that reaches `enough`, the search is on
/// (pockets.min_area_m2 > 0) and the last one, at `last_search_s`, is pockets.period_s old or
/// more, the frontier cells opening onto pockets are first marked in `exhausted`, for good
/// (`last_search_s` becomes `time_s`), and the cells are counted again.
std::size_t countEndTestFrontierCells(const OccupancyGrid& grid, const Costmap& costmap,
                                      int obstacle_l1_cells, std::vector<std::uint8_t>& exhausted,
                                      const Vec2& robot_m, std::size_t enough,
                                      const EndTestPockets& pockets, double time_s,
                                      double& last_search_s);

}  // namespace roomscout
