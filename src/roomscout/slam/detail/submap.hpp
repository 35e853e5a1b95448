#pragma once
// A submap: an occupancy grid of a few consecutive scans in its own frame, as Cartographer
// builds them. Scans go in through OccupancyMapper, the same cell update as the robot's map;
// the grid grows to hold every scan. Its pose in the map frame is what the pose graph moves.

#include <memory>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"

namespace roomscout::slam::detail {

class Submap {
 public:
  /// An empty submap whose frame is `global_pose` in the map frame. `options` sets the cell
  /// size and the log-odds update.
  Submap(const Pose2& global_pose, const OccupancyGridOptions& options);
  Submap(const Submap&) = delete;
  Submap& operator=(const Submap&) = delete;

  /// Integrates a scan taken with the sensor at `T_submap_sensor`, beams cut at
  /// `max_range_m`. Returns the submap cells that may have changed (after any growth: the
  /// grid's cells at return).
  CellRect insert(const LaserScan& scan, const Pose2& T_submap_sensor);

  const OccupancyGrid& grid() const { return grid_; }
  /// Scans inserted.
  int scans() const { return scans_; }
  /// Bumped whenever the grid's geometry changes (growth), so cached views can tell.
  int geometryVersion() const { return geometry_version_; }

  Pose2 global_pose;      ///< the submap frame in the map frame (optimised)
  bool finished = false;  ///< no more scans go in

 private:
  void growToInclude(const Vec2& min_m, const Vec2& max_m);

  OccupancyGrid grid_;
  std::unique_ptr<OccupancyMapper> mapper_;
  int scans_ = 0;
  int geometry_version_ = 0;
};

}  // namespace roomscout::slam::detail
