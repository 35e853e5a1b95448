#include "roomscout/experiment/oracle_tour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <queue>
#include <utility>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/grid_ray.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/planning/costmap.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/exploration_truth.hpp"

namespace roomscout::experiment {

using sim::EpisodeConfig;
using sim::ExplorationTruth;
using sim::WorldModel;

void OracleTourOptions::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(map_resolution_m)) throw OptionError("oracle.map_resolution_m must be > 0");
  if (!(std::isfinite(lethal_radius_m) && lethal_radius_m >= 0.0)) {
    throw OptionError("oracle.lethal_radius_m must be >= 0");
  }
  if (!positive(sensor_range_m)) throw OptionError("oracle.sensor_range_m must be > 0");
  if (rays_per_viewpoint < 4 || rays_per_viewpoint > 100000) {
    throw OptionError("oracle.rays_per_viewpoint must be in [4, 100000]");
  }
  if (!(positive(viewpoint_spacing_m) && viewpoint_spacing_m >= map_resolution_m)) {
    throw OptionError("oracle.viewpoint_spacing_m must be >= map_resolution_m");
  }
  const double ratio = visibility_cell_m / map_resolution_m;
  if (!(positive(visibility_cell_m) && ratio >= 1.0 - 1e-9 &&
        std::abs(ratio - std::round(ratio)) < 1e-6)) {
    throw OptionError("oracle.visibility_cell_m must be a whole multiple of map_resolution_m");
  }
  if (!(target_coverage > 0.0 && target_coverage <= 1.0)) {
    throw OptionError("oracle.target_coverage must be in (0, 1]");
  }
}

std::vector<ParameterRef> OracleTourOptions::parameters() {
  return {
      {"map_resolution_m", &map_resolution_m,
       "grid of the exploration truth and the paths [m] (the mapper's mapping.resolution_m)"},
      {"lethal_radius_m", &lethal_radius_m,
       "clearance the robot centre keeps from solid cells [m] (the costmap's robot radius + "
       "inflation margin)"},
      {"sensor_range_m", &sensor_range_m,
       "a viewpoint sees the free cells in line of sight within this range [m] "
       "(laser.range_max_m)"},
      {"rays_per_viewpoint", &rays_per_viewpoint,
       "rays cast from each candidate viewpoint, evenly spaced (at 3.5 m, 360 rays are 6 cm apart, "
       "finer than the cells)"},
      {"viewpoint_spacing_m", &viewpoint_spacing_m,
       "one candidate viewpoint per square of this side: its traversable cell nearest the square's "
       "centre [m]"},
      {"visibility_cell_m", &visibility_cell_m,
       "coverage is counted on cells of this side (a multiple of map_resolution_m), each weighted "
       "by the reachable map cells in it [m]"},
      {"target_coverage", &target_coverage,
       "the greedy set cover stops at this fraction of the reachable free space"},
      {"smooth_legs", &smooth_legs,
       "measure each leg on its grid path shortened by line-of-sight string pulling (true), or on "
       "the 8-connected grid path itself (false; up to 8 % longer than the straight segment)"},
  };
}

OracleTourOptions oracleTourOptionsFor(const EpisodeConfig& config) {
  const ExplorerOptions explorer = sim::explorerOptionsFor(config, 0.0);
  OracleTourOptions options;
  options.map_resolution_m = config.mapping.resolution_m;
  options.lethal_radius_m = explorer.costmap.lethalRadius_m();
  options.sensor_range_m = explorer.goals.sensor_range_m;
  return options;
}

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kSqrt2 = 1.41421356f;

/// 8-neighbourhood offsets; the first four are the straight moves.
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

/// The map-resolution grids the tour is planned on.
struct PlanningGrids {
  GridGeometry geometry;
  std::vector<std::uint8_t> nav;     ///< 1: the robot centre may be here and it is connected
                                     ///< to the start (the costmap's non-lethal cells)
  std::vector<std::uint8_t> blocks;  ///< 1: a laser-solid raster cell lies in the cell
  Cell start;
};

/// Laser-blocking map cells: any overlapped raster cell blocks the laser plane.
std::vector<std::uint8_t> laserBlocking(const WorldModel& world, const GridGeometry& g) {
  const GridGeometry& raster = world.geometry();
  const double ratio = g.resolution_m() / raster.resolution_m();
  const auto& laser = world.laserSolid();
  std::vector<std::uint8_t> blocks(g.cellCount(), 0);
  for (int y = 0; y < g.height(); ++y) {
    const int ry0 = static_cast<int>(std::floor(y * ratio + 1e-9));
    const int ry1 = std::min(raster.height(), static_cast<int>(std::ceil((y + 1) * ratio - 1e-9)));
    for (int x = 0; x < g.width(); ++x) {
      const int rx0 = static_cast<int>(std::floor(x * ratio + 1e-9));
      const int rx1 = std::min(raster.width(), static_cast<int>(std::ceil((x + 1) * ratio - 1e-9)));
      bool solid = false;
      for (int ry = ry0; !solid && ry < ry1; ++ry) {
        for (int rx = rx0; rx < rx1; ++rx) {
          if (laser[raster.index({rx, ry})]) {
            solid = true;
            break;
          }
        }
      }
      blocks[g.index({x, y})] = solid ? 1 : 0;
    }
  }
  return blocks;
}

/// May the robot step from `c` in direction k (no corner cutting past a blocked cell)?
inline bool canStep(const std::vector<std::uint8_t>& nav, const GridGeometry& g, Cell c, int k) {
  const Cell n{c.x + kDx[k], c.y + kDy[k]};
  if (!g.contains(n) || !nav[g.index(n)]) return false;
  if (k < 4) return true;
  return nav[g.index({c.x + kDx[k], c.y})] && nav[g.index({c.x, c.y + kDy[k]})];
}

/// The costmap over the fully known ground truth, reduced to the start's 8-connected
/// component of non-lethal cells (the start moves to the nearest non-lethal cell if needed;
/// start.x < 0 when there is none), and the laser-blocking cells.
PlanningGrids planningGrids(const WorldModel& world, const ExplorationTruth& truth,
                            const OracleTourOptions& options) {
  PlanningGrids grids;
  grids.geometry = truth.geometry();
  grids.blocks = laserBlocking(world, grids.geometry);
  const GridGeometry& g = grids.geometry;
  OccupancyGrid known(g);
  const auto& truly_free = truth.trulyFree();
  for (std::size_t i = 0; i < g.cellCount(); ++i) {
    known.setState(i, truly_free[i] ? CellState::kFree : CellState::kOccupied);
  }
  CostmapOptions costmap_options;
  costmap_options.robot_radius_m = options.lethal_radius_m;
  costmap_options.inflation_margin_m = 0.0;
  costmap_options.cost_scaling_distance_m = options.lethal_radius_m + 0.2;
  Costmap costmap(costmap_options);
  costmap.update(known);

  grids.nav.assign(g.cellCount(), 0);
  const Vec2 start_m = world.start().position();
  Cell start = g.cellOf(start_m);
  if (!g.contains(start) || costmap.isLethal(start)) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < g.cellCount(); ++i) {
      if (costmap.isLethal(i)) continue;
      const double d = (g.centerOf(g.cellAt(i)) - start_m).squaredNorm();
      if (d < best) {
        best = d;
        start = g.cellAt(i);
      }
    }
    if (!std::isfinite(best)) {
      grids.start = {-1, -1};
      return grids;
    }
  }
  grids.start = start;
  std::vector<std::uint8_t> open(g.cellCount());
  for (std::size_t i = 0; i < g.cellCount(); ++i) open[i] = costmap.isLethal(i) ? 0 : 1;
  std::vector<std::uint32_t> queue{static_cast<std::uint32_t>(g.index(start))};
  grids.nav[g.index(start)] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Cell c = g.cellAt(queue[head]);
    for (int k = 0; k < 8; ++k) {
      if (!canStep(open, g, c, k)) continue;
      const std::size_t n = g.index({c.x + kDx[k], c.y + kDy[k]});
      if (grids.nav[n]) continue;
      grids.nav[n] = 1;
      queue.push_back(static_cast<std::uint32_t>(n));
    }
  }
  return grids;
}

/// Coverage bookkeeping on the coarse visibility grid.
class VisibilityGrid {
 public:
  VisibilityGrid(const GridGeometry& g, int factor, const std::vector<std::uint32_t>& reachable)
      : factor_(factor),
        width_((g.width() + factor - 1) / factor),
        height_((g.height() + factor - 1) / factor),
        weight_(static_cast<std::size_t>(width_) * height_, 0),
        stamp_(weight_.size(), 0) {
    for (std::uint32_t i : reachable) {
      const Cell c = g.cellAt(i);
      ++weight_[coarseIndex(c)];
    }
  }

  std::size_t coarseIndex(Cell fine) const {
    return static_cast<std::size_t>(fine.y / factor_) * width_ + fine.x / factor_;
  }
  std::size_t size() const { return weight_.size(); }
  std::uint32_t weight(std::size_t coarse) const { return weight_[coarse]; }

  /// Appends to `out` every coarse cell with reachable weight that a ray fan from `origin`
  /// (in map-cell units) reaches within `range` map cells before a laser-blocking cell (the
  /// blocking cell itself is seen: it holds the wall face).
  void castFan(const GridGeometry& g, const std::vector<std::uint8_t>& blocks, const Vec2& origin,
               double range, int rays, std::vector<std::uint32_t>& out) {
    if (++current_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      current_ = 1;
    }
    const int w = g.width(), h = g.height();
    const auto mark = [&](int x, int y) {
      const std::size_t c = coarseIndex({x, y});
      if (stamp_[c] == current_) return;
      stamp_[c] = current_;
      if (weight_[c]) out.push_back(static_cast<std::uint32_t>(c));
    };
    const int x0 = static_cast<int>(std::floor(origin.x()));
    const int y0 = static_cast<int>(std::floor(origin.y()));
    if (x0 < 0 || y0 < 0 || x0 >= w || y0 >= h) return;
    mark(x0, y0);
    if (blocks[g.index({x0, y0})]) return;
    if (directions_.size() != static_cast<std::size_t>(rays)) {
      directions_.clear();
      for (int r = 0; r < rays; ++r) {
        // Half a step off the axes, so that no ray runs exactly along a grid line.
        const double angle = (r + 0.5) * 2.0 * M_PI / rays;
        directions_.emplace_back(std::cos(angle), std::sin(angle));
      }
    }
    for (const Vec2& direction : directions_) {
      GridRay ray(origin, direction.x(), direction.y());
      while (true) {
        const double t_enter = ray.step();
        const int x = ray.x(), y = ray.y();
        if (t_enter > range || x < 0 || y < 0 || x >= w || y >= h) break;
        mark(x, y);
        if (blocks[static_cast<std::size_t>(y) * w + x]) break;
      }
    }
  }

 private:
  int factor_;
  int width_, height_;
  std::vector<std::uint32_t> weight_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 0;
  std::vector<Vec2> directions_;  ///< unit ray directions of the last fan
};

/// One candidate per square of `spacing` cells: its navigable cell nearest the square's centre.
std::vector<std::uint32_t> candidateCells(const PlanningGrids& grids, int spacing) {
  const GridGeometry& g = grids.geometry;
  std::vector<std::uint32_t> candidates;
  for (int by = 0; by < g.height(); by += spacing) {
    for (int bx = 0; bx < g.width(); bx += spacing) {
      const double cx = bx + 0.5 * spacing, cy = by + 0.5 * spacing;
      double best = std::numeric_limits<double>::infinity();
      std::size_t best_index = 0;
      for (int y = by; y < std::min(g.height(), by + spacing); ++y) {
        for (int x = bx; x < std::min(g.width(), bx + spacing); ++x) {
          const std::size_t i = g.index({x, y});
          if (!grids.nav[i]) continue;
          const double d = (x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy);
          if (d < best) {
            best = d;
            best_index = i;
          }
        }
      }
      if (std::isfinite(best)) candidates.push_back(static_cast<std::uint32_t>(best_index));
    }
  }
  return candidates;
}

/// Greedy weighted set cover with lazy gain updates (same picks as plain greedy: the largest
/// gain, ties to the lower candidate index). Returns the chosen candidate positions.
std::vector<std::size_t> greedyCover(const std::vector<std::uint32_t>& offsets,
                                     const std::vector<std::uint32_t>& cells,
                                     const VisibilityGrid& vis, std::vector<std::uint8_t>& covered,
                                     std::uint64_t& covered_weight, std::uint64_t target_weight) {
  const std::size_t n = offsets.size() - 1;
  const auto gain = [&](std::size_t c) {
    std::uint64_t sum = 0;
    for (std::uint32_t k = offsets[c]; k < offsets[c + 1]; ++k) {
      if (!covered[cells[k]]) sum += vis.weight(cells[k]);
    }
    return sum;
  };
  // Max-heap on (gain, -index).
  using Entry = std::pair<std::uint64_t, std::int64_t>;
  std::priority_queue<Entry> heap;
  for (std::size_t c = 0; c < n; ++c) {
    const std::uint64_t g = gain(c);
    if (g > 0) heap.push({g, -static_cast<std::int64_t>(c)});
  }
  std::vector<std::size_t> chosen;
  while (covered_weight < target_weight && !heap.empty()) {
    const auto [bound, neg_index] = heap.top();
    heap.pop();
    const std::size_t c = static_cast<std::size_t>(-neg_index);
    const std::uint64_t g = gain(c);
    if (g == 0) continue;
    if (!heap.empty() && Entry{g, neg_index} < heap.top()) {
      heap.push({g, neg_index});
      continue;
    }
    chosen.push_back(c);
    for (std::uint32_t k = offsets[c]; k < offsets[c + 1]; ++k) {
      if (!covered[cells[k]]) {
        covered[cells[k]] = 1;
        covered_weight += vis.weight(cells[k]);
      }
    }
  }
  return chosen;
}

/// Shortest paths over the navigable cells, 8-connected without corner cutting.
class GridSearch {
 public:
  explicit GridSearch(const PlanningGrids& grids)
      : grids_(grids),
        dist_(grids.geometry.cellCount(), kInf),
        parent_(grids.geometry.cellCount(), 0),
        stamp_(grids.geometry.cellCount(), 0),
        target_stamp_(grids.geometry.cellCount(), 0),
        moves_(grids.geometry.cellCount(), 0) {
    const GridGeometry& g = grids.geometry;
    for (int k = 0; k < 8; ++k)
      offset_[k] = static_cast<std::ptrdiff_t>(kDy[k]) * g.width() + kDx[k];
    for (std::size_t i = 0; i < g.cellCount(); ++i) {
      if (!grids.nav[i]) continue;
      for (int k = 0; k < 8; ++k) {
        if (canStep(grids.nav, g, g.cellAt(i), k)) moves_[i] |= static_cast<std::uint8_t>(1u << k);
      }
    }
  }

  /// Geodesic distances [cells] from `source` to every target (+inf when unreachable).
  /// Dial's bucket queue on integer step costs 5 (straight) and 7 (diagonal): a diagonal
  /// costs 1.4 instead of 1.414, within 1 %, and the search costs O(cells) instead of a
  /// heap's O(cells log cells). Stops when every target is settled.
  std::vector<float> distances(std::uint32_t source, const std::vector<std::uint32_t>& targets) {
    newStamp();
    std::size_t remaining = markTargets(targets);
    constexpr std::uint32_t kStep[2] = {5, 7};
    constexpr std::size_t kBuckets = 8;  // > largest step cost
    std::array<std::vector<std::uint32_t>, kBuckets> buckets;
    std::vector<std::uint32_t>& idist = integer_dist_;
    if (idist.size() != stamp_.size()) idist.assign(stamp_.size(), 0);
    stamp_[source] = current_;
    idist[source] = 0;
    buckets[0].push_back(source);
    std::size_t queued = 1;
    for (std::uint32_t d = 0; queued > 0 && remaining > 0; ++d) {
      std::vector<std::uint32_t>& bucket = buckets[d % kBuckets];
      // The bucket only receives entries of larger distances while it is processed.
      for (std::size_t b = 0; b < bucket.size(); ++b) {
        const std::uint32_t i = bucket[b];
        if (idist[i] != d) continue;  // stale: improved since it was queued
        if (target_stamp_[i] == current_) {
          target_stamp_[i] = 0;
          if (--remaining == 0) break;
        }
        const std::uint8_t moves = moves_[i];
        for (int k = 0; k < 8; ++k) {
          if (!(moves & (1u << k))) continue;
          const auto n = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(i) + offset_[k]);
          const std::uint32_t nd = d + kStep[k < 4 ? 0 : 1];
          if (stamp_[n] == current_ && idist[n] <= nd) continue;
          stamp_[n] = current_;
          idist[n] = nd;
          buckets[nd % kBuckets].push_back(n);
          ++queued;
        }
      }
      queued -= bucket.size();
      bucket.clear();
    }
    std::vector<float> out(targets.size());
    for (std::size_t k = 0; k < targets.size(); ++k) {
      out[k] = stamp_[targets[k]] == current_ ? static_cast<float>(idist[targets[k]]) / 5.0f : kInf;
    }
    return out;
  }

  /// Cells of a shortest path (exact step costs 1 and sqrt 2), source first; empty when the
  /// target is unreachable. A* with the octile heuristic.
  std::vector<std::uint32_t> path(std::uint32_t source, std::uint32_t target) {
    const GridGeometry& g = grids_.geometry;
    newStamp();
    const Cell goal = g.cellAt(target);
    const auto h = [&](std::uint32_t i) -> float {
      const Cell c = g.cellAt(i);
      const auto ax = static_cast<float>(std::abs(c.x - goal.x));
      const auto ay = static_cast<float>(std::abs(c.y - goal.y));
      return std::max(ax, ay) + (kSqrt2 - 1.0f) * std::min(ax, ay);
    };
    using Entry = std::pair<float, std::uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    stamp_[source] = current_;
    dist_[source] = 0.0f;
    parent_[source] = source;
    open.push({h(source), source});
    bool found = false;
    while (!open.empty()) {
      const auto [f, i] = open.top();
      open.pop();
      if (f > dist_[i] + h(i) + 1e-4f) continue;  // stale entry
      if (i == target) {
        found = true;
        break;
      }
      const std::uint8_t moves = moves_[i];
      for (int k = 0; k < 8; ++k) {
        if (!(moves & (1u << k))) continue;
        const auto n = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(i) + offset_[k]);
        const float d = dist_[i] + (k < 4 ? 1.0f : kSqrt2);
        if (stamp_[n] == current_ && dist_[n] <= d) continue;
        stamp_[n] = current_;
        dist_[n] = d;
        parent_[n] = i;
        open.push({d + h(n), n});
      }
    }
    std::vector<std::uint32_t> cells;
    if (!found) return cells;
    for (std::uint32_t c = target;; c = parent_[c]) {
      cells.push_back(c);
      if (c == source) break;
    }
    std::reverse(cells.begin(), cells.end());
    return cells;
  }

 private:
  void newStamp() {
    if (++current_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      std::fill(target_stamp_.begin(), target_stamp_.end(), 0);
      current_ = 1;
    }
  }

  std::size_t markTargets(const std::vector<std::uint32_t>& targets) {
    std::size_t count = 0;
    for (std::uint32_t t : targets) {
      if (target_stamp_[t] != current_) {
        target_stamp_[t] = current_;
        ++count;
      }
    }
    return count;
  }

  const PlanningGrids& grids_;
  std::vector<float> dist_;
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint32_t> target_stamp_;
  std::vector<std::uint32_t> integer_dist_;
  std::vector<std::uint8_t> moves_;  ///< bit k: step k is allowed from the cell
  std::array<std::ptrdiff_t, 8> offset_{};
  std::uint32_t current_ = 0;
};

/// True when the straight segment between two cell centres crosses only navigable cells
/// (supercover: where it passes exactly through a corner, both side cells must be navigable).
bool lineOfSight(const PlanningGrids& grids, Cell a, Cell b) {
  const GridGeometry& g = grids.geometry;
  const long long dx = std::abs(b.x - a.x), dy = std::abs(b.y - a.y);
  const int sx = b.x > a.x ? 1 : -1, sy = b.y > a.y ? 1 : -1;
  int x = a.x, y = a.y;
  for (long long n = dx + dy; n > 0; --n) {
    // The next x grid line is crossed at t = (2i+1)/(2dx), the next y line at (2j+1)/(2dy),
    // with i, j the lines crossed so far; compare them without division.
    const long long tx = (2LL * std::abs(x - a.x) + 1) * dy;
    const long long ty = (2LL * std::abs(y - a.y) + 1) * dx;
    if (tx < ty) {
      x += sx;
    } else if (ty < tx) {
      y += sy;
    } else {  // through a corner: both side cells must be navigable, then step diagonally
      if (!grids.nav[g.index({x + sx, y})] || !grids.nav[g.index({x, y + sy})]) return false;
      x += sx;
      y += sy;
      --n;
    }
    if (!grids.nav[g.index({x, y})]) return false;
  }
  return true;
}

/// Length [cells] of a grid path, shortened by string pulling when `smooth`; appends the
/// kept cells (after the first) to `points`.
double legLength(const PlanningGrids& grids, const std::vector<std::uint32_t>& cells, bool smooth,
                 std::vector<Cell>& points) {
  const GridGeometry& g = grids.geometry;
  double length = 0.0;
  const auto add = [&](Cell from, Cell to) {
    length += std::hypot(to.x - from.x, to.y - from.y);
    points.push_back(to);
  };
  if (cells.size() < 2) return 0.0;
  if (!smooth) {
    for (std::size_t k = 1; k < cells.size(); ++k) add(g.cellAt(cells[k - 1]), g.cellAt(cells[k]));
    return length;
  }
  std::size_t anchor = 0;
  std::size_t k = 1;
  while (k < cells.size()) {
    std::size_t last_visible = k;
    while (last_visible + 1 < cells.size() &&
           lineOfSight(grids, g.cellAt(cells[anchor]), g.cellAt(cells[last_visible + 1]))) {
      ++last_visible;
    }
    add(g.cellAt(cells[anchor]), g.cellAt(cells[last_visible]));
    anchor = last_visible;
    k = anchor + 1;
  }
  return length;
}

/// Or-opt: moves segments of 1 to 3 stops, either way round, to where they shorten the
/// open tour most; repeated until no move helps. True when the route changed.
bool orOpt(std::vector<std::size_t>& route, const std::vector<std::vector<float>>& d) {
  const std::size_t n = route.size();
  const auto dist = [&](std::size_t a, std::size_t b) { return static_cast<double>(d[a][b]); };
  bool any = false;
  bool improved = true;
  while (improved) {
    improved = false;
    for (std::size_t len = 1; len <= 3; ++len) {
      for (std::size_t i = 1; i + len <= n; ++i) {
        const std::size_t prev = route[i - 1], first = route[i], last = route[i + len - 1];
        const bool has_next = i + len < n;
        const double removed =
            dist(prev, first) +
            (has_next ? dist(last, route[i + len]) - dist(prev, route[i + len]) : 0.0);
        double best = -1e-6;
        std::size_t best_j = n;
        bool best_reversed = false;
        for (std::size_t j = 0; j < n; ++j) {
          if (j + 1 >= i && j < i + len) continue;  // inside the segment or right before it
          const std::size_t a = route[j];
          const bool has_b = j + 1 < n;
          const double base = has_b ? -dist(a, route[j + 1]) : 0.0;
          const double forward = base + dist(a, first) + (has_b ? dist(last, route[j + 1]) : 0.0);
          const double backward = base + dist(a, last) + (has_b ? dist(first, route[j + 1]) : 0.0);
          if (forward - removed < best) {
            best = forward - removed;
            best_j = j;
            best_reversed = false;
          }
          if (backward - removed < best) {
            best = backward - removed;
            best_j = j;
            best_reversed = true;
          }
        }
        if (best_j == n) continue;
        std::vector<std::size_t> segment(route.begin() + static_cast<std::ptrdiff_t>(i),
                                         route.begin() + static_cast<std::ptrdiff_t>(i + len));
        if (best_reversed) std::reverse(segment.begin(), segment.end());
        route.erase(route.begin() + static_cast<std::ptrdiff_t>(i),
                    route.begin() + static_cast<std::ptrdiff_t>(i + len));
        const std::size_t insert_at = best_j < i ? best_j + 1 : best_j + 1 - len;
        route.insert(route.begin() + static_cast<std::ptrdiff_t>(insert_at), segment.begin(),
                     segment.end());
        improved = any = true;
      }
    }
  }
  return any;
}

/// 2-opt for an open tour with a fixed first stop: reverses route[i..j] while that shortens
/// it. True when the route changed.
bool twoOpt(std::vector<std::size_t>& route, const std::vector<std::vector<float>>& d) {
  const std::size_t n = route.size();
  bool any = false;
  bool improved = true;
  while (improved) {
    improved = false;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        const std::size_t a = route[i - 1], b = route[i], c = route[j];
        double delta = static_cast<double>(d[a][c]) - d[a][b];
        if (j + 1 < n) delta += static_cast<double>(d[b][route[j + 1]]) - d[c][route[j + 1]];
        if (delta < -1e-6) {
          std::reverse(route.begin() + static_cast<std::ptrdiff_t>(i),
                       route.begin() + static_cast<std::ptrdiff_t>(j) + 1);
          improved = any = true;
        }
      }
    }
  }
  return any;
}

/// Open-tour order from node 0 (the start) over the distance matrix `d`: nearest neighbour,
/// then 2-opt and Or-opt in turn until neither shortens it.
std::vector<std::size_t> orderTour(const std::vector<std::vector<float>>& d) {
  const std::size_t n = d.size();
  std::vector<std::size_t> route{0};
  std::vector<std::uint8_t> used(n, 0);
  used[0] = 1;
  for (std::size_t step = 1; step < n; ++step) {
    const std::size_t from = route.back();
    std::size_t best = n;
    for (std::size_t j = 1; j < n; ++j) {
      if (!used[j] && (best == n || d[from][j] < d[from][best])) best = j;
    }
    used[best] = 1;
    route.push_back(best);
  }
  twoOpt(route, d);
  while (orOpt(route, d) && twoOpt(route, d)) {
  }
  return route;
}

}  // namespace

OracleTour planOracleTour(const WorldModel& world, const OracleTourOptions& options) {
  options.validate();
  OracleTour tour;
  const ExplorationTruth truth(world, mapGeometryFor(world, options.map_resolution_m),
                               options.lethal_radius_m);
  tour.reachable_area_m2 = truth.reachableArea_m2();
  const PlanningGrids grids = planningGrids(world, truth, options);
  const GridGeometry& g = grids.geometry;
  if (truth.reachableCells().empty() || grids.start.x < 0) return tour;

  const double res = g.resolution_m();
  const int factor = static_cast<int>(std::lround(options.visibility_cell_m / res));
  const int spacing = std::max(1, static_cast<int>(std::lround(options.viewpoint_spacing_m / res)));
  const double range_cells = options.sensor_range_m / res;
  VisibilityGrid vis(g, factor, truth.reachableCells());

  // What the start sees is covered before the robot moves.
  std::vector<std::uint8_t> covered(vis.size(), 0);
  std::uint64_t covered_weight = 0;
  const std::uint64_t total_weight = truth.reachableCells().size();
  {
    std::vector<std::uint32_t> seen;
    const Vec2 start_cells = (world.start().position() - g.origin_m()) / res;
    vis.castFan(g, grids.blocks, start_cells, range_cells, options.rays_per_viewpoint, seen);
    for (std::uint32_t c : seen) {
      covered[c] = 1;
      covered_weight += vis.weight(c);
    }
  }
  const auto target_weight = static_cast<std::uint64_t>(
      std::ceil(options.target_coverage * static_cast<double>(total_weight) - 1e-9));

  // Visibility of every candidate, as one flat list with offsets (CSR).
  const std::vector<std::uint32_t> candidates = candidateCells(grids, spacing);
  tour.candidates = static_cast<int>(candidates.size());
  std::vector<std::uint32_t> offsets{0};
  std::vector<std::uint32_t> cells;
  offsets.reserve(candidates.size() + 1);
  for (std::uint32_t c : candidates) {
    const Cell cell = g.cellAt(c);
    vis.castFan(g, grids.blocks, {cell.x + 0.5, cell.y + 0.5}, range_cells,
                options.rays_per_viewpoint, cells);
    offsets.push_back(static_cast<std::uint32_t>(cells.size()));
  }
  const std::vector<std::size_t> chosen =
      greedyCover(offsets, cells, vis, covered, covered_weight, target_weight);
  tour.coverage = static_cast<double>(covered_weight) / static_cast<double>(total_weight);

  // Geodesic distances between the start (node 0) and the chosen viewpoints.
  std::vector<std::uint32_t> nodes{static_cast<std::uint32_t>(g.index(grids.start))};
  for (std::size_t c : chosen) nodes.push_back(candidates[c]);
  const std::size_t n = nodes.size();
  std::vector<std::vector<float>> d(n, std::vector<float>(n, 0.0f));
  GridSearch search(grids);
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<std::uint32_t> targets(nodes.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                             nodes.end());
    const std::vector<float> row = search.distances(nodes[i], targets);
    for (std::size_t k = 0; k < row.size(); ++k) d[i][i + 1 + k] = d[i + 1 + k][i] = row[k];
  }
  const std::vector<std::size_t> route = orderTour(d);

  // Legs along the route, measured on their (shortened) grid paths.
  std::vector<Cell> points{grids.start};
  for (std::size_t k = 1; k < route.size(); ++k) {
    const std::vector<std::uint32_t> path = search.path(nodes[route[k - 1]], nodes[route[k]]);
    const double leg_m = legLength(grids, path, options.smooth_legs, points) * res;
    tour.leg_lengths_m.push_back(leg_m);
    tour.length_m += leg_m;
    tour.viewpoints_m.push_back(g.centerOf(g.cellAt(nodes[route[k]])));
  }
  tour.path_m.reserve(points.size());
  for (const Cell& c : points) tour.path_m.push_back(g.centerOf(c));
  return tour;
}

}  // namespace roomscout::experiment
