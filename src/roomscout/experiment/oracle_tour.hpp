#pragma once
// A reference for exploration lengths: the tour a robot that already knew the whole map would
// drive to see the reachable free space. Viewpoints are chosen by greedy set cover of what the
// laser sees from candidate positions on the ground truth, and ordered by a TSP heuristic
// (nearest neighbour, then 2-opt and Or-opt) over geodesic distances from the start. Both
// steps are heuristics, and what the laser sees while driving between viewpoints is not
// counted, so the length is a reference, not a proven optimum or bound; exploration methods
// that do not know the map usually drive well beyond it.

#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {
struct EpisodeConfig;
}  // namespace roomscout::sim

namespace roomscout::experiment {

/// Its fields are documented in parameters(); no config group sets them (see
/// oracleTourOptionsFor()), so `roomscout options` does not print them.
struct OracleTourOptions {
  double map_resolution_m = 0.05;
  double lethal_radius_m = 0.155;
  double sensor_range_m = 3.5;
  int rays_per_viewpoint = 360;
  double viewpoint_spacing_m = 0.5;
  double visibility_cell_m = 0.1;
  double target_coverage = 0.98;
  bool smooth_legs = true;

  /// Throws OptionError when a value is out of range.
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// The oracle options matching an episode's: map resolution, the costmap's lethal radius (with
/// the robot group's radius) and the laser's range.
OracleTourOptions oracleTourOptionsFor(const sim::EpisodeConfig& config);

struct OracleTour {
  double length_m = 0.0;              ///< open tour: start, then every viewpoint in order [m]
  double coverage = 0.0;              ///< fraction of the reachable free space seen from the
                                      ///< start and the viewpoints, in [0, 1]
  std::vector<Vec2> viewpoints_m;     ///< in visiting order, start excluded (map frame)
  std::vector<double> leg_lengths_m;  ///< leg k ends at viewpoints_m[k]
  std::vector<Vec2> path_m;           ///< the whole tour as one polyline from the start
  int candidates = 0;                 ///< candidate viewpoints considered
  double reachable_area_m2 = 0.0;     ///< the exploration truth's reachable free area

  std::size_t viewpointCount() const { return viewpoints_m.size(); }
};

/// Plans the oracle tour from the world's start pose. Deterministic (no randomness; ties go to
/// the lower cell index). When the target coverage cannot be reached (space visible only from
/// places the robot cannot go) the tour covers what it can and `coverage` says how much.
/// Throws OptionError when `options` are invalid.
OracleTour planOracleTour(const sim::WorldModel& world, const OracleTourOptions& options = {});

}  // namespace roomscout::experiment
