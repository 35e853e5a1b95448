#pragma once
// Integrates laser scans into an OccupancyGrid by ray tracing each beam (log-odds update).
// It never sees ground truth: only the scan and the sensor pose.

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"

#include <cstdint>
#include <vector>

namespace roomscout {

/// Inverse sensor model with OctoMap's per-scan set semantics (Hornung et al., 2013): within
/// one scan every cell is updated at most once, a cell that any beam ends in gets a hit, and
/// the cells beams cross, except those hit cells, get a miss. So grazing beams crossing the
/// free part of a wall-face cell cannot outvote the beams that hit the wall in it.
/// Across scans, a cell taken for a wall is not cleared by a beam running along that wall
/// (within 10 degrees of the line the cell forms with an occupied neighbour): such a beam
/// crosses the free part of the cell that holds the wall's face, and its misses would wear a
/// wall seen at grazing angles down to free cells with unknown behind them, frontiers no
/// robot can ever close (a 0.5 m corridor's walls, seen from along it). Beams at steeper
/// angles clear such a cell as before: an opened door still shows, and so do free cells that
/// pose drift (SLAM) has drawn walls on. A wider angle keeps more of those drift walls.
/// Beams without a return (+inf, as REP 117 has it) clear space up to the scan's
/// range_max_m; NaN, -inf and finite readings outside the scan's range carry no information.
class OccupancyMapper {
 public:
  explicit OccupancyMapper(OccupancyGrid& grid)
      : grid_(grid), stamp_(grid.geometry().cellCount(), 0) {}

  /// Updates the grid with one scan taken at `T_map_sensor`. Returns the rectangle of cells
  /// that may have changed (for incremental consumers such as a costmap).
  CellRect integrate(const LaserScan& scan, const Pose2& T_map_sensor);

 private:
  OccupancyGrid& grid_;
  std::vector<std::uint32_t> stamp_;  ///< 2*scan+1: hit in scan `scan`; 2*scan+2: missed in it
  std::uint32_t scan_ = 0;
  std::vector<std::size_t> hits_;
};

}  // namespace roomscout
