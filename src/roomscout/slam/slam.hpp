#pragma once
// SLAM for a robot that does not know where it is: its 2D laser scans and wheel odometry go to
// roomscout's graph SLAM (scan-to-submap matching with an odometry prior, loop closure, a pose
// graph solved by Ceres; it renders the robot's map itself, as Cartographer and slam_toolbox
// publish /map), or to MRPT's ICP-SLAM or Rao-Blackwellised particle-filter SLAM, which
// estimate the pose against a map of laser points; with those the caller builds the occupancy
// grid from every scan at the estimate (OccupancyMapper). MRPT and Ceres stay behind this
// header: callers see our scan, pose and grid types only.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <optional>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout::slam {

enum class SlamMode {
  kNone,   ///< no SLAM: the caller knows the true pose and maps with it
  kGraph,  ///< roomscout's graph SLAM: submaps, loop closure, a pose graph (Ceres)
  kIcp,    ///< MRPT CMetricMapBuilderICP: each scan aligned by ICP with the points seen so far
  kRbpf,   ///< MRPT CMetricMapBuilderRBPF: particles with a map of points each, ICP-based
           ///< optimal proposal
};

/// The config group "slam".
/// Its fields are documented in parameters() and printed by `roomscout options`.
struct SlamOptions {
  std::string mode = "none";
  double match_distance_m = 0.1;
  double match_angle_deg = 5.0;
  double insert_distance_m = 0.2;
  double insert_angle_deg = 10.0;
  int particles = 10;
  double diverged_ate_m = 1.0;
  // graph
  int submap_scans = 40;
  double max_range_m = 15.0;
  double odometry_sd_per_m = -1.0;  ///< < 0: automatic (see parameters())
  double odometry_rotation_sd_per_rad = -1.0;
  double odometry_rotation_sd_per_m = -1.0;
  double range_sd_fraction = -1.0;  ///< < 0: automatic (see parameters())
  double loop_search_distance_m = 2.5;
  double loop_window_m = 1.0;
  double loop_window_deg = 20.0;
  double loop_min_score = 0.6;
  int loop_every_n_nodes = 4;
  int optimise_every_n_nodes = 30;
  double huber_scale = 2.0;

  /// Throws OptionError naming the key for an unknown mode or a value out of range.
  SlamMode slamMode() const;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// What the graph SLAM did (zero for the other modes).
struct SlamStats {
  int nodes = 0;  ///< scans that became graph nodes
  int submaps = 0;
  int matches_rejected = 0;    ///< scan matches refused (too few points on walls, or too far
                               ///< from the odometry for its uncertainty): odometry used
  int matches_degenerate = 0;  ///< accepted across walls in one direction only
  int loop_closures = 0;       ///< constraints found, verified and added
  int optimisations = 0;
  std::vector<double> loop_search_ms;  ///< wall time per loop-closure search
  std::vector<double> optimise_ms;     ///< wall time per optimisation (with re-rendering)
};

/// One SLAM run from a known start pose, whose frame becomes the map frame. Not
/// thread-safe; several instances may run on different threads (rbpf's calls into MRPT's
/// global random generator are serialised and reseeded from `seed`, so a run is repeatable).
class Slam {
 public:
  /// The robot starts at `start` in the map frame (its odometry too). Throws OptionError for
  /// bad options (or mode "none") and InvalidArgument when MRPT fails to initialise.
  /// `cells` sets the cell size and log-odds update of the graph SLAM's submaps and map; with
  /// `map_geometry` the graph SLAM renders the robot's map on that geometry (map()).
  Slam(const SlamOptions& options, const Pose2& start, std::uint64_t seed,
       const OccupancyGridOptions& cells = {}, std::optional<GridGeometry> map_geometry = {});
  ~Slam();
  Slam(const Slam&) = delete;
  Slam& operator=(const Slam&) = delete;

  /// One scan, taken with the robot at odometry pose `odometry` (the laser at the robot's
  /// centre). Returns the cells of map() that changed (all of them after an optimisation moved
  /// the map). NaN and negative ranges are dropped beams. Throws InvalidArgument for a scan of
  /// fewer than two beams or a non-finite pose.
  CellRect update(const LaserScan& scan, const Pose2& odometry);

  /// The estimated pose of a robot now at odometry pose `odometry`: the last SLAM estimate
  /// moved on by the odometry since (the map -> odom correction of a ROS robot).
  Pose2 pose(const Pose2& odometry) const;
  /// Ends the run: a SLAM with a back end runs its last optimisation. update() may not be
  /// called afterwards. Returns the cells of map() that changed.
  CellRect finish();
  /// The robot's map as the graph SLAM renders it, when it was given a map geometry; null
  /// otherwise.
  const OccupancyGrid* map() const;
  SlamStats stats() const;
  /// One pose per update() call: the SLAM's estimate of where the robot was when it took that
  /// scan, as of now (after the latest optimisation, for a SLAM that optimises).
  std::vector<Pose2> trajectory() const;
  SlamMode mode() const;
  /// Wall time of each update() [ms].
  const std::vector<double>& updateTimes_ms() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace roomscout::slam
