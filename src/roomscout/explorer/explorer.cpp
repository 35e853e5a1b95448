#include "roomscout/explorer/explorer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "roomscout/core/errors.hpp"
#include "roomscout/planning/path_blocking.hpp"

namespace roomscout {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// The stall watchdog and the retry after a round of failed goals run on this period [s].
constexpr double kWatchdogPeriod_s = 1.0;
constexpr double kRetryDelay_s = 1.0;
/// The path to the goal must shrink by this much to count as progress [m].
constexpr double kMinProgress_m = 0.05;

bool finiteNonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

std::size_t freeCells(const OccupancyGrid& grid) {
  const std::uint8_t* s = grid.stateBytes();
  return static_cast<std::size_t>(
      std::count(s, s + grid.geometry().cellCount(), static_cast<std::uint8_t>(CellState::kFree)));
}

}  // namespace

void GoalWatchdogOptions::validate() const {
  if (!(std::isfinite(sensor_range_m) && sensor_range_m > 0.0)) {
    throw OptionError("explorer.sensor_range_m must be a finite number > 0");
  }
  if (!(std::isfinite(arrival_tolerance_m) && arrival_tolerance_m > 0.0)) {
    throw OptionError("explorer.arrival_tolerance_m must be a finite number > 0");
  }
  if (!(std::isfinite(progress_lookahead_m) && progress_lookahead_m > 0.0)) {
    throw OptionError("explorer.progress_lookahead_m must be a finite number > 0");
  }
  if (!(std::isfinite(no_progress_timeout_s) && no_progress_timeout_s > 0.0) ||
      !finiteNonNegative(recovery_time_s)) {
    throw OptionError("explorer: no_progress_timeout_s must be > 0 and recovery_time_s >= 0");
  }
  if (!(std::isfinite(stall_timeout_s) && stall_timeout_s > 0.0) ||
      !finiteNonNegative(stall_radius_m)) {
    throw OptionError("explorer: stall_timeout_s must be > 0 and stall_radius_m >= 0");
  }
  if (!finiteNonNegative(stall_min_new_area_m2)) {
    throw OptionError("explorer.stall_min_new_area_m2 must be a finite number >= 0");
  }
  if (max_decisions_per_step < 1) throw OptionError("explorer.max_decisions_per_step must be >= 1");
}

std::vector<ParameterRef> GoalWatchdogOptions::parameters() {
  return {
      {"sensor_range_m", &sensor_range_m,
       "range of the robot's laser scanner: a new scan can only block the path this close to "
       "the robot [m]"},
      {"arrival_tolerance_m", &arrival_tolerance_m,
       "distance to the path's end at which the goal counts as reached (the driver's goal "
       "tolerance) [m]"},
      {"progress_lookahead_m", &progress_lookahead_m,
       "progress along the path is sought within two of these past the robot's last progress "
       "(the driver's look-ahead) [m]"},
      {"no_progress_timeout_s", &no_progress_timeout_s,
       "the path to the goal not shrinking by 5 cm this long fails the goal [s]"},
      {"recovery_time_s", &recovery_time_s, "how long the robot backs off when blocked [s]"},
      {"stall_timeout_s", &stall_timeout_s,
       "window of the stall watchdog: no new map and little motion this long fails the goal [s]"},
      {"stall_radius_m", &stall_radius_m,
       "a robot that stayed within this radius of where a stall window began counts as stalled "
       "[m]"},
      {"stall_min_new_area_m2", &stall_min_new_area_m2,
       "growth of the known free area in a stall window under which the robot counts as stalled "
       "[m^2]; 0 = never"},
      {"max_decisions_per_step", &max_decisions_per_step,
       "failed goals tried in a row before waiting a second for new data"},
  };
}

void ExplorerOptions::validate() const {
  costmap.validate();
  planner.validate();
  goals.validate();
  maps.validate();
}

std::vector<ParameterGroup> ExplorerOptions::groups() {
  return {
      {"costmap", costmap.parameters()},
      {"planner", planner.parameters()},
      {"explorer", goals.parameters()},
      {"maps", maps.parameters()},
      {"segmentation", maps.segmentation.parameters()},
      {"topology", maps.topology.parameters()},
  };
}

std::vector<RenamedOption> ExplorerOptions::renamedOptions() {
  std::vector<RenamedOption> renamed;
  for (const char* name : {"no_progress_timeout_s", "recovery_time_s", "stall_timeout_s",
                           "stall_radius_m", "stall_min_new_area_m2", "max_decisions_per_step"}) {
    renamed.push_back({std::string("episode.") + name, std::string("explorer.") + name, ""});
  }
  return renamed;
}

Explorer::Explorer(std::unique_ptr<ExplorationStrategy> strategy, const ExplorerOptions& options)
    : Explorer(*strategy, options) {
  owned_ = std::move(strategy);
}

Explorer::Explorer(ExplorationStrategy& strategy, const ExplorerOptions& options)
    : strategy_(&strategy),
      options_(options),
      costmap_((options_.validate(), options_.costmap)),
      planner_(options_.planner),
      progress_(2.0 * options_.goals.progress_lookahead_m),
      driver_progress_(2.0 * options_.goals.progress_lookahead_m) {
  strategy_->validateOptions();
  const bool reads_rooms = strategy_->readsRooms();
  if (options_.background_maps && options_.all_maps) worker_ = std::make_unique<MapWorker>(true);
  // The rooms a strategy reads are built on the caller's thread, before each decision.
  if (reads_rooms || options_.all_maps) {
    rooms_ = std::make_unique<AnalysisMap>(AnalysisMapKind::kSemantic, options_.maps, nullptr,
                                           reads_rooms ? nullptr : worker_.get());
  }
  if (options_.all_maps) {
    skeleton_ = std::make_unique<AnalysisMap>(AnalysisMapKind::kTopological, options_.maps,
                                              rooms_.get(), worker_.get());
  }
}

Explorer::~Explorer() = default;

double Explorer::relative(double time_s, const char* what) const {
  if (!std::isfinite(time_s)) {
    throw InvalidArgument(std::string("explorer: ") + what + " time is not finite (" +
                          std::to_string(time_s) + ")");
  }
  const double t = clock_start_s_ ? time_s - *clock_start_s_ : 0.0;
  if (clock_start_s_ && t < last_time_s_) {
    throw InvalidArgument(std::string("explorer: ") + what +
                          " time went backwards: " + std::to_string(time_s) + " s after " +
                          std::to_string(*clock_start_s_ + last_time_s_) + " s");
  }
  return t;
}

void Explorer::failGoal(bool stalled) {
  if (goal_) stalled ? strategy_->onGoalStalled(*goal_) : strategy_->onGoalFailed(*goal_);
  ++stats_.goal_failures;
  goal_.reset();
  progress_.reset(Path{});
  need_decision_ = true;
}

void Explorer::reachGoal() {
  if (goal_) strategy_->onGoalReached(*goal_);
  goal_.reset();
  progress_.reset(Path{});
  need_decision_ = true;
}

void Explorer::applyPendingFailure() {
  if (!pending_failure_) return;
  pending_failure_ = false;
  failGoal();
}

bool Explorer::planTo(const Vec2& robot, const Vec2& target, double t) {
  PlanResult plan = planner_.plan(costmap_, robot, target);
  if (plan.status != PlanStatus::kFound) return false;
  progress_.reset(plan.path);
  ++path_version_;
  best_remaining_m_ = std::numeric_limits<double>::infinity();
  last_progress_s_ = t;
  return true;
}

void Explorer::refreshCostmap(const OccupancyGrid& grid) {
  if (!map_changed_since_costmap_) return;
  const auto start = Clock::now();
  costmap_.update(grid, changed_since_costmap_);
  stats_.costmap_ms.push_back(msSince(start));
  map_changed_since_costmap_ = false;
  changed_since_costmap_ = CellRect{};
}

void Explorer::stallWatchdog(const OccupancyGrid& grid, const Vec2& robot, double t) {
  // A strategy that flips between goals without seeing anything new, while the robot dithers
  // in one place, is stalled: its current goal fails (explore_lite's own watchdog only
  // catches a goal that stays the same).
  // An area threshold of 0 turns the watchdog off: a map that loses free cells under noise
  // would otherwise count as growing by less than 0.
  if (options_.goals.stall_min_new_area_m2 <= 0.0) return;
  if (t < next_watchdog_s_ - 1e-9) return;
  next_watchdog_s_ += kWatchdogPeriod_s;
  const double cell_m2 = grid.geometry().resolution_m() * grid.geometry().resolution_m();
  auto knownFree_m2 = [&] { return static_cast<double>(freeCells(grid)) * cell_m2; };
  if (!stall_window_started_) {
    stall_window_started_ = true;
    stall_window_start_s_ = t;
    stall_window_free_m2_ = knownFree_m2();
    stall_window_position_ = robot;
  }
  stall_window_excursion_m_ =
      std::max(stall_window_excursion_m_, (robot - stall_window_position_).norm());
  if (t - stall_window_start_s_ < options_.goals.stall_timeout_s) return;
  const double free_now_m2 = knownFree_m2();
  if (goal_ && free_now_m2 - stall_window_free_m2_ < options_.goals.stall_min_new_area_m2 &&
      stall_window_excursion_m_ < options_.goals.stall_radius_m) {
    ++stats_.stalls;
    failGoal(/*stalled=*/true);
  }
  stall_window_start_s_ = t;
  stall_window_free_m2_ = free_now_m2;
  stall_window_position_ = robot;
  stall_window_excursion_m_ = 0.0;
}

bool Explorer::pathBlocked(const OccupancyGrid& grid, const Vec2& robot) const {
  // Beyond the laser's range a new scan cannot have blocked the path.
  const double horizon_m =
      blockingHorizon_m(options_.goals.sensor_range_m, options_.costmap.lethalRadius_m());
  return pathBlockedAhead(grid, progress_.path().waypoints_m, progress_.index(), robot, horizon_m,
                          lethal_disc_);
}

ExplorerCommand Explorer::update(const ExplorerInput& input) {
  const OccupancyGrid& grid = input.grid;
  const GridGeometry& g = grid.geometry();
  if (g.width() <= 0 || g.height() <= 0) {
    throw InvalidArgument("explorer: the occupancy grid is empty (" + std::to_string(g.width()) +
                          " x " + std::to_string(g.height()) + " cells)");
  }
  if (!std::isfinite(input.robot.x_m) || !std::isfinite(input.robot.y_m) ||
      !std::isfinite(input.robot.yaw_rad)) {
    throw InvalidArgument("explorer: robot pose is not finite (" + std::to_string(input.robot.x_m) +
                          ", " + std::to_string(input.robot.y_m) + ", " +
                          std::to_string(input.robot.yaw_rad) + ")");
  }
  const double t = relative(input.time_s, "update");
  if (!clock_start_s_) clock_start_s_ = input.time_s;
  last_time_s_ = t;

  ExplorerCommand command;
  if (done_) {
    command.kind = ExplorerCommand::Kind::kDone;
    command.reason = "exploration done";
    return command;
  }
  applyPendingFailure();

  // What changed since the last cycle: a new geometry changes everything.
  const bool geometry_changed = !last_geometry_ || *last_geometry_ != g;
  last_geometry_ = g;
  const CellRect changed = geometry_changed || !input.changed ? g.bounds() : *input.changed;
  const bool grid_changed = !changed.empty();
  if (grid_changed) {
    changed_since_costmap_.unite(changed);
    map_changed_since_costmap_ = true;
  }
  if (lethal_disc_resolution_m_ != g.resolution_m()) {
    lethal_disc_ = discOffsets(options_.costmap.lethalRadius_m() / g.resolution_m());
    lethal_disc_resolution_m_ = g.resolution_m();
  }
  const Vec2 robot = input.robot.position();

  stallWatchdog(grid, robot, t);
  if (rooms_) rooms_->observe(grid, t, grid_changed);
  if (skeleton_) skeleton_->observe(grid, t, grid_changed);

  if (!g.contains(robot)) {
    command.reason = "robot outside the map";
    return command;
  }

  // A path through newly seen obstacles is replanned; failing that, the goal fails.
  if (grid_changed && goal_ && !progress_.empty() && pathBlocked(grid, robot)) {
    refreshCostmap(grid);
    if (!planTo(robot, *goal_, t)) failGoal();
  }

  // Decide.
  const double period = strategy_->replanPeriod_s();
  const bool periodic = goal_ && period > 0.0 && t - last_decision_s_ >= period;
  if (t >= recovery_until_s_ && t >= next_decision_s_ && (need_decision_ || periodic)) {
    refreshCostmap(grid);
    const SemanticMap* semantic =
        strategy_->readsRooms() && rooms_ ? rooms_->semanticMap() : nullptr;
    bool have_goal = false;
    for (int attempt = 0; attempt < options_.goals.max_decisions_per_step && !done_ && !have_goal;
         ++attempt) {
      const ExplorationInput in{grid, costmap_, input.robot, t, semantic};
      const auto start = Clock::now();
      const Decision d = strategy_->decide(in);
      stats_.decision_ms.push_back(msSince(start));
      if (d.status == Decision::Status::kDone) {
        done_ = true;
      } else if (goal_ && (d.goal_m - *goal_).norm() < 1e-6 && !progress_.empty()) {
        have_goal = true;  // same goal: keep driving the current path
      } else if (planTo(robot, d.goal_m, t)) {
        goal_ = d.goal_m;
        ++stats_.goals;
        have_goal = true;
      } else {
        goal_ = d.goal_m;
        failGoal();
      }
    }
    last_decision_s_ = t;
    need_decision_ = !have_goal && !done_;
    if (need_decision_)
      next_decision_s_ = t + kRetryDelay_s;  // every candidate failed: wait for new data
  }
  if (done_) {
    command.kind = ExplorerCommand::Kind::kDone;
    command.reason = "exploration done";
    return command;
  }

  if (t < recovery_until_s_) {
    command.kind = ExplorerCommand::Kind::kBackOff;
    command.reason = "backing off";
    return command;
  }
  if (progress_.empty()) {
    command.reason = need_decision_ ? "no reachable goal yet" : "no goal";
    return command;
  }
  if (arrived(progress_.path(), robot, options_.goals.arrival_tolerance_m)) {
    reachGoal();
    command.reason = "goal reached";
    return command;
  }
  // The no-progress watchdog: measured now, acted on at the next call, after the driver had
  // this cycle's command.
  progress_.update(robot);
  double remaining = progress_.remaining_m(robot);
  if (input.driver_path != nullptr && !input.driver_path->waypoints_m.empty()) {
    if (driver_progress_.path().waypoints_m != input.driver_path->waypoints_m)
      driver_progress_.reset(*input.driver_path);
    driver_progress_.update(robot);
    remaining = driver_progress_.remaining_m(robot);
  }
  if (remaining < best_remaining_m_ - kMinProgress_m) {
    best_remaining_m_ = remaining;
    last_progress_s_ = t;
  } else if (t - last_progress_s_ > options_.goals.no_progress_timeout_s) {
    pending_failure_ = true;
  }
  command.kind = ExplorerCommand::Kind::kDrive;
  command.goal_m = *goal_;
  command.new_path = path_version_ != sent_path_version_;
  command.path = &progress_.path();
  command.reason = "driving to goal";
  sent_path_version_ = path_version_;
  return command;
}

void Explorer::report(GoalOutcome outcome, double time_s) {
  const double t = relative(time_s, "report");
  applyPendingFailure();
  switch (outcome) {
    case GoalOutcome::kReached:
      reachGoal();
      break;
    case GoalOutcome::kFailed:
      failGoal();
      break;
    case GoalOutcome::kBlocked:
      ++stats_.recoveries;
      recovery_until_s_ = t + options_.goals.recovery_time_s;
      failGoal();
      break;
  }
}

void Explorer::finish(const OccupancyGrid& grid) {
  if (rooms_) rooms_->finish(grid);
  if (skeleton_) skeleton_->finish(grid);
}

}  // namespace roomscout
