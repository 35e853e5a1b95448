#pragma once
// One exploration episode in the simulator: the robot senses and maps, hands the map to the
// library's Explorer as a robot's loop would, and drives the paths it commands until it
// declares the end or time runs out, while the harness scores the map against ground truth
// (DESIGN "Metrics").

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/explorer/explorer.hpp"
#include "roomscout/planning/path_follower.hpp"
#include "roomscout/sim/episode_observer.hpp"
#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/map_accuracy.hpp"
#include "roomscout/sim/robot.hpp"
#include "roomscout/sim/sensor_noise.hpp"
#include "roomscout/sim/slam_metrics.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/slam/slam.hpp"

namespace roomscout::sim {

/// How the simulator publishes its map to the Explorer.
enum class MapMode {
  kFixed,    ///< the whole world's extent from the start
  kGrowing,  ///< as SLAM packages do: the known area's bounding box plus map_margin_m, the
             ///< origin moving as the map grows
};

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct EpisodeOptions {
  double dt_s = 0.05;
  double max_time_s = 0.0;
  double metrics_period_s = 1.0;
  double completion_rate = 0.98;
  double stuck_timeout_s = 2.0;
  double room_dwell_s = 2.0;
  double stall_floor_fraction = 0.001;
  std::string map_mode = "fixed";
  double map_margin_m = 1.0;
  MapMode mapMode() const;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Every option an episode uses, grouped as in a config file. The robot group is
/// authoritative for the radius and speed limits, which are mirrored into the world and the
/// follower; explorerOptionsFor() tells the Explorer about the simulated robot.
struct EpisodeConfig {
  WorldModelOptions world;
  RobotOptions robot;
  LaserOptions laser;
  OccupancyGridOptions mapping;
  PathFollowerOptions follower;
  EpisodeOptions episode;
  /// Sensor and odometry noise. Without SLAM the robot is told its true pose and only the
  /// range noise matters.
  NoiseOptions noise;
  /// SLAM in the loop: with a mode other than none, the robot moves in the true world while
  /// the Explorer, the follower, the occupancy grid and the point cloud's keyframes use MRPT's
  /// estimate of its pose (docs/slam.md).
  roomscout::slam::SlamOptions slam;
  /// Costmap, planner, watchdogs, rooms and skeleton graph. What describes the robot (its
  /// radius, sensor range, arrival tolerance and look-ahead) and the stall threshold are set
  /// by explorerOptionsFor() from the groups above.
  ExplorerOptions explorer;

  /// Copies the robot's radius and limits into the world and the follower.
  void resolve();
  /// Throws OptionError when any option is out of range.
  void validate() const;
  /// The editable groups, for configuration files and run records.
  std::vector<ParameterGroup> groups();
  /// Former names of its options, accepted for one release with a warning.
  static std::vector<RenamedOption> renamedOptions();
};

/// Median and 95th percentile of a set of durations [ms].
struct TimingStats {
  std::size_t count = 0;
  double median_ms = 0.0;
  double p95_ms = 0.0;
  /// The updates of a map that grows, grouped by the area the map knew: bins up to 250,
  /// 500, 1000, ... m^2 (each twice the last), empty bins left out. Filled by ofGrowth() only.
  struct AreaBin {
    double known_max_m2 = 0.0;
    std::size_t count = 0;
    double median_ms = 0.0;
    double p95_ms = 0.0;
  };
  std::vector<AreaBin> by_known_area;
  static TimingStats of(std::vector<double> samples_ms);
  /// of(samples_ms) with by_known_area; known_m2[i]: the area known at update i.
  static TimingStats ofGrowth(const std::vector<double>& samples_ms,
                              const std::vector<double>& known_m2);
};

struct CurveSample {
  double time_s = 0.0;
  double length_m = 0.0;
  double rate = 0.0;
};

/// How SLAM did, against the truth.
struct SlamResult {
  std::string mode;             ///< slam.mode
  TrajectoryError error;        ///< of the poses used online (one per scan)
  TrajectoryError final_error;  ///< of the same poses as the SLAM ends them (graph: optimised)
  int nodes = 0;                ///< graph: scans that became nodes
  int loop_closures = 0;        ///< graph
  int optimisations = 0;        ///< graph
  int matches_rejected = 0;     ///< graph: scan matches refused (odometry used)
  TimingStats loop_search;      ///< graph: per loop-closure search
  TimingStats optimise;         ///< graph: per optimisation
  bool diverged = false;        ///< error.rmse_m above slam.diverged_ate_m: the run does not count
};

struct EpisodeResult {
  double exploration_rate = 0.0;   ///< final, in [0, 1]: ExplorationTruth::explorationRate() of
                                   ///< the robot's map (with SLAM, as it lies in the world frame)
  MapAccuracy map_accuracy;        ///< of the final map, in the world frame
  std::optional<double> t98_s;     ///< first time the rate reached completion_rate
  std::optional<double> l98_m;     ///< distance driven by then
  std::optional<double> t_done_s;  ///< when the strategy declared the end
  std::optional<double> l_done_m;
  bool timed_out = false;
  double sim_time_s = 0.0;
  double length_m = 0.0;
  double max_time_s = 0.0;
  double reachable_area_m2 = 0.0;
  bool room_truth = false;        ///< the world has ground-truth rooms: without, the two
                                  ///< counts below are 0 and mean nothing
  int revisits = 0;               ///< entries into a ground-truth room entered before
  std::optional<int> revisits98;  ///< ... counted up to t98_s (none if never reached):
                                  ///< the revisits of the exploration itself, whatever the
                                  ///< strategy does once the map is complete
  int rooms_entered = 0;
  int goals = 0;
  int goal_failures = 0;
  int recoveries = 0;  ///< back-offs after the robot was blocked
  int stalls = 0;      ///< goals failed by the stall watchdog
  double wall_time_s = 0.0;
  TimingStats occupancy_update;                    ///< per scan: ray tracing into the grid
  TimingStats costmap_update;                      ///< per decision
  TimingStats decision;                            ///< strategy decide() per call
  TimingStats slam_update;                         ///< per scan: the SLAM update (with SLAM only)
  std::map<std::string, TimingStats> map_updates;  ///< per observer, by its name()
  std::vector<CurveSample> curve;
  std::vector<TrajectorySample> trajectory;  ///< one per scan
  std::optional<SlamResult> slam;            ///< with SLAM only
  OccupancyGrid map;  ///< the final map as the Explorer saw it (growing: cropped)
};

/// Progress report for a caller's display: simulated time, limit, current rate.
using EpisodeProgress = std::function<void(double time_s, double max_time_s, double rate)>;

/// The map a SLAM package would publish: the known area's bounding box (cells of `full`) plus
/// `margin` cells, clipped to `full` (the simulator's mapper grid, the world's extent).
GridGeometry publishedGeometry(const GridGeometry& full, const CellRect& known, int margin);

/// The SLAM's options for a simulated robot with `noise`: an odometry or range noise model
/// left automatic (-1) is the simulated sensor's.
slam::SlamOptions slamOptionsFor(slam::SlamOptions options, const NoiseProfile& noise);

/// The Explorer's options for the simulated robot: config.explorer with the robot's radius,
/// the laser's range, the follower's goal tolerance and look-ahead, and a stall threshold of
/// episode.stall_floor_fraction of `reachable_area_m2`, the floor the robot can reach. The one
/// place where the simulator describes its robot to the Explorer.
ExplorerOptions explorerOptionsFor(EpisodeConfig config, double reachable_area_m2);

/// The same for `world`, whose reachable floor is measured here.
ExplorerOptions explorerOptionsFor(const WorldModel& world, const EpisodeConfig& config);

/// Runs one episode with `explorer`, made with explorerOptionsFor(world, config) and used up
/// (read its rooms and skeleton graph afterwards). The world model is shared read-only;
/// everything else is created here from `config` and `seed`, so the same inputs give the
/// same result. `observers` build further maps (the point cloud) as the robot explores.
EpisodeResult runEpisode(const WorldModel& world, EpisodeConfig config, Explorer& explorer,
                         std::uint64_t seed, const EpisodeProgress& progress = {},
                         const std::vector<EpisodeObserver*>& observers = {});

/// The same with an Explorer made here around `strategy`, building only the maps the
/// strategy reads.
EpisodeResult runEpisode(const WorldModel& world, EpisodeConfig config,
                         ExplorationStrategy& strategy, std::uint64_t seed,
                         const EpisodeProgress& progress = {},
                         const std::vector<EpisodeObserver*>& observers = {});

}  // namespace roomscout::sim
