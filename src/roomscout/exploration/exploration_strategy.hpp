#pragma once
// The interface every exploration strategy implements, and what it is given to decide.

#include <string_view>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/planning/costmap.hpp"

namespace roomscout {

class SemanticMap;

/// What a strategy sees when it decides: the current map, its costmap (updated from that map
/// just before the call), the robot pose and the clock. Never ground truth.
/// The map's geometry may differ from one call to the next, as a SLAM map's does when it grows
/// and its origin moves (normally by whole cells, the resolution kept): a strategy keeps what
/// it remembers in the map frame and never indexes one grid's cells with another's.
struct ExplorationInput {
  const OccupancyGrid& grid;
  const Costmap& costmap;
  Pose2 robot;
  double time_s = 0.0;  ///< time since the episode started [s] (simulated or wall clock)
  const SemanticMap* semantic = nullptr;  ///< rooms of the current map, when one is built
};

/// The outcome of one decision. An expected outcome, not an error.
struct Decision {
  enum class Status {
    kGoal,  ///< drive to `goal_m`
    kDone,  ///< exploration is over: nothing reachable is left to explore
  };
  Status status = Status::kDone;
  Vec2 goal_m = Vec2::Zero();

  static Decision goal(const Vec2& goal_m) { return {Status::kGoal, goal_m}; }
  static Decision done() { return {Status::kDone, Vec2::Zero()}; }
};

/// An exploration strategy: turns the map and pose into the next goal.
///
/// Contract, in call order:
/// 1. parameters() may be edited, then validateOptions() is called once; both before decide().
/// 2. decide() is called when the robot has no goal, when it reached or failed its goal, and
///    every replanPeriod_s() while it drives (0 = only on those events). A returned goal is
///    never inside an obstacle or the costmap's lethal inflation.
/// 3. onGoalReached()/onGoalFailed() report what became of the goal last returned.
/// Implementations are deterministic for a given seed and input sequence. Not thread-safe.
class ExplorationStrategy {
 public:
  virtual ~ExplorationStrategy() = default;

  virtual std::string_view name() const = 0;
  virtual Decision decide(const ExplorationInput& input) = 0;
  virtual void onGoalReached(const Vec2& /*goal_m*/) {}
  /// The robot could not reach the goal (no path, no progress, or stuck).
  virtual void onGoalFailed(const Vec2& /*goal_m*/) {}
  /// The runner's stall watchdog gave up on the goal: the robot dithered in one place, seeing
  /// nothing new, while decisions flipped between goals. The goal may well be reachable; by
  /// default this counts as a failure all the same.
  virtual void onGoalStalled(const Vec2& goal_m) { onGoalFailed(goal_m); }
  /// Seconds between decisions while a goal is active; 0 means only on events.
  virtual double replanPeriod_s() const { return 0.0; }
  /// True when decide() reads ExplorationInput::semantic. Only then does a runner hand it the
  /// rooms, and keep them up to date before each decision; otherwise it may build them in
  /// the background.
  virtual bool readsRooms() const { return false; }
  /// The frontier points the strategy picks its goals among, as of its last decide(), for
  /// display (e.g. rviz markers); empty for strategies that keep no such list and read
  /// frontier cells off the map at each decision.
  virtual std::vector<Vec2> candidateGoals() const { return {}; }

  /// The strategy's tunable options, for configuration files and run records.
  virtual std::vector<ParameterRef> parameters() { return {}; }
  /// Throws OptionError when an option is out of range.
  virtual void validateOptions() const {}
};

}  // namespace roomscout
