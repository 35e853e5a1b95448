#pragma once
// Maps built from the simulated sensors alongside the occupancy grid during an episode (the
// point cloud; the rooms and skeleton graph are the Explorer's). The runner shows every
// observer each simulation step; an observer decides when to update (its own period), times
// its updates, and keeps its map for the caller to write.

#include <optional>
#include <string_view>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::sim {

class WorldModel;

/// What an observer may look at after one simulation step.
struct EpisodeSnapshot {
  double time_s = 0.0;
  Pose2 robot;  ///< true pose: where simulated sensors see from
  const OccupancyGrid& grid;
  const WorldModel& world;        ///< ground truth: for simulated sensors only, never for maps
  bool grid_changed = false;      ///< a laser scan was integrated in this step
  std::optional<Pose2> estimate;  ///< the robot's own estimate, when it differs from the truth
  /// The pose maps are built at: the estimate, or the true pose when the robot is told it.
  const Pose2& believed() const { return estimate ? *estimate : robot; }
};

/// A map builder attached to an episode. Call order: onStep() once per step (after mapping,
/// before the Explorer decides), then onFinish() once. Not thread-safe.
class EpisodeObserver {
 public:
  virtual ~EpisodeObserver() = default;
  /// Key of its update times in metrics.json's update_ms (e.g. "semantic").
  virtual std::string_view name() const = 0;
  virtual void onStep(const EpisodeSnapshot& snapshot) = 0;
  /// The episode ended: bring the map up to date with the final grid.
  virtual void onFinish(const EpisodeSnapshot& snapshot) = 0;
  /// Wall-clock durations of its updates so far [ms].
  virtual const std::vector<double>& updateTimes_ms() const = 0;
};

}  // namespace roomscout::sim
