#include "roomscout/sim/episode.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_set>

#include "roomscout/core/errors.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"
#include "roomscout/sim/exploration_truth.hpp"

namespace roomscout::sim {

MapMode EpisodeOptions::mapMode() const {
  if (map_mode == "fixed") return MapMode::kFixed;
  if (map_mode == "growing") return MapMode::kGrowing;
  throw OptionError("episode.map_mode must be \"fixed\" or \"growing\", not \"" + map_mode + "\"");
}

void EpisodeOptions::validate() const {
  if (!(dt_s > 0.0 && dt_s <= 0.5)) throw OptionError("episode.dt_s must be in (0, 0.5]");
  if (!(max_time_s >= 0.0)) throw OptionError("episode.max_time_s must be >= 0 (0 = automatic)");
  if (!(metrics_period_s > 0.0)) throw OptionError("episode.metrics_period_s must be > 0");
  if (!(completion_rate > 0.0 && completion_rate <= 1.0)) {
    throw OptionError("episode.completion_rate must be in (0, 1]");
  }
  if (!(stuck_timeout_s > 0.0)) throw OptionError("episode.stuck_timeout_s must be > 0");
  if (!(room_dwell_s >= 0.0)) throw OptionError("episode.room_dwell_s must be >= 0");
  mapMode();
  if (!(std::isfinite(map_margin_m) && map_margin_m >= 0.0)) {
    throw OptionError("episode.map_margin_m must be a finite number >= 0");
  }
}

std::vector<ParameterRef> EpisodeOptions::parameters() {
  return {
      {"dt_s", &dt_s, "simulation and control step [s]"},
      {"max_time_s", &max_time_s,
       "simulated time limit [s]; 0 = 600 s + 5 s per m^2 of reachable floor"},
      {"metrics_period_s", &metrics_period_s, "exploration rate sampling period [s]"},
      {"completion_rate", &completion_rate,
       "exploration rate that counts as fully explored (T98, L98)"},
      {"stuck_timeout_s", &stuck_timeout_s,
       "commanded motion blocked this long: the robot counts as blocked and backs off [s]"},
      {"room_dwell_s", &room_dwell_s, "time in a room before it counts as entered [s]"},
      {"map_mode", &map_mode,
       "map the Explorer sees: fixed (the world's extent) or growing (as a SLAM map grows)"},
      {"map_margin_m", &map_margin_m, "growing map: unknown border around the known area [m]"},
  };
}

void EpisodeConfig::resolve() {
  world.robot_radius_m = robot.radius_m;
  explorer.costmap.robot_radius_m = robot.radius_m;
  follower.max_linear_speed_mps = robot.max_linear_speed_mps;
  follower.max_angular_speed_radps = robot.max_angular_speed_radps;
  explorer.goals.goal_tolerance_m = follower.goal_tolerance_m;
  explorer.goals.lookahead_m = follower.lookahead_m;
  explorer.goals.laser_range_m = laser.range_max_m;
}

void EpisodeConfig::validate() const {
  world.validate();
  robot.validate();
  laser.validate();
  mapping.validate();
  follower.validate();
  episode.validate();
  noise.validate();
  slam.validate();
  explorer.validate();
}

std::vector<ParameterGroup> EpisodeConfig::groups() {
  // Fields mirrored from another group are not editable on their own.
  auto without = [](std::vector<ParameterRef> params,
                    std::initializer_list<std::string_view> names) {
    std::erase_if(params, [&](const ParameterRef& p) {
      return std::find(names.begin(), names.end(), p.name) != names.end();
    });
    return params;
  };
  std::vector<ParameterGroup> groups = {
      {"robot", robot.parameters()},
      {"world", without(world.parameters(), {"robot_radius_m"})},
      {"laser", laser.parameters()},
      {"mapping", mapping.parameters()},
      {"follower",
       without(follower.parameters(), {"max_linear_speed_mps", "max_angular_speed_radps"})},
      {"episode", episode.parameters()},
      {"noise", noise.parameters()},
      {"slam", slam.parameters()},
  };
  for (ParameterGroup& g : explorer.groups()) {
    if (g.name == "follower" || g.name == "laser") continue;  // mirrored (resolve())
    if (g.name == "costmap") g.parameters = without(std::move(g.parameters), {"robot_radius_m"});
    auto same = std::find_if(groups.begin(), groups.end(),
                             [&](const ParameterGroup& h) { return h.name == g.name; });
    if (same != groups.end()) {
      same->parameters.insert(same->parameters.end(), g.parameters.begin(), g.parameters.end());
    } else {
      groups.push_back(std::move(g));
    }
  }
  return groups;
}

TimingStats TimingStats::of(std::vector<double> samples_ms) {
  TimingStats s;
  s.count = samples_ms.size();
  if (samples_ms.empty()) return s;
  std::sort(samples_ms.begin(), samples_ms.end());
  auto at = [&](double q) {
    const double pos = q * static_cast<double>(samples_ms.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const auto hi = std::min(lo + 1, samples_ms.size() - 1);
    return samples_ms[lo] + (samples_ms[hi] - samples_ms[lo]) * (pos - static_cast<double>(lo));
  };
  s.median_ms = at(0.5);
  s.p95_ms = at(0.95);
  return s;
}

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

GridGeometry publishedGeometry(const GridGeometry& full, const CellRect& known, int margin) {
  const CellRect r = CellRect{known.min_x - margin, known.min_y - margin, known.max_x + margin,
                              known.max_y + margin}
                         .clippedTo(full.width(), full.height());
  const double res = full.resolution_m();
  return GridGeometry(full.origin_m() + Vec2(r.min_x * res, r.min_y * res), res, r.max_x - r.min_x,
                      r.max_y - r.min_y);
}

slam::SlamOptions slamOptionsFor(slam::SlamOptions options, const NoiseProfile& noise) {
  if (options.odometry_sd_per_m < 0.0)
    options.odometry_sd_per_m = noise.odometry.translation_sd_per_m;
  if (options.odometry_rotation_sd_per_rad < 0.0)
    options.odometry_rotation_sd_per_rad = noise.odometry.rotation_sd_per_rad;
  if (options.odometry_rotation_sd_per_m < 0.0)
    options.odometry_rotation_sd_per_m = noise.odometry.rotation_sd_per_m;
  if (options.range_sd_fraction < 0.0) options.range_sd_fraction = noise.laser.sd_fraction;
  return options;
}

ExplorerOptions explorerOptionsFor(const WorldModel& world, EpisodeConfig config) {
  config.resolve();
  ExplorerOptions options = config.explorer;
  if (options.goals.stall_min_new_area_m2 == 0.0) {
    const ExplorationTruth truth(world, mapGeometryFor(world, config.mapping.resolution_m),
                                 options.costmap.lethalRadius_m());
    options.goals.stall_min_new_area_m2 = 0.001 * truth.reachableArea_m2();
  }
  return options;
}

EpisodeResult runEpisode(const WorldModel& world, EpisodeConfig config,
                         ExplorationStrategy& strategy, std::uint64_t seed,
                         const EpisodeProgress& progress,
                         const std::vector<EpisodeObserver*>& observers) {
  config.resolve();
  config.validate();
  ExplorerOptions options = explorerOptionsFor(world, config);
  options.all_maps = false;
  Explorer explorer(strategy, options);
  return runEpisode(world, config, explorer, seed, progress, observers);
}

EpisodeResult runEpisode(const WorldModel& world, EpisodeConfig config, Explorer& explorer,
                         std::uint64_t seed, const EpisodeProgress& progress,
                         const std::vector<EpisodeObserver*>& observers) {
  const auto wall_start = Clock::now();
  config.resolve();
  config.validate();
  const EpisodeOptions& opt = config.episode;
  const bool growing = opt.mapMode() == MapMode::kGrowing;

  const GridGeometry map_geometry = mapGeometryFor(world, config.mapping.resolution_m);
  // Reachable = what the robot's navigation footprint (radius plus the planner's safety
  // margin) can cover: gaps the planner may never pass do not count as explorable.
  const ExplorationTruth truth(world, map_geometry, config.explorer.costmap.lethalRadius_m());
  ExplorationRateCounter rate_counter(truth);
  CellRect changed_since_sample;
  OccupancyGrid grid(map_geometry, config.mapping);
  OccupancyMapper mapper(grid);
  const NoiseProfile noise = config.noise.resolved();
  LaserSimulator laser(world, config.laser, seed ^ 0x9E3779B97F4A7C15ull, noise.laser);
  Robot robot(world, config.robot, world.start());
  // With SLAM the robot knows only its odometry and MRPT's estimate, at which it maps; the
  // exploration rate honestly counts that map as it lies in the world frame.
  std::unique_ptr<slam::Slam> slam;
  std::optional<OdometrySimulator> odometry;
  if (config.slam.slamMode() != slam::SlamMode::kNone) {
    slam = std::make_unique<slam::Slam>(slamOptionsFor(config.slam, noise), world.start(),
                                        seed ^ 0xD1B54A32D192ED03ull, config.mapping, map_geometry);
    odometry.emplace(noise.odometry, world.start(), seed ^ 0x94D049BB133111EBull);
  }
  // The graph SLAM renders the robot's map itself; the grid is kept a copy of it.
  const OccupancyGrid* slam_map = slam ? slam->map() : nullptr;
  Pose2 estimate = robot.pose();
  PathFollower follower(config.follower);
  // Growing mode: the map the Explorer sees, and the bounding box of the known cells.
  OccupancyGrid published;
  CellRect known_cells;
  const int margin_cells =
      static_cast<int>(std::ceil(opt.map_margin_m / map_geometry.resolution_m()));

  EpisodeResult result;
  result.reachable_area_m2 = truth.reachableArea_m2();
  const double max_time_s =
      opt.max_time_s > 0.0 ? opt.max_time_s : 600.0 + 5.0 * result.reachable_area_m2;
  result.max_time_s = max_time_s;

  const double scan_period_s = 1.0 / config.laser.rate_hz;
  std::vector<double> occupancy_ms;
  double t = 0.0;
  double next_scan_s = 0.0, next_metrics_s = 0.0;
  double blocked_for_s = 0.0;
  double rate = 0.0;
  int current_room = world.roomAt(robot.pose().position());
  int candidate_room = current_room;
  double candidate_since_s = 0.0;
  std::unordered_set<int> visited_rooms;
  if (current_room != 0) visited_rooms.insert(current_room);

  auto sampleMetrics = [&]() {
    rate_counter.update(grid, changed_since_sample);
    changed_since_sample = CellRect{};
    rate = rate_counter.rate();
    result.curve.push_back({t, robot.odometer_m(), rate});
    if (!result.t98_s && rate >= opt.completion_rate) {
      result.t98_s = t;
      result.l98_m = robot.odometer_m();
      result.revisits98 = result.revisits;
    }
  };

  while (true) {
    // 1. Sense and map.
    bool scanned = false;
    CellRect changed;
    if (t >= next_scan_s - 1e-9) {
      const LaserScan scan = laser.scan(robot.pose());
      if (slam) {
        // The SLAM estimates the pose from its own map. The graph SLAM's map is the robot's
        // map; with MRPT's the grid is built from every scan at the estimate, as a robot's
        // costmap is, so drift shows in it.
        const CellRect slam_changed = slam->update(scan, odometry->pose());
        estimate = slam->pose(odometry->pose());
        if (slam_map) {
          grid.copyCells(*slam_map, slam_changed);
          changed = slam_changed;
        }
      }
      if (!slam_map) {
        const auto start = Clock::now();
        changed = mapper.integrate(scan, estimate);
        occupancy_ms.push_back(msSince(start));
      }
      changed_since_sample.unite(changed);
      next_scan_s += scan_period_s;
      scanned = true;
      result.trajectory.push_back({t, robot.pose(), estimate});
    }
    if (t >= next_metrics_s - 1e-9) {
      sampleMetrics();
      next_metrics_s += opt.metrics_period_s;
      if (progress) progress(t, max_time_s, rate);
    }

    for (EpisodeObserver* o : observers)
      o->onStep(EpisodeSnapshot{t, robot.pose(), grid, world, scanned, estimate});

    // 2. Publish the map and ask the Explorer what to do.
    const OccupancyGrid* map = &grid;
    std::optional<CellRect> hint = changed;
    if (growing) {
      // The cells a scan touched are known (a hit or a miss classifies a cell at once).
      known_cells.unite(changed);
      const GridGeometry g = publishedGeometry(map_geometry, known_cells, margin_cells);
      if (g != published.geometry()) {
        published = grid.reframed(g);
        hint.reset();
      } else {
        published.copyCells(grid, changed);
        const Cell d = map_geometry.cellOf(g.centerOf(Cell{0, 0}));
        hint = changed.empty() ? changed
                               : CellRect{changed.min_x - d.x, changed.min_y - d.y,
                                          changed.max_x - d.x, changed.max_y - d.y};
      }
      map = &published;
    }
    const ExplorerCommand command = explorer.update(ExplorerInput{*map, estimate, t, hint});
    if (command.kind == ExplorerCommand::Kind::kDone) {
      result.t_done_s = t;
      result.l_done_m = robot.odometer_m();
      break;
    }

    // 3. Act: follow the commanded path, back off, or stand still.
    VelocityCommand velocity;
    switch (command.kind) {
      case ExplorerCommand::Kind::kDrive:
        if (command.new_path) follower.setPath(*command.path);
        velocity = follower.compute(estimate);
        break;
      case ExplorerCommand::Kind::kBackOff:
        follower.clear();
        velocity.linear_mps = -0.1;  // back off from whatever we are pressed against
        break;
      default:
        follower.clear();
        break;
    }
    const Pose2 before = robot.pose();
    const bool moved = robot.step(velocity, opt.dt_s);
    if (slam) {
      odometry->step(before, robot.pose());
      estimate = slam->pose(odometry->pose());
    } else {
      estimate = robot.pose();
    }
    if (velocity.linear_mps > 0.0 && !moved) {
      blocked_for_s += opt.dt_s;
      if (blocked_for_s >= opt.stuck_timeout_s) {
        blocked_for_s = 0.0;
        explorer.report(GoalOutcome::kBlocked, t);
      }
    } else {
      blocked_for_s = 0.0;
    }

    // 4. Rooms entered (a room counts after room_dwell_s inside it).
    const int room = world.roomAt(robot.pose().position());
    if (room == 0 || room == current_room) {
      candidate_room = current_room;
    } else if (room != candidate_room) {
      candidate_room = room;
      candidate_since_s = t;
    } else if (t - candidate_since_s >= opt.room_dwell_s) {
      if (!visited_rooms.insert(room).second) ++result.revisits;
      current_room = room;
    }

    t += opt.dt_s;
    if (t > max_time_s) {
      result.timed_out = true;
      break;
    }
  }

  if (slam) {
    // The last optimisation: the map and the trajectory as the SLAM ends them.
    const CellRect changed = slam->finish();
    if (slam_map && !changed.empty()) {
      grid.copyCells(*slam_map, changed);
      changed_since_sample.unite(changed);
      if (growing) {
        known_cells.unite(changed);
        published = grid.reframed(publishedGeometry(map_geometry, known_cells, margin_cells));
      }
    }
  }
  sampleMetrics();
  const OccupancyGrid& final_map = growing ? published : grid;
  explorer.finish(final_map);
  for (const AnalysisMap* m : {explorer.roomMap(), explorer.skeletonMap()}) {
    if (m != nullptr)
      result.map_updates[std::string(m->name())] = TimingStats::of(m->updateTimes_ms());
  }
  for (EpisodeObserver* o : observers) {
    o->onFinish(EpisodeSnapshot{t, robot.pose(), grid, world, true, estimate});
    result.map_updates[std::string(o->name())] = TimingStats::of(o->updateTimes_ms());
  }
  const ExplorerStats& stats = explorer.stats();
  result.goals = stats.goals;
  result.goal_failures = stats.goal_failures;
  result.recoveries = stats.recoveries;
  result.stalls = stats.stalls;
  result.exploration_rate = rate;
  result.sim_time_s = t;
  result.length_m = robot.odometer_m();
  result.rooms_entered = static_cast<int>(visited_rooms.size());
  result.room_truth = world.hasRooms();
  result.occupancy_update = TimingStats::of(std::move(occupancy_ms));
  result.costmap_update = TimingStats::of(stats.costmap_ms);
  result.decision = TimingStats::of(stats.decision_ms);
  if (slam) {
    result.slam_update = TimingStats::of(slam->updateTimes_ms());
    SlamResult s;
    s.mode = config.slam.mode;
    s.error = trajectoryError(result.trajectory);
    // The trajectory as the SLAM ends it (after its last optimisation).
    const std::vector<Pose2> final_poses = slam->trajectory();
    if (final_poses.size() == result.trajectory.size()) {
      for (std::size_t i = 0; i < final_poses.size(); ++i)
        result.trajectory[i].estimate = final_poses[i];
    }
    s.final_error = trajectoryError(result.trajectory);
    const slam::SlamStats stats = slam->stats();
    s.nodes = stats.nodes;
    s.loop_closures = stats.loop_closures;
    s.optimisations = stats.optimisations;
    s.matches_rejected = stats.matches_rejected;
    s.loop_search = TimingStats::of(stats.loop_search_ms);
    s.optimise = TimingStats::of(stats.optimise_ms);
    s.map_precision = mapPrecision(grid, world);
    s.diverged = s.error.rmse_m > config.slam.diverged_ate_m;
    result.slam = s;
  }
  result.map = growing ? std::move(published) : std::move(grid);
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return result;
}

}  // namespace roomscout::sim
