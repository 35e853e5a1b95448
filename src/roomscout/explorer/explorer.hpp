#pragma once
// The explore loop a robot runs. Each cycle, give it the latest occupancy grid (any size,
// resolution and origin, as a SLAM package publishes it), the robot's pose and the time on
// any clock; it answers with what to do next: drive to a goal along the path it planned,
// back off, wait, or stop because nothing reachable is left to explore. Tell it what became
// of a goal when whatever drives the robot knows (reached, failed, blocked).
//
// Inside: the strategy, the costmap and the A* planner, the rooms and the skeleton graph on
// their schedule (on a background thread when asked), and the goal watchdogs, which judge from
// what a robot has (its pose over time, the map, the driver's path when reported): a path
// through newly seen obstacles is replanned, a goal whose path stops shrinking or whose robot
// dithers without mapping anything new fails, a robot reported blocked backs off, and every
// failed goal is reported to the strategy, which keeps its own blacklist. Knows nothing of the
// simulator, files or the command line; our simulator drives it as a robot's loop would.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/explorer/analysis_maps.hpp"
#include "roomscout/explorer/map_worker.hpp"
#include "roomscout/planning/astar_planner.hpp"
#include "roomscout/planning/costmap.hpp"
#include "roomscout/planning/path_progress.hpp"

namespace roomscout {

/// The Explorer's group "explorer": what it knows of the robot (the sensor's range), when a
/// goal counts as reached, and the watchdogs that fail a goal the robot makes no progress
/// towards. Its fields are documented in parameters() and printed by `roomscout options`.
struct GoalWatchdogOptions {
  double sensor_range_m = 3.5;
  double arrival_tolerance_m = 0.15;
  double progress_lookahead_m = 0.35;
  double no_progress_timeout_s = 45.0;
  double recovery_time_s = 1.5;
  double stall_timeout_s = 60.0;
  double stall_radius_m = 4.0;
  double stall_min_new_area_m2 = 1.0;
  int max_decisions_per_step = 8;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Every option of an Explorer, in the YAML groups its robot's config file sets: "costmap"
/// (with the robot's radius), "planner", "explorer", "maps", "segmentation", "topology".
struct ExplorerOptions {
  CostmapOptions costmap;        ///< group "costmap"
  AStarOptions planner;          ///< group "planner"
  GoalWatchdogOptions goals;     ///< group "explorer"
  AnalysisMapsOptions maps;      ///< groups "maps", "segmentation", "topology"
  bool all_maps = true;          ///< also build the rooms and skeleton graph a strategy does not
                                 ///< read (for display and saving); not in YAML
  bool background_maps = false;  ///< build the maps the strategy does not read on a background
                                 ///< thread below the caller's priority; not in YAML
  void validate() const;
  std::vector<ParameterGroup> groups();
  /// Former names of its options, accepted for one release with a warning.
  static std::vector<RenamedOption> renamedOptions();
};

/// One cycle's input.
struct ExplorerInput {
  ExplorerInput(const OccupancyGrid& grid, const Pose2& robot, double time_s,
                std::optional<CellRect> changed = std::nullopt)
      : grid(grid), robot(robot), time_s(time_s), changed(changed) {}

  const OccupancyGrid& grid;  ///< the latest map; may differ in size and origin from the last
  Pose2 robot;                ///< robot pose in the grid's frame
  double time_s = 0.0;        ///< any clock that never goes backwards [s]
  /// Cells that may differ from the previous cycle's grid, a hint that saves work (e.g. the
  /// union of the mapper's changed rectangles; empty when nothing changed). None: any may.
  std::optional<CellRect> changed;
  /// The path the driver follows to the current goal, when it reports one (e.g. move_base's
  /// global plan), in the grid's frame: the no-progress watchdog measures the robot's progress
  /// along it. Null or empty: along the path the Explorer planned. Read during the call only.
  const Path* driver_path = nullptr;
};

/// What the robot should do now.
struct ExplorerCommand {
  enum class Kind {
    kDrive,    ///< drive to goal_m along path
    kBackOff,  ///< back away slowly from what blocks the robot (a recovery)
    kWait,     ///< stand still: no goal at the moment (see reason)
    kDone,     ///< exploration is over: nothing reachable is left to explore
  };
  Kind kind = Kind::kWait;
  Vec2 goal_m = Vec2::Zero();  ///< kDrive: the goal
  bool new_path = false;       ///< kDrive: path differs from the last command's (a new goal or a
                               ///< replanned path): send it to the driver again
  const Path* path = nullptr;  ///< kDrive: the planned path; valid until the next call
  std::string_view reason;     ///< a few words for a status display
};

/// What the driver saw become of the current goal. Reports of a goal that was already
/// replaced are harmless: they apply to the Explorer's current goal, if any.
enum class GoalOutcome {
  kReached,  ///< the driver arrived (e.g. move_base succeeded)
  kFailed,   ///< the driver gave up (aborted, rejected)
  kBlocked,  ///< the robot cannot move: fail the goal and back off for recovery_time_s
};

/// Counters and timings of an Explorer's run.
struct ExplorerStats {
  int goals = 0;          ///< goals sent to the driver
  int goal_failures = 0;  ///< goals that failed (unplannable, no progress, stalled, blocked)
  int recoveries = 0;     ///< back-offs after the robot was blocked
  int stalls = 0;         ///< goals failed by the stall watchdog
  std::vector<double> costmap_ms;   ///< wall time of each costmap refresh [ms]
  std::vector<double> decision_ms;  ///< wall time of each strategy decision [ms]
};

/// Not thread-safe: one thread calls update(), report() and finish().
class Explorer {
 public:
  /// Owns the strategy. Throws OptionError when an option is out of range.
  Explorer(std::unique_ptr<ExplorationStrategy> strategy, const ExplorerOptions& options = {});
  /// Borrows the strategy, which must outlive the Explorer.
  Explorer(ExplorationStrategy& strategy, const ExplorerOptions& options = {});
  ~Explorer();
  Explorer(const Explorer&) = delete;
  Explorer& operator=(const Explorer&) = delete;

  /// One cycle. Throws InvalidArgument naming the value for an empty grid, a non-finite pose
  /// or time, or a time before the previous call's. A robot outside the grid gets kWait until
  /// the map covers it again. Once kDone, every later call answers kDone.
  ExplorerCommand update(const ExplorerInput& input);
  /// What became of the current goal, at `time_s` (same clock; not before the last update).
  void report(GoalOutcome outcome, double time_s);
  /// Brings the rooms and skeleton graph up to date with the final grid (waits for the
  /// background thread). Call once, at the end.
  void finish(const OccupancyGrid& grid);

  bool done() const { return done_; }
  /// The goal being driven to, if any.
  std::optional<Vec2> goal() const { return goal_; }
  const ExplorationStrategy& strategy() const { return *strategy_; }
  const Costmap& costmap() const { return costmap_; }
  const ExplorerStats& stats() const { return stats_; }
  /// The rooms and skeleton graph (null when not built, see ExplorerOptions::all_maps). Built
  /// in the background, they are up to date only after finish().
  const AnalysisMap* roomMap() const { return rooms_.get(); }
  const AnalysisMap* skeletonMap() const { return skeleton_.get(); }

 private:
  /// Reports the goal failed (or, from the stall watchdog, stalled) and drops it.
  void failGoal(bool stalled = false);
  /// Reports the goal reached and drops it.
  void reachGoal();
  void applyPendingFailure();
  bool planTo(const Vec2& robot, const Vec2& target, double t);
  void refreshCostmap(const OccupancyGrid& grid);
  void stallWatchdog(const OccupancyGrid& grid, const Vec2& robot, double t);
  bool pathBlocked(const OccupancyGrid& grid, const Vec2& robot) const;
  double relative(double time_s, const char* what) const;

  std::unique_ptr<ExplorationStrategy> owned_;
  ExplorationStrategy* strategy_;
  ExplorerOptions options_;
  Costmap costmap_;
  AStarPlanner planner_;
  PathProgress progress_;         ///< the current goal's path and how far the robot came along it
  PathProgress driver_progress_;  ///< the same along the driver's path, when it reports one
  std::uint64_t path_version_ = 0, sent_path_version_ = 0;  ///< paths planned / sent so far
  std::unique_ptr<MapWorker> worker_;                       ///< before the maps, whose jobs it runs
  std::unique_ptr<AnalysisMap> rooms_, skeleton_;
  std::vector<Cell> lethal_disc_;
  double lethal_disc_resolution_m_ = 0.0;
  ExplorerStats stats_;

  std::optional<double> clock_start_s_;  ///< time_s of the first update: times are relative
  double last_time_s_ = 0.0;             ///< relative time of the last update
  bool done_ = false;
  std::optional<Vec2> goal_;
  bool need_decision_ = true;
  bool pending_failure_ = false;  ///< no progress seen at the last update: fail at the next call
  double next_decision_s_ = 0.0;
  double last_decision_s_ = -std::numeric_limits<double>::infinity();
  double recovery_until_s_ = -1.0;
  double best_remaining_m_ = 0.0;
  double last_progress_s_ = 0.0;
  bool map_changed_since_costmap_ = true;
  CellRect changed_since_costmap_;
  std::optional<GridGeometry> last_geometry_;
  // Stall watchdog, checked once a second: its window's start, known free cells and position,
  // and the farthest the robot went from there.
  double next_watchdog_s_ = 0.0;
  double stall_window_start_s_ = 0.0;
  double stall_window_free_m2_ = 0.0;
  Vec2 stall_window_position_ = Vec2::Zero();
  double stall_window_excursion_m_ = 0.0;
  bool stall_window_started_ = false;
};

}  // namespace roomscout
