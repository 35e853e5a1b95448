#pragma once
// Refines a scan's pose against a submap as Cartographer's Ceres scan matcher does: every scan
// point should fall on a cell of high occupancy probability (the grid read bicubically), and
// the pose should stay near the prediction (odometry), each term weighted by its uncertainty.
// It then judges the match: enough points on walls, and walls in more than one direction. In
// a direction the walls do not pin (a corridor's length) the prediction is kept.

#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/slam/detail/probability_grid.hpp"

namespace roomscout::slam::detail {

struct ScanMatchOptions {
  /// Weight of the point term: sum over points of (weight / sqrt(n) * distance outside the
  /// paired wall cell / cell size)^2.
  double occupied_weight = 10.0;
  int max_iterations = 20;
  /// A match needs this many points on cells more likely occupied than not...
  int min_points_on_walls = 20;
  /// ... and walls in two directions: the weaker direction's information at least this
  /// fraction of the stronger's; along a weaker one the prediction is kept.
  double min_direction_ratio = 0.05;
};

struct ScanMatch {
  Pose2 pose;               ///< the refined pose (the prediction when rejected)
  bool accepted = false;    ///< enough points on walls
  bool degenerate = false;  ///< walls in one direction only: moved across them only
  int points_on_walls = 0;  ///< at the refined pose
  double score = 0.0;       ///< mean occupancy probability of the points at the pose
};

/// The mean occupancy probability of `points` (sensor frame) with the sensor at `pose`.
double scoreAt(const ProbabilityGrid& grid, const std::vector<Vec2>& points, const Pose2& pose);

/// Refines `prediction` (the sensor pose in the grid's frame) for `points` (sensor frame) on
/// `grid`; the prediction's standard deviations are `sd_m` (each axis) and `sd_rad`.
ScanMatch matchScan(const ProbabilityGrid& grid, const std::vector<Vec2>& points,
                    const Pose2& prediction, double sd_m, double sd_rad,
                    const ScanMatchOptions& options);
/// The same, starting the search from `initial` rather than from the prediction.
ScanMatch matchScan(const ProbabilityGrid& grid, const std::vector<Vec2>& points,
                    const Pose2& initial, const Pose2& prediction, double sd_m, double sd_rad,
                    const ScanMatchOptions& options);

}  // namespace roomscout::slam::detail
