#include "roomscout/exploration/frontier_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomscout {

std::vector<Cell> reachableFrontierCells(const OccupancyGrid& grid, const Costmap& costmap,
                                         int obstacle_l1_cells,
                                         const std::vector<std::uint8_t>* exhausted,
                                         const Vec2* robot_m) {
  const GridGeometry& g = grid.geometry();
  const int w = g.width(), h = g.height();
  std::vector<Cell> out;
  if (w < 5 || h < 5) return out;
  auto free = [&](int x, int y) { return grid.isFree(static_cast<std::size_t>(y) * w + x); };
  static constexpr int kDx[4] = {1, 0, -1, 0};
  static constexpr int kDy[4] = {0, 1, 0, -1};
  const int r = obstacle_l1_cells - 1;  // occupied cells at L1 <= r reject a cell
  std::vector<std::uint8_t> region;
  if (robot_m != nullptr) region = robotFreeRegion(grid, costmap, *robot_m);
  for (int y = 2; y < h - 2; ++y) {
    for (int x = 2; x < w - 2; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!grid.isUnknown(i)) continue;
      if (exhausted != nullptr && i < exhausted->size() && (*exhausted)[i] != 0) continue;
      bool reachable = false;
      for (int k = 0; k < 4 && !reachable; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (!free(nx, ny)) continue;
        // The free neighbour needs a further free neighbour: ahead, left or right of it.
        reachable = free(nx + kDx[k], ny + kDy[k]) || free(nx + kDy[k], ny + kDx[k]) ||
                    free(nx - kDy[k], ny - kDx[k]);
      }
      if (!reachable || costmap.isLethal(i)) continue;
      if (robot_m != nullptr && !region[i - 1] && !region[i + 1] && !region[i - w] && !region[i + w]) continue;
      bool near_obstacle = false;
      for (int dy = -r; dy <= r && !near_obstacle; ++dy) {
        const int yy = y + dy;
        if (yy < 0 || yy >= h) continue;
        const int span = r - std::abs(dy);
        for (int dx = -span; dx <= span; ++dx) {
          const int xx = x + dx;
          if (xx < 0 || xx >= w) continue;
          if (grid.isOccupied(static_cast<std::size_t>(yy) * w + xx)) {
            near_obstacle = true;
            break;
          }
        }
      }
      if (!near_obstacle) out.push_back({x, y});
    }
  }
  return out;
}

std::vector<std::uint8_t> robotFreeRegion(const OccupancyGrid& grid, const Costmap& costmap, const Vec2& from_m) {
  const GridGeometry& g = grid.geometry();
  std::vector<std::uint8_t> region(g.cellCount(), 0);
  auto open = [&](std::size_t i) { return grid.isFree(i) && !costmap.isLethal(i); };
  std::optional<Cell> start;
  const Cell c = g.cellOf(from_m);
  if (g.contains(c) && open(g.index(c))) {
    start = c;
  } else {
    const int r = static_cast<int>(std::ceil(1.0 / g.resolution_m()));
    long best = std::numeric_limits<long>::max();
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        const Cell q{c.x + dx, c.y + dy};
        const long d2 = static_cast<long>(dx) * dx + static_cast<long>(dy) * dy;
        if (d2 < best && g.contains(q) && open(g.index(q))) {
          best = d2;
          start = q;
        }
      }
    }
  }
  if (!start) return region;
  std::vector<std::size_t> stack{g.index(*start)};
  region[stack.back()] = 1;
  const int w = g.width();
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    const Cell q = g.cellAt(i);
    const std::size_t n[4] = {i + 1, i - 1, i + w, i - w};
    const bool ok[4] = {q.x + 1 < w, q.x > 0, q.y + 1 < g.height(), q.y > 0};
    for (int k = 0; k < 4; ++k) {
      if (ok[k] && !region[n[k]] && open(n[k])) {
        region[n[k]] = 1;
        stack.push_back(n[k]);
      }
    }
  }
  return region;
}

void markDisc(std::vector<std::uint8_t>& mask, const GridGeometry& geometry, const Vec2& p_m,
              double radius_m) {
  if (mask.size() != geometry.cellCount()) mask.assign(geometry.cellCount(), 0);
  const Cell c = geometry.cellOf(p_m);
  const int r = static_cast<int>(std::ceil(radius_m / geometry.resolution_m()));
  const double r2 = radius_m * radius_m;
  for (int y = std::max(0, c.y - r); y <= std::min(geometry.height() - 1, c.y + r); ++y) {
    for (int x = std::max(0, c.x - r); x <= std::min(geometry.width() - 1, c.x + r); ++x) {
      const Cell q{x, y};
      if ((geometry.centerOf(q) - p_m).squaredNorm() <= r2) mask[geometry.index(q)] = 1;
    }
  }
}

std::optional<Vec2> nearestGoalCell(const OccupancyGrid& grid, const Costmap& costmap, const Vec2& p_m,
                                    double max_radius_m, bool free_only) {
  const GridGeometry& g = grid.geometry();
  const Cell c = g.cellOf(p_m);
  const int r = static_cast<int>(std::ceil(max_radius_m / g.resolution_m()));
  std::optional<Cell> best;
  long best_d2 = std::numeric_limits<long>::max();
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const long d2 = static_cast<long>(dx) * dx + static_cast<long>(dy) * dy;
      if (d2 > static_cast<long>(r) * r || d2 >= best_d2) continue;
      const Cell q{c.x + dx, c.y + dy};
      if (!g.contains(q)) continue;
      const std::size_t i = g.index(q);
      if (costmap.isLethal(i) || grid.isOccupied(i)) continue;
      if (free_only && !grid.isFree(i)) continue;
      best_d2 = d2;
      best = q;
    }
  }
  if (!best) return std::nullopt;
  return g.centerOf(*best);
}

}  // namespace roomscout
