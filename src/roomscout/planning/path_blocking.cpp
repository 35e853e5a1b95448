#include "roomscout/planning/path_blocking.hpp"

#include <cmath>

namespace roomscout {

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

bool pathBlockedAhead(const OccupancyGrid& grid, const std::vector<Vec2>& waypoints_m,
                      std::size_t from, const Vec2& robot_m, double horizon_m,
                      const std::vector<Cell>& disc) {
  const GridGeometry& g = grid.geometry();
  for (std::size_t i = from; i < waypoints_m.size(); ++i) {
    if ((waypoints_m[i] - robot_m).squaredNorm() > horizon_m * horizon_m) continue;
    const Cell c = g.cellOf(waypoints_m[i]);
    for (const Cell& o : disc) {
      const Cell q{c.x + o.x, c.y + o.y};
      if (g.contains(q) && grid.isOccupied(g.index(q))) return true;
    }
  }
  return false;
}

}  // namespace roomscout
