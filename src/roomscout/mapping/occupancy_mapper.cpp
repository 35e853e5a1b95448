#include "roomscout/mapping/occupancy_mapper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace roomscout {
namespace {

/// Visits the cells a segment crosses, from its start cell up to (excluding) its end cell,
/// with Amanatides-Woo traversal; calls miss(index) on each cell inside the grid. Returns
/// false when the segment leaves the grid.
template <typename Miss>
void traverse(const GridGeometry& g, const Vec2& from_m, const Vec2& to_m, Miss&& miss) {
  const double res = g.resolution_m();
  const Vec2 p0 = (from_m - g.origin_m()) / res;
  const Vec2 p1 = (to_m - g.origin_m()) / res;
  int x = static_cast<int>(std::floor(p0.x()));
  int y = static_cast<int>(std::floor(p0.y()));
  const int end_x = static_cast<int>(std::floor(p1.x()));
  const int end_y = static_cast<int>(std::floor(p1.y()));
  const Vec2 d = p1 - p0;
  const int step_x = d.x() > 0 ? 1 : -1;
  const int step_y = d.y() > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const double t_delta_x = d.x() != 0 ? std::abs(1.0 / d.x()) : inf;
  const double t_delta_y = d.y() != 0 ? std::abs(1.0 / d.y()) : inf;
  double t_max_x = d.x() != 0 ? ((step_x > 0 ? (x + 1 - p0.x()) : (p0.x() - x)) * t_delta_x) : inf;
  double t_max_y = d.y() != 0 ? ((step_y > 0 ? (y + 1 - p0.y()) : (p0.y() - y)) * t_delta_y) : inf;
  const int max_steps = std::abs(end_x - x) + std::abs(end_y - y) + 2;
  for (int i = 0; i < max_steps; ++i) {
    if (x == end_x && y == end_y) return;
    if (x < 0 || y < 0 || x >= g.width() || y >= g.height()) return;
    miss(static_cast<std::size_t>(y) * g.width() + x);
    if (t_max_x < t_max_y) {
      t_max_x += t_delta_x;
      x += step_x;
    } else {
      t_max_y += t_delta_y;
      y += step_y;
    }
  }
}

/// Whether a beam running in direction `dir` (unit) through the occupied cell `c` runs along
/// the wall it belongs to: within 10 degrees of the line from `c` to an occupied 8-neighbour.
bool grazesWall(const OccupancyGrid& grid, Cell c, const Vec2& dir) {
  const GridGeometry& g = grid.geometry();
  auto occupied = [&](int dx, int dy) {
    const Cell n{c.x + dx, c.y + dy};
    return g.contains(n) && grid.isOccupied(g.index(n));
  };
  constexpr double kSinGrazing = 0.17364817766693033;  // sin(10 degrees)
  constexpr double kInvSqrt2 = 0.70710678118654752;
  const double x = dir.x();
  const double y = dir.y();
  return (std::abs(y) < kSinGrazing && (occupied(-1, 0) || occupied(1, 0))) ||
         (std::abs(x) < kSinGrazing && (occupied(0, -1) || occupied(0, 1))) ||
         (std::abs(x - y) * kInvSqrt2 < kSinGrazing && (occupied(-1, -1) || occupied(1, 1))) ||
         (std::abs(x + y) * kInvSqrt2 < kSinGrazing && (occupied(-1, 1) || occupied(1, -1)));
}

}  // namespace

CellRect OccupancyMapper::integrate(const LaserScan& scan, const Pose2& T_map_sensor) {
  const GridGeometry& g = grid_.geometry();
  const Vec2 origin = T_map_sensor.position();
  CellRect changed;
  if (scan.ranges_m.empty()) return changed;
  changed.expandToInclude(g.cellOf(origin));
  if (scan_ >= (std::numeric_limits<std::uint32_t>::max() - 2) / 2) {
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    scan_ = 0;
  }
  ++scan_;
  const std::uint32_t hit_mark = 2 * scan_ + 1;
  const std::uint32_t miss_mark = 2 * scan_ + 2;

  // Pass 1: end points. Pass 2: the cells crossed, skipping this scan's hit cells.
  struct Beam {
    Vec2 end;
    bool hit;
  };
  std::vector<Beam> beams;
  beams.reserve(scan.ranges_m.size());
  hits_.clear();
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    // REP 117: +inf is "nothing within range" and clears the beam up to range_max_m; NaN,
    // -inf and finite readings outside [range_min_m, range_max_m] carry no information.
    const bool hit = std::isfinite(r) && r >= scan.range_min_m && r <= scan.range_max_m;
    if (!hit && !(std::isinf(r) && r > 0.0)) continue;
    const double length = hit ? r : scan.range_max_m;
    const double angle = T_map_sensor.yaw_rad + scan.angle_min_rad + i * scan.angle_increment_rad;
    const Vec2 dir(std::cos(angle), std::sin(angle));
    // A tiny step past the measured surface puts the end point inside the obstacle's cell.
    const Vec2 end = origin + dir * (hit ? length + 1e-4 : length);
    beams.push_back({end, hit});
    const Cell end_cell = g.cellOf(end);
    changed.expandToInclude({std::clamp(end_cell.x, 0, std::max(0, g.width() - 1)),
                             std::clamp(end_cell.y, 0, std::max(0, g.height() - 1))});
    if (hit && g.contains(end_cell)) {
      const std::size_t index = g.index(end_cell);
      if (stamp_[index] != hit_mark) {
        stamp_[index] = hit_mark;
        hits_.push_back(index);
      }
    }
  }
  Vec2 beam_dir = Vec2::Zero();
  auto miss = [&](std::size_t index) {
    if (stamp_[index] == hit_mark || stamp_[index] == miss_mark) return;
    if (grid_.isOccupied(index) &&
        grazesWall(grid_,
                   {static_cast<int>(index % g.width()), static_cast<int>(index / g.width())},
                   beam_dir))
      return;
    stamp_[index] = miss_mark;
    grid_.addMiss(index);
  };
  for (const Beam& beam : beams) {
    const Vec2 ray = beam.end - origin;
    const double length = ray.norm();
    beam_dir = length > 0.0 ? Vec2(ray / length) : Vec2::Zero();
    traverse(g, origin, beam.end, miss);
    if (!beam.hit) {
      const Cell end_cell = g.cellOf(beam.end);
      if (g.contains(end_cell)) miss(g.index(end_cell));
    }
  }
  for (std::size_t index : hits_) grid_.addHit(index);
  return changed;
}

}  // namespace roomscout
