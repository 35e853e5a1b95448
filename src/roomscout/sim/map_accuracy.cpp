#include "roomscout/sim/map_accuracy.hpp"

#include <cstdint>
#include <vector>

#include "roomscout/core/errors.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {
namespace {

double share(std::size_t part, std::size_t whole, double if_none) {
  return whole == 0 ? if_none : static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

MapAccuracy mapAccuracy(const OccupancyGrid& map, const ExplorationTruth& truth,
                        const WorldModel& world) {
  const GridGeometry& g = truth.geometry();
  if (map.geometry().width() != g.width() || map.geometry().height() != g.height() ||
      (map.geometry().origin_m() - g.origin_m()).norm() > 1e-9 ||
      map.geometry().resolution_m() != g.resolution_m()) {
    throw InvalidArgument("mapAccuracy: the map must lie on the truth's grid");
  }
  const GridGeometry& w = world.geometry();
  const int width = g.width(), height = g.height();
  const double res = g.resolution_m();

  // Per map cell: a true obstacle (solid under its centre), and near one (any solid raster
  // cell in its 3 x 3 neighbourhood's square).
  std::vector<std::uint8_t> obstacle(g.cellCount(), 0);
  std::vector<std::uint8_t> reachable(g.cellCount(), 0);
  for (std::uint32_t i : truth.reachableCells()) reachable[i] = 1;
  for (std::size_t i = 0; i < g.cellCount(); ++i) {
    const Cell c = w.cellOf(g.centerOf(g.cellAt(i)));
    obstacle[i] = world.blocksLaser(c) ? 1 : 0;
  }
  auto near_true_obstacle = [&](std::size_t i) {
    const Vec2 c = g.centerOf(g.cellAt(i));
    const double half = 1.5 * res;
    const Cell lo = w.cellOf(c - Vec2(half, half));
    const Cell hi = w.cellOf(c + Vec2(half, half) - Vec2(1e-9, 1e-9));
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x)
        if (world.blocksLaser(Cell{x, y})) return true;
    return false;
  };
  // Whether any cell of i's 3 x 3 neighbourhood satisfies `pred`.
  auto any_around = [&](std::size_t i, auto&& pred) {
    const Cell c = g.cellAt(i);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = c.x + dx, y = c.y + dy;
        if (x < 0 || y < 0 || x >= width || y >= height) continue;
        if (pred(static_cast<std::size_t>(y) * width + x)) return true;
      }
    }
    return false;
  };

  std::size_t occupied = 0, occupied_near = 0, free = 0, free_obstacle = 0;
  std::size_t walls = 0, walls_found = 0, reachable_occupied = 0, reachable_free = 0;
  for (std::size_t i = 0; i < g.cellCount(); ++i) {
    const CellState s = map.state(i);
    if (s == CellState::kOccupied) {
      ++occupied;
      occupied_near += near_true_obstacle(i) ? 1 : 0;
      reachable_occupied += reachable[i];
    } else if (s == CellState::kFree) {
      ++free;
      free_obstacle += obstacle[i];
      reachable_free += reachable[i];
    }
    if (obstacle[i] && any_around(i, [&](std::size_t j) { return reachable[j] != 0; })) {
      ++walls;
      walls_found += any_around(i, [&](std::size_t j) { return map.isOccupied(j); }) ? 1 : 0;
    }
  }
  const std::size_t n = truth.reachableCells().size();
  MapAccuracy a;
  a.false_occupied = share(reachable_occupied, n, 0.0);
  a.occupied_precision = share(occupied_near, occupied, 1.0);
  a.occupied_recall = share(walls_found, walls, 1.0);
  a.false_free = share(free_obstacle, free, 0.0);
  a.free_coverage = share(reachable_free, n, 0.0);
  return a;
}

}  // namespace roomscout::sim
