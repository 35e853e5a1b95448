#pragma once
// A submap: an occupancy grid of a few consecutive scans in its own frame, as Cartographer
// builds them. Scans go in through OccupancyMapper, the same cell update as the robot's map;
// the grid grows to hold every scan. Its pose in the map frame is what the pose graph moves.

#include <memory>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"

namespace roomscout::slam::detail {

/// Where the walls of a submap's cells lie: per cell, the sum and count of the scan returns
/// that ended in it (submap frame). Their mean is where a wall's surface crosses the cell, to
/// well within the cell, with the range noise of many returns averaged.
class WallPoints {
 public:
  WallPoints() = default;
  explicit WallPoints(const GridGeometry& geometry)
      : geometry_(geometry), cells_(geometry.cellCount()) {}
  const GridGeometry& geometry() const { return geometry_; }
  /// Adds a return at `p` (submap frame), reached along the unit direction `beam`, to the
  /// cell `c` it ended in.
  void add(Cell c, const Vec2& p, const Vec2& beam);
  /// The same returns laid on a larger geometry of the same lattice.
  WallPoints reframed(const GridGeometry& geometry) const;
  int count(int x, int y) const {
    if (x < 0 || y < 0 || x >= geometry_.width() || y >= geometry_.height()) return 0;
    return static_cast<int>(cells_[geometry_.index(Cell{x, y})].n);
  }
  /// The mean return of cell (x, y); only for a cell with count() > 0.
  Vec2 mean(int x, int y) const {
    const Sum& s = cells_[geometry_.index(Cell{x, y})];
    return {s.x / s.n, s.y / s.n};
  }
  /// The sum of the directions of the beams that ended in cell (x, y): the side the wall was
  /// seen from (a thin wall's two faces lie in neighbouring cells, seen from opposite sides).
  Vec2 beams(int x, int y) const {
    const Sum& s = cells_[geometry_.index(Cell{x, y})];
    return {s.bx, s.by};
  }

 private:
  struct Sum {
    double x = 0.0, y = 0.0, n = 0.0, bx = 0.0, by = 0.0;
  };
  GridGeometry geometry_;
  std::vector<Sum> cells_;
};

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
  const WallPoints& walls() const { return walls_; }
  /// Scans inserted.
  int scans() const { return scans_; }
  /// Bumped whenever the grid's geometry changes (growth), so cached views can tell.
  int geometryVersion() const { return geometry_version_; }

  Pose2 global_pose;      ///< the submap frame in the map frame (optimised)
  bool finished = false;  ///< no more scans go in

 private:
  void growToInclude(const Vec2& min_m, const Vec2& max_m);

  OccupancyGrid grid_;
  WallPoints walls_;
  std::unique_ptr<OccupancyMapper> mapper_;
  int scans_ = 0;
  int geometry_version_ = 0;
};

}  // namespace roomscout::slam::detail
