#include "roomscout/exploration/detail/rrt_exploration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

void RrtExplorationOptions::validate() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(global_eta_m) || !positive(local_eta_m))
    throw OptionError("rrt: global_eta_m and local_eta_m must be > 0");
  if (!positive(samples_per_s)) throw OptionError("rrt.samples_per_s must be > 0");
  if (!positive(bandwidth_m)) throw OptionError("rrt.bandwidth_m must be > 0");
  if (!positive(info_radius_m)) throw OptionError("rrt.info_radius_m must be > 0");
  if (!(min_info_gain_m2 >= 0.0)) throw OptionError("rrt.min_info_gain_m2 must be >= 0");
  if (!(info_multiplier >= 0.0) || !(hysteresis_radius_m >= 0.0) || !(hysteresis_gain >= 0.0)) {
    throw OptionError("rrt: info_multiplier, hysteresis_radius_m and hysteresis_gain must be >= 0");
  }
  if (!(assign_period_s >= 0.0)) throw OptionError("rrt.assign_period_s must be >= 0");
  if (!(blacklist_radius_m >= 0.0)) throw OptionError("rrt.blacklist_radius_m must be >= 0");
  if (!positive(end_check_period_s)) throw OptionError("rrt.end_check_period_s must be > 0");
  if (end_checks < 1 || end_min_frontier_cells < 1)
    throw OptionError("rrt: end_checks and end_min_frontier_cells must be >= 1");
  if (!(observed_radius_m >= 0.0)) throw OptionError("rrt.observed_radius_m must be >= 0");
  if (max_samples_per_call < 1) throw OptionError("rrt.max_samples_per_call must be >= 1");
  if (!positive(idle_end_s)) throw OptionError("rrt.idle_end_s must be > 0");
  end_pockets.validate("rrt");
}

std::vector<ParameterRef> RrtExplorationOptions::parameters() {
  std::vector<ParameterRef> parameters = {
      {"global_eta_m", &global_eta_m, "global tree steering step [m]"},
      {"local_eta_m", &local_eta_m, "local tree steering step [m]"},
      {"samples_per_s", &samples_per_s, "samples per simulated second, per tree"},
      {"bandwidth_m", &bandwidth_m, "mean-shift bandwidth of the frontier filter [m]"},
      {"info_radius_m", &info_radius_m, "information gain disc radius [m]"},
      {"min_info_gain_m2", &min_info_gain_m2,
       "filter: centroids with less unknown area in a disc of radius info_radius_m / 2 are dropped "
       "[m^2]"},
      {"info_multiplier", &info_multiplier, "weight of the information gain in the revenue"},
      {"hysteresis_radius_m", &hysteresis_radius_m,
       "information gain bonus radius around the robot [m]"},
      {"hysteresis_gain", &hysteresis_gain, "information gain factor within the hysteresis radius"},
      {"assign_period_s", &assign_period_s,
       "re-assignment period (the original's delay_after_assignment) [s]"},
      {"blacklist_radius_m", &blacklist_radius_m,
       "centroids this close to a failed goal are skipped [m]"},
      {"end_check_period_s", &end_check_period_s, "period of the end test [s]"},
      {"end_checks", &end_checks, "consecutive failing end tests that end exploration"},
      {"end_min_frontier_cells", &end_min_frontier_cells,
       "fewer reachable frontier cells fail the end test"},
      {"observed_radius_m", &observed_radius_m,
       "end test: frontier cells still unknown this close to the robot are ignored [m]"},
      {"max_samples_per_call", &max_samples_per_call,
       "cap on the owed samples grown in one call, per tree"},
      {"idle_end_s", &idle_end_s,
       "exploration ends after this long with no assignable centroid [s]"},
  };
  for (const ParameterRef& p : end_pockets.parameters()) parameters.push_back(p);
  return parameters;
}

namespace {

/// rrt_exploration's informationGain: unknown area [m^2] of the cells whose centres lie within
/// `radius_m` of `p`.
double unknownAreaInDisc(const OccupancyGrid& grid, const Vec2& p, double radius_m) {
  const GridGeometry& g = grid.geometry();
  const double res = g.resolution_m();
  const Cell c = g.cellOf(p);
  const int r = static_cast<int>(std::ceil(radius_m / res));
  const double r2 = radius_m * radius_m;
  constexpr auto kUnknownByte = static_cast<std::uint8_t>(CellState::kUnknown);
  int count = 0;
  for (int y = std::max(0, c.y - r); y <= std::min(g.height() - 1, c.y + r); ++y) {
    const double dy = g.origin_m().y() + (y + 0.5) * res - p.y();
    if (dy * dy > r2) continue;
    // The row's cells whose centres lie in the disc, give or take one cell at each end, where
    // the exact test decides.
    const double half = std::sqrt(r2 - dy * dy);
    const int x0 =
        std::max(0, static_cast<int>(std::floor((p.x() - half - g.origin_m().x()) / res - 0.5)));
    const int x1 = std::min(
        g.width() - 1, static_cast<int>(std::ceil((p.x() + half - g.origin_m().x()) / res - 0.5)));
    const std::size_t row = static_cast<std::size_t>(y) * g.width();
    // Interior cells lie in the disc: a branch-free count of unknown state bytes. The two
    // cells at each end (fewer in a short row) take the exact test.
    const std::uint8_t* states = grid.stateBytes() + row;
    const auto edgeCell = [&](int x) {
      return states[x] == kUnknownByte && (g.centerOf(Cell{x, y}) - p).squaredNorm() <= r2;
    };
    for (int x = x0 + 2; x <= x1 - 2; ++x) count += states[x] == kUnknownByte;
    for (int x = x0; x <= x1 && x <= x0 + 1; ++x) count += edgeCell(x);
    for (int x = std::max(x1 - 1, x0 + 2); x <= x1; ++x) count += edgeCell(x);
  }
  return count * res * res;
}

/// Mean-shift with a flat kernel, as sklearn's MeanShift(bandwidth) without bin seeding: every
/// point seeds a climb to the local mean; converged modes are ordered by how many points lie
/// within the bandwidth and near-duplicates (closer than the bandwidth) are removed.
std::vector<Vec2> meanShift(const std::vector<Vec2>& points, double bandwidth_m) {
  struct Mode {
    Vec2 p;
    std::size_t support;
    std::size_t seed;
  };
  const double b2 = bandwidth_m * bandwidth_m;
  std::vector<Mode> modes;
  modes.reserve(points.size());
  for (std::size_t s = 0; s < points.size(); ++s) {
    Vec2 x = points[s];
    std::size_t support = 0;
    for (int iter = 0; iter < 300; ++iter) {
      Vec2 sum = Vec2::Zero();
      std::size_t n = 0;
      for (const Vec2& q : points) {
        if ((q - x).squaredNorm() <= b2) {
          sum += q;
          ++n;
        }
      }
      if (n == 0) break;
      const Vec2 next = sum / static_cast<double>(n);
      support = n;
      const bool converged = (next - x).norm() < 1e-3 * bandwidth_m;
      x = next;
      if (converged) break;
    }
    if (support > 0) modes.push_back({x, support, s});
  }
  std::stable_sort(modes.begin(), modes.end(),
                   [](const Mode& a, const Mode& b) { return a.support > b.support; });
  std::vector<Vec2> centers;
  for (const Mode& m : modes) {
    const bool duplicate = std::any_of(centers.begin(), centers.end(),
                                       [&](const Vec2& c) { return (c - m.p).squaredNorm() < b2; });
    if (!duplicate) centers.push_back(m.p);
  }
  return centers;
}

}  // namespace

RrtExploration::RrtExploration(std::uint64_t seed, const RrtExplorationOptions& options)
    : options_(options), rng_(seed) {}

RrtExploration::~RrtExploration() = default;

bool RrtExploration::blacklisted(const Vec2& p) const {
  const double r2 = options_.blacklist_radius_m * options_.blacklist_radius_m;
  return std::any_of(blacklist_.begin(), blacklist_.end(),
                     [&](const Vec2& b) { return (b - p).squaredNorm() < r2; });
}

void RrtExploration::onGoalReached(const Vec2& goal_m) {
  // The robot stood at this goal: whatever is still unknown around it (behind a wall, under a
  // wall face no beam hits) cannot be seen from there, so it is not assigned again.
  if (has_goal_ && (goal_m - goal_m_).norm() < 1e-9) blacklist_.push_back(goal_m);
  has_goal_ = false;
}

void RrtExploration::onGoalFailed(const Vec2& goal_m) {
  if (has_goal_ && (goal_m - goal_m_).norm() < 1e-9) blacklist_.push_back(goal_m);
  has_goal_ = false;
}

void RrtExploration::followGeometry(const ExplorationInput& input, const GridGeometry& previous) {
  const GridGeometry& g = input.grid.geometry();
  const auto onGrid = [&g](const Vec2& p) { return g.contains(p); };
  if (global_) {
    const Vec2 max_m = farCorner(g);
    for (RrtTree* tree : {global_.get(), local_.get()}) {
      if (tree->rebound(g.origin_m(), max_m, onGrid) == 0) tree->reset(input.robot.position());
    }
    sampler_ = uniformBoxSampler(g.origin_m(), max_m);
  }
  visited_ = remapCells(visited_, previous, g);
  std::erase_if(detected_, [&](const Vec2& p) { return !onGrid(p); });
  std::erase_if(centroids_, [&](const Vec2& p) { return !onGrid(p); });
}

void RrtExploration::grow(const ExplorationInput& input) {
  const Vec2 robot = input.robot.position();
  const GridGeometry& g = input.grid.geometry();
  if (!global_) {
    const Vec2 max_m =
        g.origin_m() + Vec2(g.width() * g.resolution_m(), g.height() * g.resolution_m());
    global_ = std::make_unique<RrtTree>(options_.global_eta_m, g.origin_m(), max_m, 1.0);
    local_ = std::make_unique<RrtTree>(options_.local_eta_m, g.origin_m(), max_m, 0.5);
    sampler_ = uniformBoxSampler(g.origin_m(), max_m);
    global_->reset(robot);
    local_->reset(robot);
    grown_until_s_ = input.time_s;
    last_end_check_s_ = input.time_s;
    return;
  }
  const double owed = (input.time_s - grown_until_s_) * options_.samples_per_s;
  long n = static_cast<long>(std::floor(owed + 1e-9));
  if (n <= 0) return;
  if (n > options_.max_samples_per_call) {
    n = options_.max_samples_per_call;
    grown_until_s_ = input.time_s;
  } else {
    grown_until_s_ += static_cast<double>(n) / options_.samples_per_s;
  }
  for (long k = 0; k < n; ++k) {
    const RrtExtension a = global_->grow(input.grid, sampler_, rng_);
    if (a.status == EdgeStatus::kFrontier) detected_.push_back(a.new_m);
    const RrtExtension b = local_->grow(input.grid, sampler_, rng_);
    if (b.status == EdgeStatus::kFrontier) {
      detected_.push_back(b.new_m);
      local_->reset(robot);
    }
  }
}

void RrtExploration::filter(const ExplorationInput& input) {
  std::vector<Vec2> points = centroids_;
  points.insert(points.end(), detected_.begin(), detected_.end());
  detected_.clear();
  std::vector<Vec2> centers = meanShift(points, options_.bandwidth_m);
  const GridGeometry& g = input.grid.geometry();
  std::erase_if(centers, [&](const Vec2& c) {
    const Cell cell = g.cellOf(c);
    if (!g.contains(cell) || input.costmap.isLethal(g.index(cell))) return true;
    return unknownAreaInDisc(input.grid, c, 0.5 * options_.info_radius_m) <
           options_.min_info_gain_m2;
  });
  centroids_ = std::move(centers);
}

Decision RrtExploration::decide(const ExplorationInput& input) {
  if (const auto previous = geometry_.update(input.grid.geometry()))
    followGeometry(input, *previous);
  grow(input);
  filter(input);
  markDisc(visited_, input.grid.geometry(), input.robot.position(), options_.observed_radius_m);

  // End test (added; see the header).
  const Vec2 robot_m = input.robot.position();
  if (input.time_s - last_end_check_s_ >= options_.end_check_period_s - 1e-9) {
    last_end_check_s_ = input.time_s;
    const std::size_t cells =
        countEndTestFrontierCells(input.grid, input.costmap, 4, visited_, robot_m,
                                  static_cast<std::size_t>(options_.end_min_frontier_cells),
                                  options_.end_pockets, input.time_s, last_pocket_check_s_);
    if (cells < static_cast<std::size_t>(options_.end_min_frontier_cells)) {
      if (++failed_end_checks_ >= options_.end_checks) return Decision::done();
    } else {
      failed_end_checks_ = 0;
    }
  }

  // Assigner.
  const Vec2 robot = input.robot.position();
  double best_revenue = -std::numeric_limits<double>::infinity();
  const Vec2* best = nullptr;
  for (const Vec2& c : centroids_) {
    if (blacklisted(c)) continue;
    const double area = unknownAreaInDisc(input.grid, c, options_.info_radius_m);
    double ig = area;
    const double d = (c - robot).norm();
    if (d <= options_.hysteresis_radius_m) ig *= options_.hysteresis_gain;
    // The original's busy robot: centroids near the goal it is driving to get the bonus too,
    // so that it does not flip between goals of similar revenue on the way.
    if (has_goal_ && (c - goal_m_).norm() < options_.hysteresis_radius_m)
      ig = area * options_.hysteresis_gain;
    const double revenue = options_.info_multiplier * ig - d;
    if (revenue > best_revenue) {
      best_revenue = revenue;
      best = &c;
    }
  }
  const GridGeometry& g = input.grid.geometry();
  if (best != nullptr) {
    idle_since_s_ = -1.0;
    has_goal_ = true;
    goal_m_ = *best;
    return Decision::goal(goal_m_);
  }
  if (has_goal_ && !input.costmap.isLethal(g.cellOf(goal_m_))) return Decision::goal(goal_m_);
  if (has_goal_) onGoalFailed(goal_m_);  // a goal that became lethal is given up
  if (idle_since_s_ < 0.0) idle_since_s_ = input.time_s;
  if (input.time_s - idle_since_s_ >= options_.idle_end_s) return Decision::done();
  // Nothing to assign yet: wait where we are while the trees grow.
  if (const auto wait = nearestGoalCell(input.grid, input.costmap, robot, 3.0))
    return Decision::goal(*wait);
  return Decision::done();
}

}  // namespace roomscout
