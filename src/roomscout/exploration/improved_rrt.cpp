#include "roomscout/exploration/detail/improved_rrt.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

void ImprovedRrtOptions::validate() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(eta_m)) throw OptionError("improved_rrt.eta_m must be > 0");
  if (!positive(iterations_per_s)) throw OptionError("improved_rrt.iterations_per_s must be > 0");
  if (!positive(info_radius_m)) throw OptionError("improved_rrt.info_radius_m must be > 0");
  if (!(hysteresis_radius_m >= 0.0) || !(hysteresis_gain >= 0.0) || !(gain_weight >= 0.0)) {
    throw OptionError(
        "improved_rrt: hysteresis_radius_m, hysteresis_gain and gain_weight must be >= 0");
  }
  if (new_points_trigger < 0 || iterations_trigger < 1 || min_goal_change_cells < 0) {
    throw OptionError(
        "improved_rrt: new_points_trigger >= 0, iterations_trigger >= 1, min_goal_change_cells >= "
        "0");
  }
  if (end_check_iterations < 1 || end_checks < 1 || end_min_frontier_cells < 1 ||
      end_obstacle_l1_cells < 1) {
    throw OptionError("improved_rrt: end test counts must be >= 1");
  }
  if (!(replan_period_s >= 0.0)) throw OptionError("improved_rrt.replan_period_s must be >= 0");
  if (!(blacklist_radius_m >= 0.0))
    throw OptionError("improved_rrt.blacklist_radius_m must be >= 0");
  if (!(observed_radius_m >= 0.0)) throw OptionError("improved_rrt.observed_radius_m must be >= 0");
  if (max_iterations_per_call < 1)
    throw OptionError("improved_rrt.max_iterations_per_call must be >= 1");
  end_pockets.validate("improved_rrt");
  if (!(look_after_idle_s >= 0.0 && std::isfinite(look_after_idle_s))) {
    throw OptionError("improved_rrt.look_after_idle_s must be finite and >= 0");
  }
}

std::vector<ParameterRef> ImprovedRrtOptions::parameters() {
  std::vector<ParameterRef> parameters = {
      {"eta_m", &eta_m, "tree steering step [m]"},
      {"iterations_per_s", &iterations_per_s, "RRT iterations per simulated second"},
      {"info_radius_m", &info_radius_m, "half-side of the information gain square [m]"},
      {"hysteresis_radius_m", &hysteresis_radius_m, "gain bonus radius around the robot [m]"},
      {"hysteresis_gain", &hysteresis_gain, "gain factor within the hysteresis radius"},
      {"gain_weight", &gain_weight,
       "score = gain_weight * G - distance, G the (unknown - occupied) area [m^2] in the "
       "information gain square"},
      {"new_points_trigger", &new_points_trigger,
       "a goal selection runs after more new points than this"},
      {"iterations_trigger", &iterations_trigger,
       "a goal selection runs after more iterations than this"},
      {"min_goal_change_cells", &min_goal_change_cells, "least L1 move of a new goal [cells]"},
      {"end_check_iterations", &end_check_iterations, "iterations between end tests"},
      {"end_checks", &end_checks, "consecutive failing end tests that end exploration"},
      {"end_min_frontier_cells", &end_min_frontier_cells,
       "fewer reachable frontier cells fail the end test"},
      {"end_obstacle_l1_cells", &end_obstacle_l1_cells,
       "L1 margin of a reachable frontier cell to obstacles [cells]"},
      {"replan_period_s", &replan_period_s, "decision period while driving [s]"},
      {"blacklist_radius_m", &blacklist_radius_m,
       "points this close to a failed goal are dropped [m]"},
      {"observed_radius_m", &observed_radius_m,
       "end test: frontier cells still unknown this close to the robot are ignored [m]"},
      {"unsigned_count_quirk", &unsigned_count_quirk,
       "also select whenever points were removed since the last selection (the original's unsigned "
       "difference)"},
      {"max_iterations_per_call", &max_iterations_per_call,
       "cap on the owed iterations run in one call"},
  };
  for (const ParameterRef& p : end_pockets.parameters()) parameters.push_back(p);
  parameters.push_back(
      {"look_after_idle_s", &look_after_idle_s,
       "no frontier point for this long while the end test still counts reachable frontier cells: "
       "drive to look at the nearest of them [s]; 0 = never (the original idles)"});
  return parameters;
}

/// Row prefix sums of (unknown - occupied) over a grid, for SMMR-Explore's
/// informationRectangleGain: a square's sum costs two lookups per row. A build brings only the
/// rows whose cell states changed since the last build up to date and records the box of cells
/// that changed, so that a point's cached gain is recomputed only when its square meets that box
/// (the sums are integers: a cached gain is exactly the one a full recomputation would give).
class GainTable {
 public:
  void build(const OccupancyGrid& grid) {
    const GridGeometry& g = grid.geometry();
    const std::uint8_t* states = grid.stateBytes();
    const bool resized = g.width() != w_ || g.height() != h_;
    if (resized) {
      w_ = g.width();
      h_ = g.height();
      const std::size_t cells = static_cast<std::size_t>(w_) * h_;
      snapshot_.assign(states, states + cells);
      row_sum_.assign(static_cast<std::size_t>(w_ + 1) * h_, 0);
      changed_x0_ = 0, changed_x1_ = w_ - 1, changed_y0_ = 0, changed_y1_ = h_ - 1;
    } else {
      changed_x0_ = w_, changed_x1_ = -1, changed_y0_ = h_, changed_y1_ = -1;
    }
    for (int y = 0; y < h_; ++y) {
      const std::size_t row = static_cast<std::size_t>(y) * w_;
      if (!resized) {
        const std::uint8_t* old_row = snapshot_.data() + row;
        if (std::memcmp(old_row, states + row, static_cast<std::size_t>(w_)) == 0) continue;
        int x0 = 0, x1 = w_ - 1;
        while (old_row[x0] == states[row + x0]) ++x0;
        while (old_row[x1] == states[row + x1]) --x1;
        changed_x0_ = std::min(changed_x0_, x0);
        changed_x1_ = std::max(changed_x1_, x1);
        changed_y0_ = std::min(changed_y0_, y);
        changed_y1_ = y;
        std::memcpy(snapshot_.data() + row, states + row, static_cast<std::size_t>(w_));
      }
      // Unknown +1, free 0, occupied -1: one minus the state byte.
      int* out = &row_sum_[static_cast<std::size_t>(y) * (w_ + 1)];
      int run = 0;
      out[0] = 0;
      for (int x = 0; x < w_; ++x) out[x + 1] = run += 1 - static_cast<int>(states[row + x]);
    }
  }
  /// Whether any cell of [x0, x1) x [y0, y1) changed in the last build.
  bool changed(int x0, int y0, int x1, int y1) const {
    return x0 <= changed_x1_ && x1 > changed_x0_ && y0 <= changed_y1_ && y1 > changed_y0_;
  }
  /// Sum over cells [x0, x1) x [y0, y1), clipped to the grid.
  int sum(int x0, int y0, int x1, int y1) const {
    x0 = std::clamp(x0, 0, w_);
    x1 = std::clamp(x1, 0, w_);
    y0 = std::clamp(y0, 0, h_);
    y1 = std::clamp(y1, 0, h_);
    if (x0 >= x1 || y0 >= y1) return 0;
    const std::size_t stride = static_cast<std::size_t>(w_) + 1;
    int total = 0;
    for (int y = y0; y < y1; ++y) {
      const int* rs = &row_sum_[y * stride];
      total += rs[x1] - rs[x0];
    }
    return total;
  }

 private:
  int w_ = -1, h_ = -1;
  std::vector<std::uint8_t> snapshot_;  ///< cell states at the last build
  std::vector<int> row_sum_;            ///< per row: prefix sums of its cell values
  int changed_x0_ = 0, changed_x1_ = -1, changed_y0_ = 0, changed_y1_ = -1;  ///< inclusive; empty
};

/// SMMR-Explore's informationRectangleGain: (unknown - occupied) area [m^2] in the square of
/// half-side `half_m` around `p`: 2r+1 rows by 2r columns of cells (r = half_m / resolution,
/// truncated), as the original's loops; cells outside the grid count as nothing.
namespace {

struct GainSquare {
  int x0, y0, x1, y1;
};

GainSquare gainSquare(const GridGeometry& g, const Cell& c, double half_m) {
  const int r = static_cast<int>(half_m / g.resolution_m());
  return {c.x - r, c.y - r, c.x + r, c.y + r + 1};
}

double rectangleGain(const GainTable& table, const GridGeometry& g, const Cell& c, double half_m) {
  const GainSquare q = gainSquare(g, c, half_m);
  return table.sum(q.x0, q.y0, q.x1, q.y1) * g.resolution_m() * g.resolution_m();
}

}  // namespace

ImprovedRrt::ImprovedRrt(std::uint64_t seed, const ImprovedRrtOptions& options)
    : options_(options), rng_(seed), gain_table_(std::make_unique<GainTable>()) {}

ImprovedRrt::~ImprovedRrt() = default;

template <typename Pred>
void ImprovedRrt::eraseFrontiers(Pred&& pred) {
  std::erase_if(frontiers_, pred);
  held_ = 0;
  previous_index_ = -1;
  for (std::size_t i = 0; i < frontiers_.size(); ++i) {
    held_ += frontiers_[i].copies;
    if (has_previous_ && previous_index_ < 0 && frontiers_[i].p == previous_goal_.p) {
      previous_index_ = static_cast<long>(i);
    }
  }
}

bool ImprovedRrt::blacklisted(const Vec2& p) const {
  const double r2 = options_.blacklist_radius_m * options_.blacklist_radius_m;
  return std::any_of(blacklist_.begin(), blacklist_.end(),
                     [&](const Vec2& b) { return (b - p).squaredNorm() < r2; });
}

void ImprovedRrt::onGoalReached(const Vec2& goal_m) { onGoalFailed(goal_m); }

void ImprovedRrt::onGoalFailed(const Vec2& goal_m) {
  if (looking_ && (goal_m - look_goal_m_).norm() < 1e-9) {
    // Reached, or given up as unreachable: either way the cell counts as looked at (marked in
    // the next decide(), which has the grid).
    look_ended_ = true;
    looking_ = false;
  }
  // Reached or failed, the goal is not sent again: what is still unknown around a reached goal
  // cannot be seen from it (behind a wall), and a failed one cannot be reached.
  if (goal_active_ && (goal_m - previous_goal_.p).norm() < 1e-9) {
    blacklist_.push_back(goal_m);
    eraseFrontiers([&](const Point& f) { return blacklisted(f.p); });
  }
  goal_active_ = false;
}

ImprovedRrt::Point ImprovedRrt::makePoint(const GridGeometry& g, const Vec2& p, long copies) {
  Point f{p, copies};
  f.cell = g.cellOf(p);
  f.index = g.contains(f.cell) ? static_cast<long>(g.index(f.cell)) : -1;
  const double res = g.resolution_m();
  const Vec2 offsets[4] = {{res, 0}, {0, res}, {-res, 0}, {0, -res}};
  for (int k = 0; k < 4; ++k) {
    const Cell c = g.cellOf(p + offsets[k]);
    f.neighbours[k] = g.contains(c) ? static_cast<long>(g.index(c)) : -1;
  }
  return f;
}

bool ImprovedRrt::stale(const ExplorationInput& input, const Point& f) {
  if (f.index < 0) return true;
  const auto i = static_cast<std::size_t>(f.index);
  return !input.grid.isUnknown(i) || input.costmap.isLethal(i);
}

ImprovedRrt::Step ImprovedRrt::iterate(const ExplorationInput& input,
                                       const RrtTree::Sampler& sampler) {
  // End test every end_check_iterations iterations; a failing test skips the iteration.
  if (++iterations_since_end_check_ >= options_.end_check_iterations) {
    const Vec2 robot_m = input.robot.position();
    iterations_since_end_check_ = 0;
    const std::size_t cells = countEndTestFrontierCells(
        input.grid, input.costmap, options_.end_obstacle_l1_cells, visited_, robot_m,
        static_cast<std::size_t>(options_.end_min_frontier_cells), options_.end_pockets,
        input.time_s, last_pocket_check_s_);
    if (cells < static_cast<std::size_t>(options_.end_min_frontier_cells)) {
      if (++failed_end_checks_ >= options_.end_checks) return Step::kDone;
      return Step::kContinue;
    }
    failed_end_checks_ = 0;
  }

  // The original appends the new point and the previous goal, then drops every stale point.
  // The grid does not change within a call and decide() dropped the stale points before the
  // first iteration, so only the appended ones need the test; the previous goal's copies are
  // counted on its entry instead of stored (see Point::copies).
  const RrtExtension e = tree_->grow(input.grid, sampler, rng_);
  if (e.status == EdgeStatus::kFrontier && !blacklisted(e.new_m)) {
    Point f = makePoint(input.grid.geometry(), e.new_m, 1);
    if (!stale(input, f)) {
      frontiers_.push_back(f);
      ++held_;
    }
  }
  ++iterations_since_selection_;
  if (has_previous_ && !stale(input, previous_goal_) && !blacklisted(previous_goal_.p)) {
    if (previous_index_ < 0) {
      previous_index_ = static_cast<long>(frontiers_.size());
      frontiers_.push_back(previous_goal_);
      frontiers_.back().copies = 0;
      frontiers_.back().gain_valid = false;  // the copy missed the table's builds since
    }
    ++frontiers_[static_cast<std::size_t>(previous_index_)].copies;
    ++held_;
  }

  const long held = held_;
  // The original's unsigned difference: fewer points than after the last selection also fires.
  const bool more = held - selected_count_ > options_.new_points_trigger ||
                    (options_.unsigned_count_quirk && held < selected_count_);
  if (more || iterations_since_selection_ > options_.iterations_trigger) select(input);
  return Step::kContinue;
}

void ImprovedRrt::select(const ExplorationInput& input) {
  iterations_since_selection_ = 0;
  const GridGeometry& g = input.grid.geometry();
  const double res = g.resolution_m();
  // Points whose four neighbours are all unknown lie outside the valid map.
  eraseFrontiers([&](const Point& f) {
    for (const long n : f.neighbours) {
      if (n < 0 || !input.grid.isUnknown(static_cast<std::size_t>(n))) return false;
    }
    return true;
  });
  selected_count_ = held_;
  if (frontiers_.empty()) return;

  const Vec2 robot = input.robot.position();
  double best_score = -500.0;
  const Point* best = nullptr;
  if (table_call_ != call_) {
    // The grid changed since the last build (if at all) only inside the table's changed box.
    gain_table_->build(input.grid);
    table_call_ = call_;
    for (Point& f : frontiers_) {
      const GainSquare q = gainSquare(g, f.cell, options_.info_radius_m);
      if (f.gain_valid && gain_table_->changed(q.x0, q.y0, q.x1, q.y1)) f.gain_valid = false;
    }
  }
  for (Point& f : frontiers_) {
    if (!f.gain_valid) {
      f.gain_m2 = rectangleGain(*gain_table_, g, f.cell, options_.info_radius_m);
      f.gain_valid = true;
    }
    double gain = f.gain_m2;
    const double d = (f.p - robot).norm();
    if (d <= options_.hysteresis_radius_m) gain *= options_.hysteresis_gain;
    const double score = options_.gain_weight * gain - d;
    if (score > best_score) {
      best_score = score;
      best = &f;
    }
  }
  if (best == nullptr) return;
  const double l1 =
      std::abs(best->p.x() - previous_goal_.p.x()) + std::abs(best->p.y() - previous_goal_.p.y());
  if (has_previous_ && l1 < options_.min_goal_change_cells * res) return;
  previous_goal_ = *best;
  previous_index_ = best - frontiers_.data();
  has_previous_ = true;
  goal_active_ = true;
}

void ImprovedRrt::followGeometry(const ExplorationInput& input, const GridGeometry& previous) {
  const GridGeometry& g = input.grid.geometry();
  if (tree_ && tree_->rebound(g.origin_m(), farCorner(g),
                              [&g](const Vec2& p) { return g.contains(p); }) == 0) {
    tree_->reset(input.robot.position());
  }
  // Cells and indices are the old grid's: recomputed from the points; gains too.
  for (Point& f : frontiers_) f = makePoint(g, f.p, f.copies);
  if (has_previous_) previous_goal_ = makePoint(g, previous_goal_.p, previous_goal_.copies);
  eraseFrontiers([](const Point& f) { return f.index < 0; });
  gain_table_ = std::make_unique<GainTable>();
  table_call_ = 0;
  visited_ = remapCells(visited_, previous, g);
  if (looking_ && !g.contains(look_cell_m_)) looking_ = false;
}

Decision ImprovedRrt::decide(const ExplorationInput& input) {
  ++call_;
  if (const auto previous = geometry_.update(input.grid.geometry()))
    followGeometry(input, *previous);
  const Vec2 robot = input.robot.position();
  if (!tree_) {
    const GridGeometry& g = input.grid.geometry();
    const Vec2 max_m =
        g.origin_m() + Vec2(g.width() * g.resolution_m(), g.height() * g.resolution_m());
    tree_ = std::make_unique<RrtTree>(options_.eta_m, g.origin_m(), max_m, 0.5);
    tree_->reset(robot);
    done_until_s_ = input.time_s;
  }
  const double owed = (input.time_s - done_until_s_) * options_.iterations_per_s;
  long n = static_cast<long>(std::floor(owed + 1e-9));
  if (n > options_.max_iterations_per_call) {
    n = options_.max_iterations_per_call;
    done_until_s_ = input.time_s;
  } else if (n > 0) {
    done_until_s_ += static_cast<double>(n) / options_.iterations_per_s;
  }
  markDisc(visited_, input.grid.geometry(), robot, options_.observed_radius_m);
  if (look_ended_)
    markDisc(visited_, input.grid.geometry(), look_cell_m_, options_.observed_radius_m);
  look_ended_ = false;
  if (n > 0) {
    Vec2 box_min, box_max;
    knownCellsBox(input.grid, robot, kCartographerPaddingCells, box_min, box_max);
    const RrtTree::Sampler sampler = uniformBoxSampler(box_min, box_max);
    eraseFrontiers([&](const Point& f) { return stale(input, f); });
    for (long k = 0; k < n; ++k) {
      if (iterate(input, sampler) == Step::kDone) return Decision::done();
    }
  }

  const GridGeometry& g = input.grid.geometry();
  if (goal_active_ && !input.costmap.isLethal(g.cellOf(previous_goal_.p)))
    return Decision::goal(previous_goal_.p);
  // A goal that became lethal is given up like a failed one.
  if (goal_active_) onGoalFailed(previous_goal_.p);
  if (const auto look = lookGoal(input)) return Decision::goal(*look);
  // No goal to drive to: wait where we are until the next selection.
  if (const auto wait = nearestGoalCell(input.grid, input.costmap, robot, 3.0))
    return Decision::goal(*wait);
  return Decision::done();
}

std::optional<Vec2> ImprovedRrt::lookGoal(const ExplorationInput& input) {
  if (!frontiers_.empty() || options_.look_after_idle_s <= 0.0) {
    idle_since_s_ = -1.0;
    looking_ = false;
    return std::nullopt;
  }
  if (idle_since_s_ < 0.0) idle_since_s_ = input.time_s;
  if (input.time_s - idle_since_s_ < options_.look_after_idle_s - 1e-9) return std::nullopt;
  const GridGeometry& g = input.grid.geometry();
  if (looking_ && g.contains(look_cell_m_) && visited_[g.index(g.cellOf(look_cell_m_))] == 0)
    return look_goal_m_;
  looking_ = false;
  const Vec2 robot = input.robot.position();
  const std::vector<Cell> cells = reachableFrontierCells(
      input.grid, input.costmap, options_.end_obstacle_l1_cells, &visited_, &robot);
  if (cells.empty()) return std::nullopt;
  const Cell nearest =
      *std::min_element(cells.begin(), cells.end(), [&](const Cell& a, const Cell& b) {
        return (g.centerOf(a) - robot).squaredNorm() < (g.centerOf(b) - robot).squaredNorm();
      });
  look_cell_m_ = g.centerOf(nearest);
  const std::optional<Vec2> goal =
      nearestGoalCell(input.grid, input.costmap, look_cell_m_, 2.0 * g.resolution_m());
  if (!goal) {
    markDisc(visited_, g, look_cell_m_, options_.observed_radius_m);
    return std::nullopt;
  }
  looking_ = true;
  look_goal_m_ = *goal;
  return look_goal_m_;
}

std::vector<Vec2> ImprovedRrt::candidateGoals() const {
  std::vector<Vec2> out;
  out.reserve(frontiers_.size());
  for (const Point& f : frontiers_) out.push_back(f.p);
  return out;
}

}  // namespace roomscout
