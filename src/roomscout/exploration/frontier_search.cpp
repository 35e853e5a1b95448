#include "roomscout/exploration/frontier_search.hpp"

#include <cmath>
#include <deque>
#include <limits>
#include <optional>

namespace roomscout {
namespace {

std::optional<std::size_t> nearestFreeCell(const OccupancyGrid& grid, Cell start, int radius) {
  const GridGeometry& g = grid.geometry();
  std::optional<std::size_t> best;
  int best_d2 = std::numeric_limits<int>::max();
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const Cell c{start.x + dx, start.y + dy};
      const int d2 = dx * dx + dy * dy;
      if (d2 > radius * radius || d2 >= best_d2 || !g.contains(c)) continue;
      if (grid.isFree(g.index(c))) {
        best = g.index(c);
        best_d2 = d2;
      }
    }
  }
  return best;
}

}  // namespace

std::vector<Frontier> searchFrontiers(const OccupancyGrid& grid, const Vec2& from_m,
                                      std::size_t min_cells) {
  const GridGeometry& g = grid.geometry();
  std::vector<Frontier> frontiers;
  const Cell start_cell = g.cellOf(from_m);
  if (!g.contains(start_cell)) return frontiers;
  const auto start = nearestFreeCell(grid, start_cell, static_cast<int>(std::ceil(1.0 / g.resolution_m())));
  if (!start) return frontiers;

  const int w = g.width();
  const int h = g.height();
  std::vector<std::uint8_t> visited(g.cellCount(), 0);
  std::vector<std::uint8_t> frontier_flag(g.cellCount(), 0);
  auto isNewFrontierCell = [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * w + x;
    if (frontier_flag[i] || !grid.isUnknown(i)) return false;
    return (x > 0 && grid.isFree(i - 1)) || (x + 1 < w && grid.isFree(i + 1)) ||
           (y > 0 && grid.isFree(i - w)) || (y + 1 < h && grid.isFree(i + w));
  };

  auto buildFrontier = [&](int x0, int y0) {
    Frontier f;
    std::deque<Cell> queue{{x0, y0}};
    frontier_flag[static_cast<std::size_t>(y0) * w + x0] = 1;
    Vec2 sum = Vec2::Zero();
    f.min_distance_m = std::numeric_limits<double>::infinity();
    while (!queue.empty()) {
      const Cell c = queue.front();
      queue.pop_front();
      f.cells.push_back(c);
      const Vec2 p = g.centerOf(c);
      sum += p;
      const double d = (p - from_m).norm();
      if (d < f.min_distance_m) {
        f.min_distance_m = d;
        f.nearest_m = p;
      }
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = c.x + dx, ny = c.y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          if (isNewFrontierCell(nx, ny)) {
            frontier_flag[static_cast<std::size_t>(ny) * w + nx] = 1;
            queue.push_back({nx, ny});
          }
        }
      }
    }
    f.centroid_m = sum / static_cast<double>(f.cells.size());
    return f;
  };

  std::deque<std::size_t> bfs{*start};
  visited[*start] = 1;
  while (!bfs.empty()) {
    const std::size_t i = bfs.front();
    bfs.pop_front();
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    const int nbr[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
    for (const auto& n : nbr) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
      const std::size_t j = static_cast<std::size_t>(n[1]) * w + n[0];
      if (grid.isFree(j)) {
        if (!visited[j]) {
          visited[j] = 1;
          bfs.push_back(j);
        }
      } else if (isNewFrontierCell(n[0], n[1])) {
        Frontier f = buildFrontier(n[0], n[1]);
        if (f.size() >= min_cells) frontiers.push_back(std::move(f));
      }
    }
  }
  return frontiers;
}

}  // namespace roomscout
