#pragma once
// explore_lite's greedy frontier exploration (Hörner, m-explore, 2016), the strategy most ROS
// users run: go to the frontier of lowest cost
//   cost = potential_scale * min_distance * resolution - gain_scale * size * resolution,
// where min_distance [m] is the Euclidean distance to the frontier's nearest cell and size its
// cell count. The extra resolution factor on both terms is explore_lite's own (so the size
// term dominates at 0.05 m cells); we keep it to stay faithful.

#include <vector>

#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct NearestFrontierOptions {
  double potential_scale = 3.0;
  double gain_scale = 1.0;
  double min_frontier_size_m = 0.3;
  double planner_period_s = 3.0;
  double progress_timeout_s = 30.0;
  double blacklist_radius_m = 0.25;
  double max_centroid_offset_m = 1.0;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

class NearestFrontier final : public ExplorationStrategy {
 public:
  explicit NearestFrontier(const NearestFrontierOptions& options = {}) : options_(options) {}

  std::string_view name() const override { return "nearest_frontier"; }
  Decision decide(const ExplorationInput& input) override;
  void onGoalFailed(const Vec2& goal_m) override { failed_.push_back(goal_m); }
  /// A stalled goal is given up as the progress watchdog gives one up: its frontier stays.
  void onGoalStalled(const Vec2& goal_m) override { slow_.push_back(goal_m); }
  double replanPeriod_s() const override { return options_.planner_period_s; }
  std::vector<ParameterRef> parameters() override { return options_.parameters(); }
  void validateOptions() const override { options_.validate(); }

 private:
  /// True when `p` lies within blacklist_radius_m (a box) of one of `goals`.
  bool near(const std::vector<Vec2>& goals, const Vec2& p) const;

  NearestFrontierOptions options_;
  std::vector<Vec2> failed_;  ///< goals the robot failed to reach (explore_lite's blacklist)
  std::vector<Vec2> slow_;    ///< goals the progress or stall watchdog gave up on
  bool has_previous_ = false;
  Vec2 previous_goal_m_ = Vec2::Zero();
  double previous_distance_m_ = 0.0;
  double last_progress_s_ = 0.0;
};

}  // namespace roomscout
