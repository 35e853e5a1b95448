#pragma once
// The simulated robot in its world, stepped on a simulated clock: the robot and its motion,
// the laser (with noise), the odometry, the optional SLAM, the occupancy mapper, the map it
// publishes (the world's extent, or grown as a SLAM package grows it) and the ground-truth
// scoring (exploration rate, T98 and L98, rooms entered, trajectory). Whatever decides where
// to go drives it through sense(), publishMap(), act() and step(); runEpisode (the CLI) and
// roomscout_sim_node (ROS) both do, so the simulation is written once.

#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_set>
#include <vector>

#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"
#include "roomscout/planning/path_follower.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/laser_simulator.hpp"
#include "roomscout/sim/robot.hpp"
#include "roomscout/sim/sensor_noise.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/slam/slam.hpp"

namespace roomscout::sim {

/// What sense() observed at the current time.
struct Sensed {
  std::optional<LaserScan> scan;  ///< the scan taken now, if one was due
  CellRect changed;               ///< mapper cells the scan may have changed (empty: none)
  bool sampled = false;           ///< the exploration rate was sampled now
};

/// The map as published to the explorer, and the cells that changed since the last call.
struct PublishedMap {
  const OccupancyGrid& grid;
  std::optional<CellRect> changed;  ///< none: any cell may have changed (a new geometry)
};

/// Call order per step: sense(), publishMap() (when the map is due), act(), step(); finish()
/// once at the end, then takeResult(). Deterministic for a world, config and seed. Not
/// thread-safe.
class Simulation {
 public:
  /// `world` must outlive the simulation. `config` is resolved and validated here; throws
  /// OptionError when an option is out of range.
  Simulation(const WorldModel& world, EpisodeConfig config, std::uint64_t seed);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Takes a scan and maps it when one is due, and samples the exploration rate when due.
  Sensed sense();
  /// Brings the published map up to date with everything mapped since the last call.
  PublishedMap publishMap();
  /// Drives the robot for one step. Returns true when the robot has been blocked (commanded
  /// forward but not moving) for episode.stuck_timeout_s: a collision to report.
  bool act(const VelocityCommand& command);
  /// Advances the clock by one step; false once the time limit is passed (timedOut()).
  bool step();
  /// The final sample of the rate; call once, at the end.
  void finish();
  /// Everything the simulation measured (not the explorer's counters), the final map moved
  /// out. Call once, after finish().
  EpisodeResult takeResult();

  const EpisodeConfig& config() const { return config_; }
  /// The Explorer's options for this robot in this world (explorerOptionsFor()).
  ExplorerOptions explorerOptions() const {
    return explorerOptionsFor(config_, truth_.reachableArea_m2());
  }
  const WorldModel& world() const { return world_; }
  double time_s() const { return t_; }
  double maxTime_s() const { return max_time_s_; }
  bool timedOut() const { return timed_out_; }
  /// Exploration rate at the last sample, in [0, 1].
  double rate() const { return rate_; }
  std::optional<double> t98_s() const { return t98_s_; }
  std::optional<double> l98_m() const { return l98_m_; }
  double reachableArea_m2() const { return truth_.reachableArea_m2(); }
  double odometer_m() const { return robot_.odometer_m(); }
  /// The true pose.
  const Pose2& robotPose() const { return robot_.pose(); }
  /// The pose the robot believes: the SLAM estimate, or the true pose without SLAM.
  const Pose2& estimate() const { return estimate_; }
  /// The wheel odometry's pose (the true pose without SLAM, which draws no odometry noise).
  const Pose2& odometryPose() const { return odometry_ ? odometry_->pose() : robot_.pose(); }
  bool hasSlam() const { return slam_ != nullptr; }
  /// The mapper's grid over the world's extent.
  const OccupancyGrid& grid() const { return grid_; }
  /// The map as last published.
  const OccupancyGrid& publishedGrid() const { return growing_ ? published_ : grid_; }

 private:
  /// The SLAM step: the scan updates the SLAM with the odometry, the estimate follows, and the
  /// scan is mapped at the estimate (with no SLAM, at the true pose).
  CellRect localizeAndMap(const LaserScan& scan);
  void sampleMetrics();
  void trackRooms();

  const WorldModel& world_;
  EpisodeConfig config_;
  bool growing_ = false;
  GridGeometry map_geometry_;
  ExplorationTruth truth_;
  ExplorationRateCounter rate_counter_;
  OccupancyGrid grid_;
  OccupancyMapper mapper_;
  LaserSimulator laser_;
  Robot robot_;
  std::unique_ptr<slam::Slam> slam_;
  std::optional<OdometrySimulator> odometry_;
  Pose2 estimate_;

  // The published map: growing, the known cells' bounding box plus the margin.
  OccupancyGrid published_;
  CellRect known_cells_;
  CellRect changed_since_publish_;
  int margin_cells_ = 0;

  double t_ = 0.0;
  double max_time_s_ = 0.0;
  bool timed_out_ = false;
  double next_scan_s_ = 0.0, next_metrics_s_ = 0.0;
  double blocked_for_s_ = 0.0;

  // Scoring.
  CellRect changed_since_sample_;
  double rate_ = 0.0;
  std::optional<double> t98_s_, l98_m_;
  std::optional<int> revisits98_;
  int revisits_ = 0;
  int current_room_ = 0, candidate_room_ = 0;
  double candidate_since_s_ = 0.0;
  std::unordered_set<int> visited_rooms_;
  std::vector<CurveSample> curve_;
  std::vector<TrajectorySample> trajectory_;
  std::vector<double> occupancy_ms_;
};

}  // namespace roomscout::sim
