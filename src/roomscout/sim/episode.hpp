#pragma once
// One exploration episode in the simulator: the robot senses, maps, asks its strategy for
// goals, plans and drives until the strategy declares the end or time runs out, while the
// harness scores the map against ground truth (DESIGN "Metrics").

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/planning/astar_planner.hpp"
#include "roomscout/planning/costmap.hpp"
#include "roomscout/planning/path_follower.hpp"
#include "roomscout/sim/episode_observer.hpp"
#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/robot.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {

struct EpisodeOptions {
  double dt_s = 0.05;                  ///< simulation and control step [s]
  double max_time_s = 0.0;             ///< simulated time limit [s]; 0 = 600 s + 5 s per m^2
                                       ///< of reachable floor
  double metrics_period_s = 1.0;       ///< how often the exploration rate is sampled [s]
  double completion_rate = 0.98;       ///< rate that counts as fully explored (T98, L98)
  double stuck_timeout_s = 2.0;        ///< commanded motion blocked this long: recovery [s]
  double no_progress_timeout_s = 45.0; ///< path to the goal not shrinking this long: goal failed [s]
  double recovery_time_s = 1.5;        ///< how long a recovery backs off [s]
  double stall_timeout_s = 60.0;       ///< window of the stall watchdog [s]
  double stall_radius_m = 4.0;         ///< a robot that stayed within this radius of where the
                                       ///< window began, while the rate grew < 0.1 %, is stalled [m]
  double room_dwell_s = 2.0;           ///< time inside a room before it counts as entered [s]
  int max_decisions_per_step = 8;      ///< failed goals tried in a row before waiting a second
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Every option an episode uses, grouped as in a config file. The robot group is
/// authoritative for the radius and speed limits, which are mirrored into the others.
struct EpisodeConfig {
  WorldModelOptions world;
  RobotOptions robot;
  LaserOptions laser;
  OccupancyGridOptions mapping;
  CostmapOptions costmap;
  AStarOptions planner;
  PathFollowerOptions follower;
  EpisodeOptions episode;

  /// Copies the robot's radius and limits into the groups that mirror them.
  void resolve();
  /// Throws OptionError when any option is out of range.
  void validate() const;
  /// The editable groups, for configuration files and run records.
  std::vector<ParameterGroup> groups();
};

/// Median and 95th percentile of a set of durations [ms].
struct TimingStats {
  std::size_t count = 0;
  double median_ms = 0.0;
  double p95_ms = 0.0;
  static TimingStats of(std::vector<double> samples_ms);
};

struct CurveSample {
  double time_s = 0.0;
  double length_m = 0.0;
  double rate = 0.0;
};

struct TrajectorySample {
  double time_s = 0.0;
  Pose2 pose;
};

struct EpisodeResult {
  double exploration_rate = 0.0;   ///< final, in [0, 1]
  std::optional<double> t98_s;     ///< first time the rate reached completion_rate
  std::optional<double> l98_m;     ///< distance driven by then
  std::optional<double> t_done_s;  ///< when the strategy declared the end
  std::optional<double> l_done_m;
  bool timed_out = false;
  double sim_time_s = 0.0;
  double length_m = 0.0;
  double max_time_s = 0.0;
  double reachable_area_m2 = 0.0;
  bool room_truth = false;         ///< the world has ground-truth rooms: without, the two
                                   ///< counts below are 0 and mean nothing
  int revisits = 0;                ///< entries into a ground-truth room entered before
  std::optional<int> revisits98;   ///< ... counted up to t98_s (none if never reached):
                                   ///< the revisits of the exploration itself, whatever the
                                   ///< strategy does once the map is complete
  int rooms_entered = 0;
  int goals = 0;
  int goal_failures = 0;
  int recoveries = 0;
  int stalls = 0;                  ///< goals failed by the stall watchdog
  double wall_time_s = 0.0;
  TimingStats occupancy_update;    ///< per scan: ray tracing into the grid
  TimingStats costmap_update;      ///< per decision
  TimingStats decision;            ///< strategy decide() per call
  std::map<std::string, TimingStats> map_updates;  ///< per observer, by its name()
  std::vector<CurveSample> curve;
  std::vector<TrajectorySample> trajectory;
  OccupancyGrid map;
};

/// Progress report for a caller's display: simulated time, limit, current rate.
using EpisodeProgress = std::function<void(double time_s, double max_time_s, double rate)>;

/// Runs one episode. The world model is shared read-only; everything else is created here
/// from `config` and `seed`, so the same inputs give the same result. `observers` build
/// further maps as the robot explores; the first one that has a semanticMap() feeds the
/// strategy's ExplorationInput::semantic, when the strategy readsRooms().
EpisodeResult runEpisode(const WorldModel& world, EpisodeConfig config, ExplorationStrategy& strategy,
                         std::uint64_t seed, const EpisodeProgress& progress = {},
                         const std::vector<EpisodeObserver*>& observers = {});

}  // namespace roomscout::sim
