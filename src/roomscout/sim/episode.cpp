#include "roomscout/sim/episode.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "roomscout/core/errors.hpp"
#include "roomscout/mapping/occupancy_mapper.hpp"
#include "roomscout/sim/exploration_truth.hpp"

namespace roomscout::sim {

void EpisodeOptions::validate() const {
  if (!(dt_s > 0.0 && dt_s <= 0.5)) throw OptionError("episode.dt_s must be in (0, 0.5]");
  if (!(max_time_s >= 0.0)) throw OptionError("episode.max_time_s must be >= 0 (0 = automatic)");
  if (!(metrics_period_s > 0.0)) throw OptionError("episode.metrics_period_s must be > 0");
  if (!(completion_rate > 0.0 && completion_rate <= 1.0)) {
    throw OptionError("episode.completion_rate must be in (0, 1]");
  }
  if (!(stuck_timeout_s > 0.0) || !(no_progress_timeout_s > 0.0) || !(recovery_time_s >= 0.0)) {
    throw OptionError("episode: timeouts must be > 0");
  }
  if (!(stall_timeout_s > 0.0) || !(stall_radius_m >= 0.0)) {
    throw OptionError("episode: stall_timeout_s must be > 0 and stall_radius_m >= 0");
  }
  if (!(room_dwell_s >= 0.0)) throw OptionError("episode.room_dwell_s must be >= 0");
  if (max_decisions_per_step < 1) throw OptionError("episode.max_decisions_per_step must be >= 1");
}

std::vector<ParameterRef> EpisodeOptions::parameters() {
  return {
      {"dt_s", &dt_s, "simulation step [s]"},
      {"max_time_s", &max_time_s, "simulated time limit [s], 0 = automatic"},
      {"metrics_period_s", &metrics_period_s, "exploration rate sampling period [s]"},
      {"completion_rate", &completion_rate, "rate that counts as fully explored"},
      {"stuck_timeout_s", &stuck_timeout_s, "blocked this long triggers a recovery [s]"},
      {"no_progress_timeout_s", &no_progress_timeout_s, "no progress this long fails the goal [s]"},
      {"recovery_time_s", &recovery_time_s, "duration of a back-off recovery [s]"},
      {"stall_timeout_s", &stall_timeout_s, "no new map and little motion this long fails the goal [s]"},
      {"stall_radius_m", &stall_radius_m, "motion radius under which the robot counts as stalled [m]"},
      {"room_dwell_s", &room_dwell_s, "time in a room before it counts as entered [s]"},
      {"max_decisions_per_step", &max_decisions_per_step, "failed goals tried in a row before waiting"},
  };
}

void EpisodeConfig::resolve() {
  world.robot_radius_m = robot.radius_m;
  costmap.robot_radius_m = robot.radius_m;
  follower.max_linear_speed_mps = robot.max_linear_speed_mps;
  follower.max_angular_speed_radps = robot.max_angular_speed_radps;
}

void EpisodeConfig::validate() const {
  world.validate();
  robot.validate();
  laser.validate();
  mapping.validate();
  costmap.validate();
  planner.validate();
  follower.validate();
  episode.validate();
}

std::vector<ParameterGroup> EpisodeConfig::groups() {
  // Fields mirrored from the robot group are not editable on their own.
  auto without = [](std::vector<ParameterRef> params, std::initializer_list<std::string_view> names) {
    std::erase_if(params, [&](const ParameterRef& p) {
      return std::find(names.begin(), names.end(), p.name) != names.end();
    });
    return params;
  };
  return {
      {"robot", robot.parameters()},
      {"world", without(world.parameters(), {"robot_radius_m"})},
      {"laser", laser.parameters()},
      {"mapping", mapping.parameters()},
      {"costmap", without(costmap.parameters(), {"robot_radius_m"})},
      {"planner", planner.parameters()},
      {"follower", without(follower.parameters(), {"max_linear_speed_mps", "max_angular_speed_radps"})},
      {"episode", episode.parameters()},
  };
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

/// Cell offsets of a disc, for checking a path against newly mapped obstacles.
std::vector<Cell> discOffsets(double radius_cells) {
  std::vector<Cell> offsets;
  const int r = static_cast<int>(std::ceil(radius_cells));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy < radius_cells * radius_cells) offsets.push_back({dx, dy});
    }
  }
  return offsets;
}

/// True when an occupied cell lies within the lethal disc of a waypoint from `from` on, among
/// the waypoints within `horizon_m` of `near_m` (only there can a new scan have changed it).
bool pathBlocked(const OccupancyGrid& grid, const Path& path, std::size_t from, const std::vector<Cell>& disc,
                 const Vec2& near_m, double horizon_m) {
  const GridGeometry& g = grid.geometry();
  for (std::size_t i = from; i < path.waypoints_m.size(); ++i) {
    const Vec2& p = path.waypoints_m[i];
    if ((p - near_m).squaredNorm() > horizon_m * horizon_m) continue;
    const Cell c = g.cellOf(p);
    for (const Cell& o : disc) {
      const Cell q{c.x + o.x, c.y + o.y};
      if (g.contains(q) && grid.isOccupied(g.index(q))) return true;
    }
  }
  return false;
}

double remainingLength(const Path& path, std::size_t from, const Vec2& robot) {
  if (path.waypoints_m.empty()) return 0.0;
  from = std::min(from, path.waypoints_m.size() - 1);
  double length = (path.waypoints_m[from] - robot).norm();
  for (std::size_t i = from + 1; i < path.waypoints_m.size(); ++i) {
    length += (path.waypoints_m[i] - path.waypoints_m[i - 1]).norm();
  }
  return length;
}

}  // namespace

EpisodeResult runEpisode(const WorldModel& world, EpisodeConfig config, ExplorationStrategy& strategy,
                         std::uint64_t seed, const EpisodeProgress& progress,
                         const std::vector<EpisodeObserver*>& observers) {
  const auto wall_start = Clock::now();
  config.resolve();
  config.validate();
  strategy.validateOptions();
  const EpisodeOptions& opt = config.episode;

  const GridGeometry map_geometry = mapGeometryFor(world, config.mapping.resolution_m);
  // Reachable = what the robot's navigation footprint (radius plus the planner's safety
  // margin) can cover: gaps the planner may never pass do not count as explorable.
  const ExplorationTruth truth(world, map_geometry, config.costmap.lethalRadius_m());
  ExplorationRateCounter rate_counter(truth);
  CellRect changed_since_sample;
  OccupancyGrid grid(map_geometry, config.mapping);
  OccupancyMapper mapper(grid);
  LaserSimulator laser(world, config.laser, seed ^ 0x9E3779B97F4A7C15ull);
  Robot robot(world, config.robot, world.start());
  Costmap costmap(config.costmap);
  AStarPlanner planner(config.planner);
  PathFollower follower(config.follower);

  EpisodeResult result;
  result.reachable_area_m2 = truth.reachableArea_m2();
  const double max_time_s = opt.max_time_s > 0.0 ? opt.max_time_s : 600.0 + 5.0 * result.reachable_area_m2;
  result.max_time_s = max_time_s;

  const std::vector<Cell> lethal_disc = discOffsets(config.costmap.lethalRadius_m() / map_geometry.resolution_m());
  const double scan_period_s = 1.0 / config.laser.rate_hz;
  const double horizon_m = config.laser.range_max_m + config.costmap.lethalRadius_m() + 0.5;

  std::vector<double> occupancy_ms, costmap_ms, decision_ms;
  const SemanticMap* semantic = nullptr;
  for (const EpisodeObserver* o : observers) {
    if (!semantic && strategy.readsRooms()) semantic = o->semanticMap();
  }
  double t = 0.0;
  double next_scan_s = 0.0, next_metrics_s = 0.0, next_decision_s = 0.0;
  bool map_changed_since_costmap = true;
  CellRect changed_since_costmap = grid.geometry().bounds();
  bool need_decision = true;
  bool finished = false;
  std::optional<Vec2> goal;
  double last_decision_s = -std::numeric_limits<double>::infinity();
  double blocked_for_s = 0.0;
  double recovery_until_s = -1.0;
  double best_remaining_m = std::numeric_limits<double>::infinity();
  double last_progress_s = 0.0;
  double rate = 0.0;
  int current_room = world.roomAt(robot.pose().position());
  int candidate_room = current_room;
  double candidate_since_s = 0.0;
  std::unordered_set<int> visited_rooms;
  // Stall watchdog window: rate and position at its start, farthest excursion since.
  double stall_window_start_s = 0.0;
  double stall_window_rate = 0.0;
  Vec2 stall_window_position = robot.pose().position();
  double stall_window_excursion_m = 0.0;
  if (current_room != 0) visited_rooms.insert(current_room);

  auto failGoal = [&]() {
    if (goal) strategy.onGoalFailed(*goal);
    ++result.goal_failures;
    goal.reset();
    follower.clear();
    need_decision = true;
  };
  auto planTo = [&](const Vec2& target) {
    PlanResult plan = planner.plan(costmap, robot.pose().position(), target);
    if (plan.status != PlanStatus::kFound) return false;
    follower.setPath(plan.path);
    best_remaining_m = std::numeric_limits<double>::infinity();
    last_progress_s = t;
    return true;
  };
  auto refreshCostmap = [&]() {
    if (!map_changed_since_costmap) return;
    const auto start = Clock::now();
    costmap.update(grid, changed_since_costmap);
    costmap_ms.push_back(msSince(start));
    map_changed_since_costmap = false;
    changed_since_costmap = CellRect{};
  };
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
    if (t >= next_scan_s - 1e-9) {
      const LaserScan scan = laser.scan(robot.pose());
      const auto start = Clock::now();
      const CellRect changed = mapper.integrate(scan, robot.pose());
      changed_since_sample.unite(changed);
      changed_since_costmap.unite(changed);
      occupancy_ms.push_back(msSince(start));
      next_scan_s += scan_period_s;
      map_changed_since_costmap = true;
      scanned = true;
      result.trajectory.push_back({t, robot.pose()});
    }
    if (t >= next_metrics_s - 1e-9) {
      sampleMetrics();
      next_metrics_s += opt.metrics_period_s;
      if (progress) progress(t, max_time_s, rate);
      // A strategy that flips between goals without seeing anything new, while the robot
      // dithers in one place, is stalled: its current goal fails (explore_lite's own
      // watchdog only catches a goal that stays the same).
      stall_window_excursion_m =
          std::max(stall_window_excursion_m, (robot.pose().position() - stall_window_position).norm());
      if (t - stall_window_start_s >= opt.stall_timeout_s) {
        if (goal && rate - stall_window_rate < 0.001 && stall_window_excursion_m < opt.stall_radius_m) {
          ++result.stalls;
          failGoal();
        }
        stall_window_start_s = t;
        stall_window_rate = rate;
        stall_window_position = robot.pose().position();
        stall_window_excursion_m = 0.0;
      }
    }

    for (EpisodeObserver* o : observers) o->onStep(EpisodeSnapshot{t, robot.pose(), grid, world, scanned});

    // 2. A path through newly seen obstacles is replanned; failing that, the goal fails.
    if (scanned && goal && follower.hasPath() &&
        pathBlocked(grid, follower.path(), follower.progressIndex(), lethal_disc, robot.pose().position(),
                    horizon_m)) {
      refreshCostmap();
      if (!planTo(*goal)) failGoal();
    }

    // 3. Decide.
    const bool periodic = goal && strategy.replanPeriod_s() > 0.0 && t - last_decision_s >= strategy.replanPeriod_s();
    if (t >= recovery_until_s && t >= next_decision_s && (need_decision || periodic)) {
      refreshCostmap();
      bool have_goal = false;
      for (int attempt = 0; attempt < opt.max_decisions_per_step && !finished && !have_goal; ++attempt) {
        const ExplorationInput input{grid, costmap, robot.pose(), t, semantic};
        const auto start = Clock::now();
        const Decision d = strategy.decide(input);
        decision_ms.push_back(msSince(start));
        if (d.status == Decision::Status::kDone) {
          finished = true;
        } else if (goal && (d.goal_m - *goal).norm() < 1e-6 && follower.hasPath()) {
          have_goal = true;  // same goal: keep driving the current path
        } else if (planTo(d.goal_m)) {
          goal = d.goal_m;
          ++result.goals;
          have_goal = true;
        } else {
          goal = d.goal_m;
          failGoal();
        }
      }
      last_decision_s = t;
      need_decision = !have_goal && !finished;
      if (need_decision) next_decision_s = t + 1.0;  // every candidate failed: wait for new data
    }
    if (finished) {
      result.t_done_s = t;
      result.l_done_m = robot.odometer_m();
      break;
    }

    // 4. Act.
    VelocityCommand command;
    if (t < recovery_until_s) {
      command.linear_mps = -0.1;  // back off from whatever we are pressed against
    } else if (follower.hasPath()) {
      if (follower.reached(robot.pose())) {
        if (goal) strategy.onGoalReached(*goal);
        goal.reset();
        follower.clear();
        need_decision = true;
      } else {
        command = follower.compute(robot.pose());
        const double remaining = remainingLength(follower.path(), follower.progressIndex(), robot.pose().position());
        if (remaining < best_remaining_m - 0.05) {
          best_remaining_m = remaining;
          last_progress_s = t;
        } else if (t - last_progress_s > opt.no_progress_timeout_s) {
          failGoal();
        }
      }
    }
    const bool moved = robot.step(command, opt.dt_s);
    if (command.linear_mps > 0.0 && !moved) {
      blocked_for_s += opt.dt_s;
      if (blocked_for_s >= opt.stuck_timeout_s) {
        ++result.recoveries;
        blocked_for_s = 0.0;
        recovery_until_s = t + opt.recovery_time_s;
        failGoal();
      }
    } else {
      blocked_for_s = 0.0;
    }

    // 5. Rooms entered (a room counts after room_dwell_s inside it).
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

  sampleMetrics();
  for (EpisodeObserver* o : observers) {
    o->onFinish(EpisodeSnapshot{t, robot.pose(), grid, world, true});
    result.map_updates[std::string(o->name())] = TimingStats::of(o->updateTimes_ms());
  }
  result.exploration_rate = rate;
  result.sim_time_s = t;
  result.length_m = robot.odometer_m();
  result.rooms_entered = static_cast<int>(visited_rooms.size());
  result.room_truth = world.hasRooms();
  result.occupancy_update = TimingStats::of(std::move(occupancy_ms));
  result.costmap_update = TimingStats::of(std::move(costmap_ms));
  result.decision = TimingStats::of(std::move(decision_ms));
  result.map = std::move(grid);
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - wall_start).count();
  return result;
}

}  // namespace roomscout::sim
