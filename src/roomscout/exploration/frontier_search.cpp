#include "roomscout/exploration/detail/frontier_search.hpp"

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
  const auto start =
      nearestFreeCell(grid, start_cell, static_cast<int>(std::ceil(1.0 / g.resolution_m())));
  if (!start) return frontiers;

  const int w = g.width();
  const int h = g.height();
  // One byte per cell of the grid framed by one cell of neither free nor unknown space, so that
  // neighbours need no bounds checks: bit 0 free, bit 1 unknown, bit 2 visited, bit 3 frontier.
  constexpr std::uint8_t kFree = 1, kUnknown = 2, kVisited = 4, kFrontier = 8;
  const std::ptrdiff_t pw = w + 2;
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(pw) * (h + 2), 0);
  for (int y = 0; y < h; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    std::uint8_t* out = flags.data() + (y + 1) * pw + 1;
    for (int x = 0; x < w; ++x) {
      const CellState s = grid.state(row + x);
      out[x] = s == CellState::kFree ? kFree : (s == CellState::kUnknown ? kUnknown : 0);
    }
  }
  auto cellOf = [pw](std::ptrdiff_t j) {
    return Cell{static_cast<int>(j % pw) - 1, static_cast<int>(j / pw) - 1};
  };
  auto isNewFrontierCell = [&](std::ptrdiff_t j) {
    if ((flags[j] & (kUnknown | kFrontier)) != kUnknown) return false;
    return ((flags[j - 1] | flags[j + 1] | flags[j - pw] | flags[j + pw]) & kFree) != 0;
  };

  std::vector<std::ptrdiff_t> queue;
  const std::ptrdiff_t around[8] = {-pw - 1, -pw, -pw + 1, -1, 1, pw - 1, pw, pw + 1};
  auto buildFrontier = [&](std::ptrdiff_t j0) {
    Frontier f;
    queue.assign(1, j0);
    flags[j0] |= kFrontier;
    Vec2 sum = Vec2::Zero();
    f.min_distance_m = std::numeric_limits<double>::infinity();
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const std::ptrdiff_t j = queue[head];
      const Cell c = cellOf(j);
      f.cells.push_back(c);
      const Vec2 p = g.centerOf(c);
      sum += p;
      const double d = (p - from_m).norm();
      if (d < f.min_distance_m) {
        f.min_distance_m = d;
        f.nearest_m = p;
      }
      for (const std::ptrdiff_t o : around) {
        if (isNewFrontierCell(j + o)) {
          flags[j + o] |= kFrontier;
          queue.push_back(j + o);
        }
      }
    }
    f.centroid_m = sum / static_cast<double>(f.cells.size());
    return f;
  };

  const Cell sc = g.cellAt(*start);
  const std::ptrdiff_t s0 = (sc.y + 1) * pw + sc.x + 1;
  std::vector<std::ptrdiff_t> bfs{s0};
  flags[s0] |= kVisited;
  const std::ptrdiff_t nbr[4] = {-1, 1, -pw, pw};
  for (std::size_t head = 0; head < bfs.size(); ++head) {
    const std::ptrdiff_t i = bfs[head];
    for (const std::ptrdiff_t o : nbr) {
      const std::ptrdiff_t j = i + o;
      if (flags[j] & kFree) {
        if (!(flags[j] & kVisited)) {
          flags[j] |= kVisited;
          bfs.push_back(j);
        }
      } else if (isNewFrontierCell(j)) {
        Frontier f = buildFrontier(j);
        if (f.size() >= min_cells) frontiers.push_back(std::move(f));
      }
    }
  }
  return frontiers;
}

}  // namespace roomscout
