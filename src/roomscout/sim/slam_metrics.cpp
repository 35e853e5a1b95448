#include "roomscout/sim/slam_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {

TrajectoryError trajectoryError(const std::vector<TrajectorySample>& trajectory) {
  TrajectoryError e;
  e.samples = trajectory.size();
  if (trajectory.empty()) return e;
  double sum_sq = 0.0, sum_sq_heading = 0.0;
  for (const TrajectorySample& s : trajectory) {
    const double d = (s.estimate.position() - s.pose.position()).norm();
    const double h = wrapAngle(s.estimate.yaw_rad - s.pose.yaw_rad);
    sum_sq += d * d;
    sum_sq_heading += h * h;
    e.max_m = std::max(e.max_m, d);
  }
  const double n = static_cast<double>(trajectory.size());
  e.rmse_m = std::sqrt(sum_sq / n);
  e.heading_rmse_rad = std::sqrt(sum_sq_heading / n);
  return e;
}

double mapPrecision(const OccupancyGrid& map, const WorldModel& world) {
  const GridGeometry& g = map.geometry();
  const GridGeometry& w = world.geometry();
  const auto& solid = world.laserSolid();
  const double half = 1.5 * g.resolution_m();
  std::size_t occupied = 0, near_obstacle = 0;
  for (std::size_t i = 0; i < g.cellCount(); ++i) {
    if (!map.isOccupied(i)) continue;
    ++occupied;
    const Vec2 c = g.centerOf(g.cellAt(i));
    // World raster cells overlapping the square of the cell's 3 x 3 neighbourhood.
    const Cell lo = w.cellOf(c - Vec2(half, half));
    const Cell hi = w.cellOf(c + Vec2(half, half) - Vec2(1e-9, 1e-9));
    bool hit = false;
    for (int y = lo.y; y <= hi.y && !hit; ++y) {
      for (int x = lo.x; x <= hi.x && !hit; ++x) {
        // Outside the raster counts as solid, as for the laser (WorldModel::blocksLaser).
        hit = !w.contains(Cell{x, y}) || solid[w.index(Cell{x, y})] != 0;
      }
    }
    near_obstacle += hit;
  }
  return occupied == 0 ? 1.0 : static_cast<double>(near_obstacle) / static_cast<double>(occupied);
}

}  // namespace roomscout::sim
