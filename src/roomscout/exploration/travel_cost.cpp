#include "roomscout/exploration/detail/travel_cost.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace roomscout {
namespace {

/// Geodesic C is searched on blocks of this many cells a side (0.1 m at 0.05 m cells).
constexpr int kBlock = 2;

}  // namespace

void TravelCost::apply(const ExplorationInput& input, std::vector<GoalCandidate>& candidates,
                       double w_c) {
  const Vec2 robot = input.robot.position();
  for (GoalCandidate& c : candidates) c.cost_m = (c.p - robot).norm();
  if (!geodesic_) return;
  // Dijkstra from the robot (8-connected) over blocks of kBlock x kBlock cells; a block is
  // passable when one of its cells is not lethal (a wall's lethal band is wider than a block,
  // so no path leaks through). Every block whose distance is at most the queue's smallest is
  // final; a candidate not final yet costs at least that much (and at least its straight-line
  // distance), which bounds its score. The search stops once the goal's cost is final and no
  // candidate still open can beat the best final one of its kind: the choice is that of a
  // search over the whole map. Open candidates keep an infinite cost (they cannot win). Blocks
  // of 2 x 2 cells instead of single cells take about half the time on large maps, with
  // lengths and revisits within the seeds' noise.
  const GridGeometry& g = input.grid.geometry();
  const int gw = g.width(), gh = g.height();
  const int w = (gw + kBlock - 1) / kBlock, h = (gh + kBlock - 1) / kBlock;
  const std::size_t blocks = static_cast<std::size_t>(w) * h;
  if (dist_.size() != blocks) dist_.assign(blocks, 0.0f);
  dist_valid_.begin(blocks);
  const float inf = std::numeric_limits<float>::infinity();
  auto distOf = [&](std::size_t i) { return dist_valid_.marked(i) ? dist_[i] : inf; };
  auto blockOf = [&](const Vec2& p) -> std::size_t {
    const Cell c = g.cellOf(p);
    if (!g.contains(c)) return blocks;
    return static_cast<std::size_t>(c.y / kBlock) * w + c.x / kBlock;
  };
  auto passable = [&](int bx, int by) {
    for (int y = by * kBlock; y < std::min(gh, (by + 1) * kBlock); ++y) {
      for (int x = bx * kBlock; x < std::min(gw, (bx + 1) * kBlock); ++x) {
        if (!input.costmap.isLethal(static_cast<std::size_t>(y) * gw + x)) return true;
      }
    }
    return false;
  };
  blocks_.clear();
  for (const GoalCandidate& c : candidates) blocks_.push_back(blockOf(c.p));
  heap_.clear();
  const std::size_t start = blockOf(robot);
  if (start < blocks) {
    dist_[start] = 0.0f;
    dist_valid_.mark(start);
    heap_.push_back({0.0f, start});
  }
  // True when nothing still open can change the choice, given that every block up to d is final.
  auto settled = [&](double d) {
    const double none = -std::numeric_limits<double>::infinity();
    double best[2] = {none, none}, open_bound[2] = {none, none};
    bool open[2] = {false, false};
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const GoalCandidate& c = candidates[k];
      const double dc = blocks_[k] < blocks ? distOf(blocks_[k]) : inf;
      if (dc <= d) {
        if (!c.goal) best[c.sliver] = std::max(best[c.sliver], c.without_cost - w_c * dc);
        continue;
      }
      if (c.goal) return false;
      open[c.sliver] = true;
      open_bound[c.sliver] =
          std::max(open_bound[c.sliver], c.without_cost - w_c * std::max(d, c.cost_m));
    }
    const bool points_done = !open[0] || open_bound[0] < best[0];
    // Slivers matter only when no other point can be chosen.
    const bool slivers_done =
        !open[1] || open_bound[1] < best[1] || (best[0] > none && points_done);
    return points_done && slivers_done;
  };
  const float step = static_cast<float>(kBlock * g.resolution_m());
  const float diag = step * std::sqrt(2.0f);
  constexpr double kCheckStep_m = 0.25;  // the stop test runs once per this much of radius
  double next_check_m = 0.0;
  const auto later = std::greater<>();
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const auto [d, i] = heap_.back();
    heap_.pop_back();
    if (d > dist_[i]) continue;
    if (d >= next_check_m) {
      if (settled(d)) break;
      next_check_m = d + kCheckStep_m;
    }
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h)
          continue;
        const std::size_t j = static_cast<std::size_t>(y + dy) * w + (x + dx);
        const float nd = d + ((dx != 0 && dy != 0) ? diag : step);
        if (nd < distOf(j) && passable(x + dx, y + dy)) {
          dist_[j] = nd;
          dist_valid_.mark(j);
          heap_.push_back({nd, j});
          std::push_heap(heap_.begin(), heap_.end(), later);
        }
      }
    }
  }
  // Final distances: those not above the smallest distance still queued (all when it is empty).
  const float final_up_to =
      heap_.empty() ? inf : std::min_element(heap_.begin(), heap_.end())->first;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const float dc = blocks_[k] < blocks ? distOf(blocks_[k]) : inf;
    candidates[k].cost_m = dc <= final_up_to ? dc : std::numeric_limits<double>::infinity();
  }
}

}  // namespace roomscout
