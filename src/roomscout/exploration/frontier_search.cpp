#include "roomscout/exploration/frontier_search.hpp"

#include <cmath>
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
  // One byte per cell: bit 0 free, bit 1 unknown, bit 2 visited, bit 3 frontier.
  constexpr std::uint8_t kFree = 1, kUnknown = 2, kVisited = 4, kFrontier = 8;
  std::vector<std::uint8_t> flags(g.cellCount());
  for (std::size_t i = 0; i < flags.size(); ++i) {
    const CellState s = grid.state(i);
    flags[i] = s == CellState::kFree ? kFree : (s == CellState::kUnknown ? kUnknown : 0);
  }
  auto isNewFrontierCell = [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * w + x;
    if ((flags[i] & (kUnknown | kFrontier)) != kUnknown) return false;
    return (x > 0 && (flags[i - 1] & kFree)) || (x + 1 < w && (flags[i + 1] & kFree)) ||
           (y > 0 && (flags[i - w] & kFree)) || (y + 1 < h && (flags[i + w] & kFree));
  };

  std::vector<Cell> queue;
  auto buildFrontier = [&](int x0, int y0) {
    Frontier f;
    queue.assign(1, Cell{x0, y0});
    flags[static_cast<std::size_t>(y0) * w + x0] |= kFrontier;
    Vec2 sum = Vec2::Zero();
    f.min_distance_m = std::numeric_limits<double>::infinity();
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const Cell c = queue[head];
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
            flags[static_cast<std::size_t>(ny) * w + nx] |= kFrontier;
            queue.push_back({nx, ny});
          }
        }
      }
    }
    f.centroid_m = sum / static_cast<double>(f.cells.size());
    return f;
  };

  std::vector<std::size_t> bfs{*start};
  flags[*start] |= kVisited;
  for (std::size_t head = 0; head < bfs.size(); ++head) {
    const std::size_t i = bfs[head];
    const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
    const int nbr[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
    for (const auto& n : nbr) {
      if (n[0] < 0 || n[1] < 0 || n[0] >= w || n[1] >= h) continue;
      const std::size_t j = static_cast<std::size_t>(n[1]) * w + n[0];
      if (flags[j] & kFree) {
        if (!(flags[j] & kVisited)) {
          flags[j] |= kVisited;
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
