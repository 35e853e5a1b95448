#include "roomscout/slam/detail/submap.hpp"

#include <algorithm>
#include <cmath>

namespace roomscout::slam::detail {

namespace {
constexpr double kGrowthPadding_m = 2.0;  ///< added around a scan that does not fit
}

void WallPoints::add(Cell c, const Vec2& p, const Vec2& beam) {
  if (!geometry_.contains(c)) return;
  Sum& s = cells_[geometry_.index(c)];
  s.x += p.x();
  s.y += p.y();
  s.n += 1.0;
  s.bx += beam.x();
  s.by += beam.y();
}

WallPoints WallPoints::reframed(const GridGeometry& geometry) const {
  WallPoints out(geometry);
  const double res = geometry.resolution_m();
  const int dx =
      static_cast<int>(std::lround((geometry_.origin_m().x() - geometry.origin_m().x()) / res));
  const int dy =
      static_cast<int>(std::lround((geometry_.origin_m().y() - geometry.origin_m().y()) / res));
  for (int y = 0; y < geometry_.height(); ++y) {
    for (int x = 0; x < geometry_.width(); ++x) {
      const Cell to{x + dx, y + dy};
      if (geometry.contains(to))
        out.cells_[geometry.index(to)] = cells_[geometry_.index(Cell{x, y})];
    }
  }
  return out;
}

Submap::Submap(const Pose2& pose, const OccupancyGridOptions& options) : global_pose(pose) {
  // The submap frame's origin lies on a cell corner, so a submap that has not moved renders
  // onto a map grid whose lattice passes through it without resampling.
  const double res = options.resolution_m;
  grid_ = OccupancyGrid(GridGeometry(Vec2(-res, -res) * 20.0, res, 40, 40), options);
  walls_ = WallPoints(grid_.geometry());
  mapper_ = std::make_unique<OccupancyMapper>(grid_);
}

void Submap::growToInclude(const Vec2& min_m, const Vec2& max_m) {
  const GridGeometry& g = grid_.geometry();
  const double res = g.resolution_m();
  const Vec2 lo = g.origin_m();
  const Vec2 hi = lo + Vec2(g.width(), g.height()) * res;
  if (min_m.x() >= lo.x() && min_m.y() >= lo.y() && max_m.x() < hi.x() && max_m.y() < hi.y()) {
    return;
  }
  // Grow on the same lattice, with padding so that a robot driving on grows it rarely.
  auto floorCells = [&](double v) { return std::floor(v / res); };
  const double x0 = std::min(lo.x() / res, floorCells(min_m.x() - kGrowthPadding_m));
  const double y0 = std::min(lo.y() / res, floorCells(min_m.y() - kGrowthPadding_m));
  const double x1 = std::max(hi.x() / res, std::ceil((max_m.x() + kGrowthPadding_m) / res));
  const double y1 = std::max(hi.y() / res, std::ceil((max_m.y() + kGrowthPadding_m) / res));
  const GridGeometry grown(Vec2(std::round(x0) * res, std::round(y0) * res), res,
                           static_cast<int>(std::lround(x1 - x0)),
                           static_cast<int>(std::lround(y1 - y0)));
  grid_ = grid_.reframed(grown);
  walls_ = walls_.reframed(grown);
  mapper_ = std::make_unique<OccupancyMapper>(grid_);
  ++geometry_version_;
}

CellRect Submap::insert(const LaserScan& scan, const Pose2& T_submap_sensor) {
  // Every beam's far end, with or without a return, must lie inside the grid.
  const double reach = scan.range_max_m + grid_.geometry().resolution_m();
  const Vec2 c = T_submap_sensor.position();
  growToInclude(c - Vec2(reach, reach), c + Vec2(reach, reach));
  ++scans_;
  // Each return in the cell the mapper marks as hit (a tiny step past the surface).
  const GridGeometry& g = grid_.geometry();
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    if (!(std::isfinite(r) && r >= scan.range_min_m && r <= scan.range_max_m)) continue;
    const double a = T_submap_sensor.yaw_rad + scan.angle_min_rad +
                     static_cast<double>(i) * scan.angle_increment_rad;
    const Vec2 dir(std::cos(a), std::sin(a));
    const Vec2 p = c + dir * r;
    walls_.add(g.cellOf(Vec2(p + dir * 1e-4)), p, dir);
  }
  return mapper_->integrate(scan, T_submap_sensor);
}

}  // namespace roomscout::slam::detail
