#include "roomscout/sim/simulation.hpp"

#include <chrono>
#include <cmath>
#include <utility>

#include "roomscout/sim/map_accuracy.hpp"

namespace roomscout::sim {

namespace {

using Clock = std::chrono::steady_clock;

/// Tolerance of the schedules (scan, metrics) against the accumulated time [s].
constexpr double kScheduleSlack_s = 1e-9;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

EpisodeConfig checked(EpisodeConfig config) {
  config.resolve();
  config.validate();
  return config;
}

}  // namespace

Simulation::Simulation(const WorldModel& world, EpisodeConfig config, std::uint64_t seed)
    : world_(world),
      config_(checked(std::move(config))),
      growing_(config_.episode.mapMode() == MapMode::kGrowing),
      map_geometry_(mapGeometryFor(world, config_.mapping.resolution_m)),
      // Reachable = what the robot's navigation footprint (radius plus the planner's safety
      // margin) can cover: gaps the planner may never pass do not count as explorable.
      truth_(world, map_geometry_, explorerOptionsFor(config_, 0.0).costmap.lethalRadius_m()),
      rate_counter_(truth_),
      grid_(map_geometry_, config_.mapping),
      mapper_(grid_),
      laser_(world, config_.laser, seed ^ 0x9E3779B97F4A7C15ull, config_.noise.resolved().laser),
      robot_(world, config_.robot, world.start()),
      estimate_(world.start()),
      margin_cells_(static_cast<int>(
          std::ceil(config_.episode.map_margin_m / map_geometry_.resolution_m()))) {
  // With SLAM the robot knows only its odometry and the SLAM's estimate, at which it maps; the
  // exploration rate honestly counts that map as it lies in the world frame.
  if (config_.slam.slamMode() != slam::SlamMode::kNone) {
    const NoiseProfile noise = config_.noise.resolved();
    slam_ =
        std::make_unique<slam::Slam>(slamOptionsFor(config_.slam, noise), world.start(),
                                     seed ^ 0xD1B54A32D192ED03ull, config_.mapping, map_geometry_);
    odometry_.emplace(config_.noise.resolved().odometry, world.start(),
                      seed ^ 0x94D049BB133111EBull);
  }
  estimate_ = robot_.pose();
  const double opt_max_s = config_.episode.max_time_s;
  max_time_s_ = opt_max_s > 0.0 ? opt_max_s : 600.0 + 5.0 * truth_.reachableArea_m2();
  current_room_ = world.roomAt(robot_.pose().position());
  candidate_room_ = current_room_;
  if (current_room_ != 0) visited_rooms_.insert(current_room_);
}

Simulation::~Simulation() = default;

CellRect Simulation::localizeAndMap(const LaserScan& scan) {
  if (slam_) {
    // The SLAM estimates the pose from its own map. The graph SLAM's map is the robot's map
    // (the grid is kept a copy of it); with MRPT's the grid is built from every scan at the
    // estimate, as a robot's costmap is, so drift shows in it.
    const CellRect changed = slam_->update(scan, odometry_->pose());
    estimate_ = slam_->pose(odometry_->pose());
    if (const OccupancyGrid* map = slam_->map()) {
      grid_.copyCells(*map, changed);
      return changed;
    }
  }
  const auto start = Clock::now();
  const CellRect changed = mapper_.integrate(scan, estimate_);
  occupancy_ms_.push_back(msSince(start));
  return changed;
}

Sensed Simulation::sense() {
  Sensed sensed;
  if (t_ >= next_scan_s_ - kScheduleSlack_s) {
    sensed.scan = laser_.scan(robot_.pose());
    sensed.changed = localizeAndMap(*sensed.scan);
    changed_since_sample_.unite(sensed.changed);
    changed_since_publish_.unite(sensed.changed);
    // The cells a scan touched are known (a hit or a miss classifies a cell at once).
    known_cells_.unite(sensed.changed);
    next_scan_s_ += 1.0 / config_.laser.rate_hz;
    trajectory_.push_back({t_, robot_.pose(), estimate_});
  }
  if (t_ >= next_metrics_s_ - kScheduleSlack_s) {
    sampleMetrics();
    next_metrics_s_ += config_.episode.metrics_period_s;
    sensed.sampled = true;
  }
  return sensed;
}

PublishedMap Simulation::publishMap() {
  const CellRect changed = changed_since_publish_;
  changed_since_publish_ = CellRect{};
  if (!growing_) return {grid_, changed};
  const GridGeometry g = publishedGeometry(map_geometry_, known_cells_, margin_cells_);
  if (g != published_.geometry()) {
    published_ = grid_.reframed(g);
    return {published_, std::nullopt};
  }
  published_.copyCells(grid_, changed);
  if (changed.empty()) return {published_, changed};
  const Cell d = map_geometry_.cellOf(g.centerOf(Cell{0, 0}));
  return {published_, CellRect{changed.min_x - d.x, changed.min_y - d.y, changed.max_x - d.x,
                               changed.max_y - d.y}};
}

bool Simulation::act(const VelocityCommand& command) {
  const double dt = config_.episode.dt_s;
  const Pose2 before = robot_.pose();
  const bool moved = robot_.step(command, dt);
  if (slam_) {
    odometry_->step(before, robot_.pose());
    estimate_ = slam_->pose(odometry_->pose());
  } else {
    estimate_ = robot_.pose();
  }
  bool blocked = false;
  if (command.linear_mps > 0.0 && !moved) {
    blocked_for_s_ += dt;
    if (blocked_for_s_ >= config_.episode.stuck_timeout_s) {
      blocked_for_s_ = 0.0;
      blocked = true;
    }
  } else {
    blocked_for_s_ = 0.0;
  }
  trackRooms();
  return blocked;
}

void Simulation::trackRooms() {
  // A room counts as entered after room_dwell_s inside it.
  const int room = world_.roomAt(robot_.pose().position());
  if (room == 0 || room == current_room_) {
    candidate_room_ = current_room_;
  } else if (room != candidate_room_) {
    candidate_room_ = room;
    candidate_since_s_ = t_;
  } else if (t_ - candidate_since_s_ >= config_.episode.room_dwell_s) {
    if (!visited_rooms_.insert(room).second) ++revisits_;
    current_room_ = room;
  }
}

bool Simulation::step() {
  t_ += config_.episode.dt_s;
  if (t_ > max_time_s_) timed_out_ = true;
  return !timed_out_;
}

void Simulation::sampleMetrics() {
  rate_counter_.update(grid_, changed_since_sample_);
  changed_since_sample_ = CellRect{};
  rate_ = rate_counter_.rate();
  curve_.push_back({t_, robot_.odometer_m(), rate_});
  if (!t98_s_ && rate_ >= config_.episode.completion_rate) {
    t98_s_ = t_;
    l98_m_ = robot_.odometer_m();
    revisits98_ = revisits_;
  }
}

void Simulation::finish() {
  if (slam_) {
    // The SLAM's last optimisation: the map and the trajectory as it ends them.
    const CellRect changed = slam_->finish();
    if (const OccupancyGrid* map = slam_->map(); map && !changed.empty()) {
      grid_.copyCells(*map, changed);
      changed_since_sample_.unite(changed);
      changed_since_publish_.unite(changed);
      known_cells_.unite(changed);
      publishMap();
    }
  }
  sampleMetrics();
}

EpisodeResult Simulation::takeResult() {
  EpisodeResult result;
  result.exploration_rate = rate_;
  result.map_accuracy = mapAccuracy(grid_, truth_, world_);
  result.t98_s = t98_s_;
  result.l98_m = l98_m_;
  result.timed_out = timed_out_;
  result.sim_time_s = t_;
  result.length_m = robot_.odometer_m();
  result.max_time_s = max_time_s_;
  result.reachable_area_m2 = truth_.reachableArea_m2();
  result.room_truth = world_.hasRooms();
  result.revisits = revisits_;
  result.revisits98 = revisits98_;
  result.rooms_entered = static_cast<int>(visited_rooms_.size());
  result.occupancy_update = TimingStats::of(std::move(occupancy_ms_));
  result.curve = std::move(curve_);
  result.trajectory = std::move(trajectory_);
  if (slam_) {
    result.slam_update = TimingStats::of(slam_->updateTimes_ms());
    SlamResult s;
    s.mode = config_.slam.mode;
    s.error = trajectoryError(result.trajectory);
    // The trajectory as the SLAM ends it (after its last optimisation).
    const std::vector<Pose2> final_poses = slam_->trajectory();
    if (final_poses.size() == result.trajectory.size()) {
      for (std::size_t i = 0; i < final_poses.size(); ++i)
        result.trajectory[i].estimate = final_poses[i];
    }
    s.final_error = trajectoryError(result.trajectory);
    const slam::SlamStats stats = slam_->stats();
    s.nodes = stats.nodes;
    s.loop_closures = stats.loop_closures;
    s.optimisations = stats.optimisations;
    s.matches_rejected = stats.matches_rejected;
    s.loop_search = TimingStats::of(stats.loop_search_ms);
    s.optimise = TimingStats::of(stats.optimise_ms);
    s.diverged = s.error.rmse_m > config_.slam.diverged_ate_m;
    result.slam = s;
  }
  result.map = growing_ ? std::move(published_) : std::move(grid_);
  return result;
}

}  // namespace roomscout::sim
