#pragma once
// Integrates laser scans into an OccupancyGrid by ray tracing each beam (log-odds update).
// It never sees ground truth: only the scan and the sensor pose.

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout {

/// Beam-wise inverse sensor model: cells a beam crosses get a miss, its end cell a hit.
/// Beams without a return clear space up to the scan's range_max_m.
class OccupancyMapper {
 public:
  explicit OccupancyMapper(OccupancyGrid& grid) : grid_(grid) {}

  /// Updates the grid with one scan taken at `T_map_sensor`. Returns the rectangle of cells
  /// that may have changed (for incremental consumers such as a costmap).
  CellRect integrate(const LaserScan& scan, const Pose2& T_map_sensor);

 private:
  OccupancyGrid& grid_;
};

}  // namespace roomscout
