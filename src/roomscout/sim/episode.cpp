#include "roomscout/sim/episode.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "roomscout/core/errors.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/simulation.hpp"

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
  if (!(stall_floor_fraction >= 0.0 && stall_floor_fraction <= 1.0)) {
    throw OptionError("episode.stall_floor_fraction must be in [0, 1]");
  }
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
      {"stall_floor_fraction", &stall_floor_fraction,
       "the Explorer's stall threshold (explorer.stall_min_new_area_m2) as a fraction of the "
       "world's reachable floor; 0 = never stalls"},
      {"map_mode", &map_mode,
       "map the Explorer sees: fixed (the world's extent) or growing (as a SLAM map grows)"},
      {"map_margin_m", &map_margin_m, "growing map: unknown border around the known area [m]"},
  };
}

void EpisodeConfig::resolve() {
  world.robot_radius_m = robot.radius_m;
  follower.max_linear_speed_mps = robot.max_linear_speed_mps;
  follower.max_angular_speed_radps = robot.max_angular_speed_radps;
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
  // What describes the robot comes from the groups above (explorerOptionsFor()).
  for (ParameterGroup& g : explorer.groups()) {
    if (g.name == "costmap") g.parameters = without(std::move(g.parameters), {"robot_radius_m"});
    if (g.name == "explorer") {
      g.parameters =
          without(std::move(g.parameters), {"sensor_range_m", "arrival_tolerance_m",
                                            "progress_lookahead_m", "stall_min_new_area_m2"});
    }
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

std::vector<RenamedOption> EpisodeConfig::renamedOptions() {
  std::vector<RenamedOption> renamed = ExplorerOptions::renamedOptions();
  for (RenamedOption& r : renamed) {
    if (r.old_name == "episode.stall_min_new_area_m2") {
      r.new_name.clear();
      r.note =
          "the simulator sets the Explorer's stall threshold from episode.stall_floor_fraction, "
          "a fraction of the world's reachable floor";
    }
  }
  return renamed;
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

TimingStats TimingStats::ofGrowth(const std::vector<double>& samples_ms,
                                  const std::vector<double>& known_m2) {
  TimingStats s = of(samples_ms);
  std::map<int, std::vector<double>> bins;  // bin k: known area up to 250 * 2^k m^2
  for (std::size_t i = 0; i < samples_ms.size() && i < known_m2.size(); ++i) {
    int k = 0;
    while (known_m2[i] > 250.0 * std::ldexp(1.0, k)) ++k;
    bins[k].push_back(samples_ms[i]);
  }
  for (auto& [k, samples] : bins) {
    const TimingStats b = of(std::move(samples));
    s.by_known_area.push_back({250.0 * std::ldexp(1.0, k), b.count, b.median_ms, b.p95_ms});
  }
  return s;
}

namespace {

using Clock = std::chrono::steady_clock;

/// The in-process driver: the Explorer's path followed by the path follower, or a back-off.
VelocityCommand driverCommand(const ExplorerCommand& command, PathFollower& follower,
                              const Pose2& estimate) {
  switch (command.kind) {
    case ExplorerCommand::Kind::kDrive:
      if (command.new_path) follower.setPath(*command.path);
      return follower.compute(estimate);
    case ExplorerCommand::Kind::kBackOff:
      follower.clear();
      return backOffCommand();
    default:
      follower.clear();
      return VelocityCommand{};
  }
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

ExplorerOptions explorerOptionsFor(EpisodeConfig config, double reachable_area_m2) {
  config.resolve();
  ExplorerOptions options = config.explorer;
  options.costmap.robot_radius_m = config.robot.radius_m;
  options.goals.sensor_range_m = config.laser.range_max_m;
  options.goals.arrival_tolerance_m = config.follower.goal_tolerance_m;
  options.goals.progress_lookahead_m = config.follower.lookahead_m;
  options.goals.stall_min_new_area_m2 = config.episode.stall_floor_fraction * reachable_area_m2;
  return options;
}

ExplorerOptions explorerOptionsFor(const WorldModel& world, const EpisodeConfig& config) {
  const double lethal_radius_m = explorerOptionsFor(config, 0.0).costmap.lethalRadius_m();
  const ExplorationTruth truth(world, mapGeometryFor(world, config.mapping.resolution_m),
                               lethal_radius_m);
  return explorerOptionsFor(config, truth.reachableArea_m2());
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
  Simulation sim(world, std::move(config), seed);
  PathFollower follower(sim.config().follower);
  auto snapshot = [&](bool scanned) {
    return EpisodeSnapshot{sim.time_s(), sim.robotPose(), sim.grid(),
                           world,        scanned,         sim.estimate()};
  };
  std::optional<double> t_done_s, l_done_m;
  while (true) {
    const Sensed sensed = sim.sense();
    if (sensed.sampled && progress) progress(sim.time_s(), sim.maxTime_s(), sim.rate());
    for (EpisodeObserver* o : observers) o->onStep(snapshot(sensed.scan.has_value()));

    const PublishedMap map = sim.publishMap();
    const ExplorerCommand command =
        explorer.update(ExplorerInput{map.grid, sim.estimate(), sim.time_s(), map.changed});
    if (command.kind == ExplorerCommand::Kind::kDone) {
      t_done_s = sim.time_s();
      l_done_m = sim.odometer_m();
      break;
    }
    if (sim.act(driverCommand(command, follower, sim.estimate())))
      explorer.report(GoalOutcome::kBlocked, sim.time_s());
    if (!sim.step()) break;
  }

  sim.finish();
  explorer.finish(sim.publishedGrid());
  std::map<std::string, TimingStats> map_updates;
  for (const AnalysisMap* m : {explorer.roomMap(), explorer.skeletonMap()}) {
    if (m != nullptr) {
      map_updates[std::string(m->name())] =
          TimingStats::ofGrowth(m->updateTimes_ms(), m->updateKnownArea_m2());
    }
  }
  for (EpisodeObserver* o : observers) {
    o->onFinish(snapshot(true));
    map_updates[std::string(o->name())] = TimingStats::of(o->updateTimes_ms());
  }
  EpisodeResult result = sim.takeResult();
  result.map_updates = std::move(map_updates);
  result.t_done_s = t_done_s;
  result.l_done_m = l_done_m;
  const ExplorerStats& stats = explorer.stats();
  result.goals = stats.goals;
  result.goal_failures = stats.goal_failures;
  result.recoveries = stats.recoveries;
  result.stalls = stats.stalls;
  result.costmap_update = TimingStats::of(stats.costmap_ms);
  result.decision = TimingStats::of(stats.decision_ms);
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return result;
}

}  // namespace roomscout::sim
