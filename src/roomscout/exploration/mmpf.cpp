#include "roomscout/exploration/detail/mmpf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

void MmpfOptions::validate() const {
  if (!(std::isfinite(cycle_period_s) && cycle_period_s > 0.0))
    throw OptionError("mmpf.cycle_period_s must be > 0");
  if (obstacle_l1_cells < 1 || cluster_l1_cells < 1)
    throw OptionError("mmpf: obstacle_l1_cells and cluster_l1_cells must be >= 1");
  if (max_descent_steps < 1) throw OptionError("mmpf.max_descent_steps must be >= 1");
  if (!(river_step >= 0.0)) throw OptionError("mmpf.river_step must be >= 0");
  if (coarse_factor < 1 || coarse_factor > 8)
    throw OptionError("mmpf.coarse_factor must be in [1, 8]");
  if (!(keep_goal_radius_m >= 0.0)) throw OptionError("mmpf.keep_goal_radius_m must be >= 0");
  if (end_cycles < 1) throw OptionError("mmpf.end_cycles must be >= 1");
}

std::vector<ParameterRef> MmpfOptions::parameters() {
  return {
      {"cycle_period_s", &cycle_period_s, "time between potential-field cycles [s]"},
      {"obstacle_l1_cells", &obstacle_l1_cells,
       "frontier cells nearer (L1) to an obstacle are dropped [cells]"},
      {"cluster_l1_cells", &cluster_l1_cells, "cluster join distance (L1, exclusive) [cells]"},
      {"max_descent_steps", &max_descent_steps, "gradient descent iterations"},
      {"river_step", &river_step, "river potential per earlier visit of a cell, times the gain"},
      {"coarse_factor", &coarse_factor, "map cells per potential-field cell"},
      {"keep_goal_radius_m", &keep_goal_radius_m,
       "a goal with a frontier cell this close is kept [m]; 0 = replan every cycle"},
      {"end_cycles", &end_cycles, "cycles without frontier cells that end exploration"},
  };
}

namespace {

struct Cluster {
  Cell centre;  // map cell
  int size = 0;
};

/// SMMR's greedy clustering: take the last unassigned cell, absorb every cell within L1 < `join`
/// of any member until nothing joins; centre = the member nearest (L1) to the mean.
std::vector<Cluster> clusterCells(std::vector<Cell> cells, int join) {
  std::vector<Cluster> clusters;
  while (!cells.empty()) {
    std::vector<Cell> members{cells.back()};
    cells.pop_back();
    // Breadth-first growth: equivalent to the original's repeated scans.
    for (std::size_t m = 0; m < members.size(); ++m) {
      const Cell a = members[m];
      for (std::size_t i = cells.size(); i-- > 0;) {
        if (std::abs(cells[i].x - a.x) + std::abs(cells[i].y - a.y) < join) {
          members.push_back(cells[i]);
          cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(i));
        }
      }
    }
    double mx = 0, my = 0;
    for (const Cell& c : members) {
      mx += c.x;
      my += c.y;
    }
    mx /= static_cast<double>(members.size());
    my /= static_cast<double>(members.size());
    Cell centre = members.front();
    double best = std::numeric_limits<double>::infinity();
    for (const Cell& c : members) {
      const double d = std::abs(mx - c.x) + std::abs(my - c.y);
      if (d < best) {
        best = d;
        centre = c;
      }
    }
    clusters.push_back({centre, static_cast<int>(members.size())});
  }
  return clusters;
}

}  // namespace

Decision Mmpf::decide(const ExplorationInput& input) {
  const bool due = !started_ || input.time_s - last_cycle_s_ >= options_.cycle_period_s - 1e-9;
  const GridGeometry& g = input.grid.geometry();
  if (!due && has_goal_ && !input.costmap.isLethal(g.cellOf(goal_m_)))
    return Decision::goal(goal_m_);
  started_ = true;
  last_cycle_s_ = input.time_s;

  const Vec2 robot_m = input.robot.position();
  std::vector<Cell> targets = reachableFrontierCells(input.grid, input.costmap,
                                                     options_.obstacle_l1_cells, nullptr, &robot_m);
  std::erase_if(targets, [&](const Cell& c) {
    const Vec2 p = g.centerOf(c);
    return std::any_of(blacklist_.begin(), blacklist_.end(),
                       [&](const Vec2& b) { return (b - p).squaredNorm() < 0.25; });
  });
  if (targets.empty()) {
    if (++empty_cycles_ >= options_.end_cycles) return Decision::done();
    if (has_goal_ && !input.costmap.isLethal(g.cellOf(goal_m_))) return Decision::goal(goal_m_);
    has_goal_ = false;
    if (const auto wait = nearestGoalCell(input.grid, input.costmap, input.robot.position(), 3.0)) {
      return Decision::goal(*wait);
    }
    return Decision::done();
  }
  empty_cycles_ = 0;
  // Commitment (a deviation, see the header): a goal still next to a frontier cell is kept.
  if (has_goal_ && !input.costmap.isLethal(g.cellOf(goal_m_))) {
    const double r2 = options_.keep_goal_radius_m * options_.keep_goal_radius_m;
    for (const Cell& c : targets) {
      if ((g.centerOf(c) - goal_m_).squaredNorm() <= r2) return Decision::goal(goal_m_);
    }
  }
  const std::vector<Cluster> clusters = clusterCells(std::move(targets), options_.cluster_l1_cells);

  // Coarse grid: a cell is free when one of its map cells is free and none is occupied. It
  // has a border of blocked cells, so the BFS below needs no bounds checks.
  const int f = options_.coarse_factor;
  const int cw = (g.width() + f - 1) / f, ch = (g.height() + f - 1) / f;
  const int pw = cw + 2;  // padded row length
  const std::size_t pn = static_cast<std::size_t>(pw) * (ch + 2);
  free_.assign(pn, 0);
  // The states are bits (free 1, occupied 2), so OR-ing them gives 1 exactly for the cells
  // with some free and no occupied map cell.
  for (int y = 0; y < g.height(); ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * g.width();
    const std::size_t crow = static_cast<std::size_t>(y / f + 1) * pw + 1;
    for (int x = 0; x < g.width(); ++x) {
      free_[crow + x / f] |= static_cast<std::uint8_t>(input.grid.state(row + x));
    }
  }
  for (std::uint8_t& c : free_) c = c == 1 ? 1 : 0;

  // Potential from every cluster's BFS distance through free cells, level by level: every
  // cell of level d adds the same -size / d (computed once per level, as the per-cell division
  // did, so the sums are bit for bit those of a cell-by-cell BFS in the same cluster order).
  potential_.assign(pn, 0.0f);
  near_centre_.assign(pn, 0);
  std::vector<std::uint32_t> level, next;
  level.reserve(1024);
  next.reserve(1024);
  const std::ptrdiff_t step[4] = {1, -1, pw, -pw};
  for (const Cluster& cl : clusters) {
    seen_.begin(pn);
    const std::size_t s = static_cast<std::size_t>(cl.centre.y / f + 1) * pw + cl.centre.x / f + 1;
    seen_.mark(s);
    level.assign(1, static_cast<std::uint32_t>(s));
    for (int d = 1; !level.empty(); ++d) {
      const float add = static_cast<float>(cl.size) / static_cast<float>(d);
      next.clear();
      for (const std::uint32_t i : level) {
        for (const std::ptrdiff_t o : step) {
          const std::size_t n = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + o);
          if (seen_.marked(n) || !free_[n]) continue;
          seen_.mark(n);
          next.push_back(static_cast<std::uint32_t>(n));
          potential_[n] -= add;
          if (d <= 1) near_centre_[n] = 1;
        }
      }
      level.swap(next);
    }
  }

  // Gradient descent with the river term.
  const Cell rc = g.cellOf(input.robot.position());
  Cell cur{std::clamp(rc.x / f, 0, cw - 1), std::clamp(rc.y / f, 0, ch - 1)};
  visits_.assign(pn, 0);
  std::vector<std::size_t> path{static_cast<std::size_t>(cur.y + 1) * pw + cur.x + 1};
  visits_[path.back()] = 1;
  double current = 1e9;
  double river_gain = 1.0;
  for (int it = 1; it < options_.max_descent_steps; ++it) {
    const Cell around[4] = {
        {cur.x, cur.y + 1}, {cur.x - 1, cur.y}, {cur.x, cur.y - 1}, {cur.x + 1, cur.y}};
    int best_k = -1;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
      const Cell a = around[k];
      if (a.x < 0 || a.y < 0 || a.x >= cw || a.y >= ch) continue;
      const std::size_t i = static_cast<std::size_t>(a.y + 1) * pw + a.x + 1;
      const double p = potential_[i] + options_.river_step * river_gain * visits_[i];
      if (p < best) {
        best = p;
        best_k = k;
      }
    }
    if (best_k < 0) break;
    // No lower neighbour: a local minimum. The gain grows and, unlike the original code (which
    // stays put for the remaining steps), the descent flows on to the lowest neighbour, the
    // river term keeping it from flowing back.
    if (!(best < current)) river_gain += 1.0;
    cur = around[best_k];
    const std::size_t i = static_cast<std::size_t>(cur.y + 1) * pw + cur.x + 1;
    path.push_back(i);
    if (visits_[i] < 60000) ++visits_[i];
    current = best;
    if (near_centre_[path.back()]) break;
  }

  const Vec2 end_m = g.origin_m() + Vec2((cur.x + 0.5) * f * g.resolution_m(),
                                         (cur.y + 0.5) * f * g.resolution_m());
  std::optional<Vec2> goal =
      nearestGoalCell(input.grid, input.costmap, end_m, 1.0, /*free_only=*/true);
  if (!goal) goal = nearestGoalCell(input.grid, input.costmap, end_m, 3.0);
  if (!goal) return Decision::done();
  has_goal_ = true;
  goal_m_ = *goal;
  return Decision::goal(goal_m_);
}

}  // namespace roomscout
