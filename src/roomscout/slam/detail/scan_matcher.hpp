#pragma once
// Refines a scan's pose against a submap, with the odometry's prediction as a prior: each scan
// point is paired with the nearest wall of the submap (the mean of the returns that ended in a
// wall cell) and costs its distance to the line fitted to the wall points round it (point to
// line, as PLICP); points with no straight wall near them are left out. Solved by Ceres,
// pairing again from each solution. It then judges the match: enough points on walls, and
// walls in more than one direction; along a direction no wall pins (a corridor's length) the
// prediction is kept.

#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/slam/detail/probability_grid.hpp"
#include "roomscout/slam/detail/submap.hpp"

namespace roomscout::slam::detail {

struct ScanMatchOptions {
  /// Weight of the point term: sum over the n paired points of (weight / sqrt(n) * distance
  /// to the wall / cell size)^2.
  double occupied_weight = 10.0;
  int max_iterations = 20;
  /// The range noise (sd) as a fraction of the range: walls are fitted over windows wide
  /// enough for such returns to line up.
  double range_sd_fraction = 0.01;
  /// A match needs this many points paired with walls...
  int min_points_on_walls = 20;
  /// ... and walls in two directions: the weaker direction's information at least this
  /// fraction of the stronger's; along a weaker one the prediction is kept.
  double min_direction_ratio = 0.05;
};

struct ScanMatch {
  Pose2 pose;               ///< the refined pose (the prediction when rejected)
  bool accepted = false;    ///< enough points on walls
  bool degenerate = false;  ///< walls in one direction only: moved across them only
  int points_on_walls = 0;  ///< paired at the refined pose
  double score = 0.0;       ///< mean occupancy probability of the points at the pose
};

/// The mean occupancy probability of `points` (sensor frame) with the sensor at `pose`.
double scoreAt(const ProbabilityGrid& grid, const std::vector<Vec2>& points, const Pose2& pose);

/// Refines the sensor pose in the submap's frame for `points` (sensor frame), starting from
/// `initial`, with a prior centred on `prediction` of standard deviations `sd_m` (each axis)
/// and `sd_rad`. `grid` is the submap's occupancy (a wall cell is one more likely occupied
/// than not) and `walls` its wall points.
ScanMatch matchScan(const ProbabilityGrid& grid, const WallPoints& walls,
                    const std::vector<Vec2>& points, const Pose2& initial, const Pose2& prediction,
                    double sd_m, double sd_rad, const ScanMatchOptions& options);

}  // namespace roomscout::slam::detail
