#pragma once
// The graph SLAM behind slam.mode "graph", built as Cartographer 2D is:
// - local SLAM: each scan that moved far enough becomes a node, matched against the older of
//   two overlapping submaps with the odometry's prediction as a prior (matchScan()), then
//   inserted into both;
// - loop closure: some nodes are searched for, by branch and bound, in finished submaps near
//   them, the best pose refined and verified before it joins the graph;
// - a pose graph of submaps and nodes (PoseGraph, Ceres, Huber loss on loop closures), solved
//   after new loop closures every few nodes and at the end;
// - the robot's map rendered from every other submap (those partition the scans) at their
//   optimised poses: per node where it changed, all of it after an optimisation moved it.
// Everything runs in the caller's thread, so a run is repeatable.

#include <memory>
#include <optional>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/slam/detail/correlative_matcher.hpp"
#include "roomscout/slam/detail/probability_grid.hpp"
#include "roomscout/slam/detail/scan_matcher.hpp"
#include "roomscout/slam/detail/submap.hpp"
#include "roomscout/slam/pose_graph.hpp"

namespace roomscout::slam::detail {

struct GraphSlamOptions {
  double node_distance_m = 0.05;  ///< motion before a scan becomes a node...
  double node_angle_rad = 0.05;   ///< ... or turn
  int submap_scans = 40;          ///< nodes per submap; a new one starts every half of it
  double max_range_m = 0.0;       ///< beams cut at this range (0: the scan's own)
  // The odometry's uncertainty (standard deviations), for the prior and the consistency check.
  double odometry_sd_per_m = 0.1;
  double odometry_rotation_sd_per_rad = 0.2;
  double odometry_rotation_sd_per_m = 0.1;
  double min_sd_m = 1e-4;  ///< floor of the prior's sd: exact odometry is trusted all but exactly
  double min_sd_rad = 1e-4;
  double max_innovation_sd = 5.0;  ///< a match further from the prediction is rejected
  ScanMatchOptions match;
  // Loop closure.
  int loop_every_n_nodes = 4;
  double loop_search_distance_m = 2.5;
  double loop_window_m = 1.0;
  double loop_window_rad = 0.35;
  double loop_min_score = 0.6;
  int loop_max_candidates = 2;
  int loop_search_depth = 5;
  // Pose graph.
  double intra_sd_m = 0.01;  ///< a node in its submaps, at most (the odometry's if less)
  double intra_sd_rad = 0.005;
  double loop_sd_m = 0.05;
  double loop_sd_rad = 0.02;
  int optimise_every_n_nodes = 30;
  PoseGraphOptions graph;
};

struct GraphSlamStats {
  int nodes = 0;
  int submaps = 0;
  int matches_rejected = 0;
  int matches_degenerate = 0;
  int loop_closures = 0;
  int optimisations = 0;
  std::vector<double> loop_search_ms;  ///< per search (one node against its candidates)
  std::vector<double> optimise_ms;     ///< per optimisation, with the map's re-rendering
};

class GraphSlam {
 public:
  /// The odometry frame is the map frame until the first correction. With `map_geometry`,
  /// renders the robot's map on it; `cells` sets the cell size (of the submaps too) and the
  /// log-odds update.
  GraphSlam(const GraphSlamOptions& options, const OccupancyGridOptions& cells,
            std::optional<GridGeometry> map_geometry);
  ~GraphSlam();

  /// One scan (sanitised by the caller: NaN and negative ranges dropped) at odometry pose
  /// `odometry`. Returns the map cells that changed.
  CellRect update(const LaserScan& scan, const Pose2& odometry);
  /// Optimises the graph one last time (if it has loop closures since the last).
  CellRect finish();

  Pose2 pose(const Pose2& odometry) const;
  /// One pose per update(), at the current node poses.
  std::vector<Pose2> trajectory() const;
  const OccupancyGrid* map() const { return map_ ? &*map_ : nullptr; }
  const GraphSlamStats& stats() const { return stats_; }

 private:
  struct Node;
  struct SubmapEntry;

  std::vector<Vec2> pointsOf(const LaserScan& scan) const;
  void addSubmap(const Pose2& at);
  void insertNode(const LaserScan& scan, const Pose2& odometry, const Pose2& estimate,
                  std::vector<Vec2> points, double sd_m, double sd_rad, CellRect& changed);
  void searchLoopClosures(int node);
  /// Solves the graph; returns the map cells that changed.
  CellRect optimise();
  CellRect renderSubmapRect(int submap, const CellRect& local);
  CellRect render(const CellRect& rect);

  GraphSlamOptions options_;
  OccupancyGridOptions cells_;
  std::optional<OccupancyGrid> map_;
  std::vector<float> sums_;  ///< scratch: summed log-odds while rendering
  std::vector<std::unique_ptr<Node>> nodes_;
  std::vector<std::unique_ptr<SubmapEntry>> submaps_;
  std::vector<int> active_;  ///< indices of the (at most two) submaps scans go into
  PoseGraph graph_;
  bool pending_loops_ = false;
  int nodes_since_optimisation_ = 0;
  struct Sample {
    int node;
    Pose2 odometry_since;  ///< the odometry since that node
  };
  std::vector<Sample> samples_;
  GraphSlamStats stats_;
};

}  // namespace roomscout::slam::detail
