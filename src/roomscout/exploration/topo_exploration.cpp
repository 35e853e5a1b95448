#include "roomscout/exploration/detail/topo_exploration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

void TopoExplorationOptions::validate() const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!positive(vertex_spacing_m)) throw OptionError("topo.vertex_spacing_m must be > 0");
  if (!positive(window_size_m)) throw OptionError("topo.window_size_m must be > 0");
  if (frontier_kernel_cells < 2 || frontier_kernel_cells > 16) {
    throw OptionError("topo.frontier_kernel_cells must be in [2, 16]");
  }
  if (!(cluster_eps_cells >= 1.0 && cluster_eps_cells <= 50.0)) {
    throw OptionError("topo.cluster_eps_cells must be in [1, 50]");
  }
  if (cluster_min_samples < 1) throw OptionError("topo.cluster_min_samples must be >= 1");
  if (min_cluster_points < 1) throw OptionError("topo.min_cluster_points must be >= 1");
  if (refresh_min_cluster_points < 1)
    throw OptionError("topo.refresh_min_cluster_points must be >= 1");
  if (!non_negative(refresh_open_unknown_m2))
    throw OptionError("topo.refresh_open_unknown_m2 must be >= 0");
  if (!non_negative(frontier_point_offset_m) || !non_negative(goal_offset_m)) {
    throw OptionError("topo: frontier_point_offset_m and goal_offset_m must be >= 0");
  }
  if (!non_negative(drop_radius_m)) throw OptionError("topo.drop_radius_m must be >= 0");
  if (!std::isfinite(centroid_weight) || !std::isfinite(heading_weight)) {
    throw OptionError("topo: centroid_weight and heading_weight must be finite");
  }
  if (!non_negative(goal_vertex_radius_m))
    throw OptionError("topo.goal_vertex_radius_m must be >= 0");
  if (!positive(stale_radius_m)) throw OptionError("topo.stale_radius_m must be > 0");
  if (!positive(goal_snap_radius_m)) throw OptionError("topo.goal_snap_radius_m must be > 0");
  if (!non_negative(observed_radius_m)) throw OptionError("topo.observed_radius_m must be >= 0");
  if (!non_negative(replan_period_s)) throw OptionError("topo.replan_period_s must be >= 0");
}

std::vector<ParameterRef> TopoExplorationOptions::parameters() {
  return {
      {"vertex_spacing_m", &vertex_spacing_m,
       "a new vertex where the robot is farther than this from every vertex [m]"},
      {"window_size_m", &window_size_m,
       "side of the square map window whose frontiers a vertex keeps [m]"},
      {"frontier_kernel_cells", &frontier_kernel_cells, "side of a frontier test window [cells]"},
      {"cluster_eps_cells", &cluster_eps_cells, "DBSCAN neighbourhood radius [cells]"},
      {"cluster_min_samples", &cluster_min_samples,
       "DBSCAN points within eps (itself included) of a core point"},
      {"min_cluster_points", &min_cluster_points,
       "frontier clusters with fewer points are dropped"},
      {"frontier_point_offset_m", &frontier_point_offset_m,
       "a direction's frontier point lies this far past its cluster mean [m]"},
      {"goal_offset_m", &goal_offset_m, "the goal lies this far past the cluster mean [m]"},
      {"drop_radius_m", &drop_radius_m,
       "a direction is dropped when the robot comes this close to its frontier point [m]"},
      {"centroid_weight", &centroid_weight,
       "score per metre between a frontier point and the centre of the map"},
      {"heading_weight", &heading_weight, "score per radian of heading change"},
      {"goal_vertex_radius_m", &goal_vertex_radius_m,
       "a goal this close to a vertex is given up [m]; 0 = never"},
      {"stale_radius_m", &stale_radius_m,
       "a direction with no frontier this close to its cluster is stale [m]"},
      {"goal_snap_radius_m", &goal_snap_radius_m,
       "the goal moves at most this far to a safe cell [m]"},
      {"final_refresh", &final_refresh,
       "before ending, the frontier clusters of the whole map become directions of their nearest "
       "vertex"},
      {"refresh_min_cluster_points", &refresh_min_cluster_points,
       "when the final refresh finds no cluster of min_cluster_points, clusters this large (about "
       "0.5 m of frontier) that open onto refresh_open_unknown_m2 of unknown space count"},
      {"refresh_open_unknown_m2", &refresh_open_unknown_m2,
       "unknown space (4-connected) a small cluster of the final refresh must open onto [m^2]"},
      {"observed_radius_m", &observed_radius_m,
       "the final refresh ignores frontiers this close to the robot's path [m]"},
      {"replan_period_s", &replan_period_s, "seconds between decisions while driving"},
  };
}

namespace {

/// Summed-area table of one cell class over a rectangle of the grid.
class AreaCount {
 public:
  AreaCount(int width, int height)
      : w_(width + 1), sum_(static_cast<std::size_t>(width + 1) * (height + 1), 0) {}
  int& at(int x, int y) { return sum_[static_cast<std::size_t>(y) * w_ + x]; }
  int at(int x, int y) const { return sum_[static_cast<std::size_t>(y) * w_ + x]; }
  /// Cells in [x, x + k) x [y, y + k).
  int box(int x, int y, int k) const {
    return at(x + k, y + k) - at(x, y + k) - at(x + k, y) + at(x, y);
  }

 private:
  int w_;
  std::vector<int> sum_;
};

/// True when the k x k window with lower-left cell `lo` holds a free and an unknown cell and no
/// occupied one (TopoMap.py if_frontier). Cells outside the grid count as nothing.
bool frontierWindow(const OccupancyGrid& grid, Cell lo, int k) {
  const GridGeometry& g = grid.geometry();
  bool free = false, unknown = false;
  for (int y = lo.y; y < lo.y + k; ++y) {
    for (int x = lo.x; x < lo.x + k; ++x) {
      if (!g.contains(Cell{x, y})) continue;
      switch (grid.state(g.index(Cell{x, y}))) {
        case CellState::kOccupied:
          return false;
        case CellState::kFree:
          free = true;
          break;
        case CellState::kUnknown:
          unknown = true;
          break;
      }
    }
  }
  return free && unknown;
}

/// One frontier cluster: DBSCAN over the frontier windows of a rectangle of the map.
struct FrontierCluster {
  Vec2 mean_m = Vec2::Zero();
  Vec2 anchor_m = Vec2::Zero();  ///< the member nearest the mean
  int points = 0;
};

/// TopoMap.py get_frontier_points over `rect` (clipped to the grid): every k x k window inside
/// it that holds a free and an unknown cell and no occupied one is a frontier point at its cell
/// (k/2, k/2), in the original's scan order (rows of the map, then columns); the points are
/// clustered by DBSCAN and clusters of fewer than min_cluster_points points dropped. Points on
/// cells flagged in `ignore` (one byte per map cell, may be null) are left out.
std::vector<FrontierCluster> frontierClusters(const OccupancyGrid& grid, CellRect rect,
                                              const TopoExplorationOptions& options,
                                              const std::vector<std::uint8_t>* ignore) {
  std::vector<FrontierCluster> clusters;
  const GridGeometry& g = grid.geometry();
  rect = rect.clippedTo(g.width(), g.height());
  const int x0 = rect.min_x, y0 = rect.min_y;
  const int k = options.frontier_kernel_cells;
  const int rw = rect.max_x - rect.min_x, rh = rect.max_y - rect.min_y;
  if (rw <= k || rh <= k) return clusters;

  // Window counts of free, unknown and occupied cells.
  AreaCount free(rw, rh), unknown(rw, rh), occupied(rw, rh);
  for (int y = 0; y < rh; ++y) {
    int row_free = 0, row_unknown = 0, row_occupied = 0;
    const std::size_t row = g.index(Cell{x0, y0 + y});
    for (int x = 0; x < rw; ++x) {
      switch (grid.state(row + x)) {
        case CellState::kFree:
          ++row_free;
          break;
        case CellState::kUnknown:
          ++row_unknown;
          break;
        case CellState::kOccupied:
          ++row_occupied;
          break;
      }
      free.at(x + 1, y + 1) = free.at(x + 1, y) + row_free;
      unknown.at(x + 1, y + 1) = unknown.at(x + 1, y) + row_unknown;
      occupied.at(x + 1, y + 1) = occupied.at(x + 1, y) + row_occupied;
    }
  }

  // Frontier points; `index` maps a window position to its point.
  const int ww = rw - k, wh = rh - k;  // range(shape - kernel_size)
  std::vector<Cell> points;
  std::vector<int> index(static_cast<std::size_t>(ww) * wh, -1);
  for (int y = 0; y < wh; ++y) {
    for (int x = 0; x < ww; ++x) {
      if (occupied.box(x, y, k) != 0 || free.box(x, y, k) == 0 || unknown.box(x, y, k) == 0)
        continue;
      if (ignore != nullptr && (*ignore)[g.index(Cell{x0 + x + k / 2, y0 + y + k / 2})] != 0)
        continue;
      index[static_cast<std::size_t>(y) * ww + x] = static_cast<int>(points.size());
      points.push_back({x, y});
    }
  }
  if (points.empty()) return clusters;
  auto centre = [&](int i) {
    return g.centerOf(Cell{x0 + points[i].x + k / 2, y0 + points[i].y + k / 2});
  };

  // DBSCAN (Euclidean distance <= eps; min_samples counts the point itself).
  const double eps = options.cluster_eps_cells;
  const int r = static_cast<int>(std::floor(eps));
  std::vector<Cell> offsets;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy <= eps * eps + 1e-9) offsets.push_back({dx, dy});
    }
  }
  auto forNeighbours = [&](const Cell& p, auto&& f) {
    for (const Cell& o : offsets) {
      const int x = p.x + o.x, y = p.y + o.y;
      if (x < 0 || y < 0 || x >= ww || y >= wh) continue;
      const int j = index[static_cast<std::size_t>(y) * ww + x];
      if (j >= 0) f(j);
    }
  };
  std::vector<std::uint8_t> core(points.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    int n = 0;
    forNeighbours(points[i], [&](int) { ++n; });
    core[i] = n >= options.cluster_min_samples ? 1 : 0;
  }
  std::vector<std::uint8_t> labelled(points.size(), 0);
  std::vector<int> members;
  for (std::size_t seed = 0; seed < points.size(); ++seed) {
    if (labelled[seed] || !core[seed]) continue;  // noise stays unlabelled and is dropped
    labelled[seed] = 1;
    members.assign(1, static_cast<int>(seed));
    for (std::size_t head = 0; head < members.size(); ++head) {
      const int i = members[head];
      if (!core[i]) continue;  // a border point joins but does not expand the cluster
      forNeighbours(points[i], [&](int j) {
        if (labelled[j]) return;
        labelled[j] = 1;
        members.push_back(j);
      });
    }
    if (static_cast<int>(members.size()) < options.min_cluster_points) continue;
    FrontierCluster c;
    c.points = static_cast<int>(members.size());
    for (const int i : members) c.mean_m += centre(i);
    c.mean_m /= static_cast<double>(members.size());
    double best = std::numeric_limits<double>::infinity();
    for (const int i : members) {
      const double d2 = (centre(i) - c.mean_m).squaredNorm();
      if (d2 < best) {
        best = d2;
        c.anchor_m = centre(i);
      }
    }
    clusters.push_back(c);
  }
  return clusters;
}

/// The direction from `from_m` toward a cluster.
TopoExploration::Direction directionTo(const Vec2& from_m, const FrontierCluster& c,
                                       const TopoExplorationOptions& options) {
  TopoExploration::Direction d;
  const Vec2 v = c.mean_m - from_m;
  d.frontier_distance_m = v.norm();
  d.heading_rad = d.frontier_distance_m > 1e-9 ? std::atan2(v.y(), v.x()) : 0.0;
  d.frontier_point_m = from_m + (d.frontier_distance_m + options.frontier_point_offset_m) *
                                    Vec2(std::cos(d.heading_rad), std::sin(d.heading_rad));
  d.anchor_m = c.anchor_m;
  d.points = c.points;
  return d;
}

/// Whether the unknown space next to `p_m` (the unknown cells within 2 cells of it and those
/// 4-connected to them) holds at least `cap` cells: a way into unseen space rather than a
/// pocket behind furniture. `seen` is scratch of one byte per cell, all 0, and left all 0.
bool opensOntoUnknown(const OccupancyGrid& grid, const Vec2& p_m, std::size_t cap,
                      std::vector<std::uint8_t>& seen) {
  const GridGeometry& g = grid.geometry();
  const Cell c = g.cellOf(p_m);
  std::vector<std::size_t> queue;
  auto push = [&](const Cell& q) {
    if (!g.contains(q)) return;
    const std::size_t j = g.index(q);
    if (seen[j] || !grid.isUnknown(j)) return;
    seen[j] = 1;
    queue.push_back(j);
  };
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) push(Cell{c.x + dx, c.y + dy});
  }
  const int w = g.width();
  for (std::size_t head = 0; head < queue.size() && queue.size() < cap; ++head) {
    const int x = static_cast<int>(queue[head] % w), y = static_cast<int>(queue[head] / w);
    push(Cell{x + 1, y});
    push(Cell{x - 1, y});
    push(Cell{x, y + 1});
    push(Cell{x, y - 1});
  }
  for (const std::size_t j : queue) seen[j] = 0;
  return queue.size() >= cap;
}

}  // namespace

std::vector<TopoExploration::Direction> TopoExploration::localDirections(
    const OccupancyGrid& grid, const Vec2& centre_m, const TopoExplorationOptions& options,
    const std::vector<std::uint8_t>* ignore) {
  const GridGeometry& g = grid.geometry();
  const Cell c = g.cellOf(centre_m);
  const int half = static_cast<int>(std::lround(options.window_size_m / 2.0 / g.resolution_m()));
  std::vector<Direction> directions;
  for (const FrontierCluster& cluster : frontierClusters(
           grid, CellRect{c.x - half, c.y - half, c.x + half, c.y + half}, options, ignore)) {
    directions.push_back(directionTo(centre_m, cluster, options));
  }
  return directions;
}

std::size_t TopoExploration::directionCount() const {
  std::size_t n = 0;
  for (const Vertex& v : vertices_) n += v.directions.size();
  return n;
}

void TopoExploration::endGoal(bool reached) {
  // A goal past the frontier that fails (often outside the building) says nothing about the
  // frontier itself, which the final refresh may still try.
  if (has_goal_ && (reached || goal_at_frontier_)) tried_anchors_.push_back(goal_anchor_m_);
  has_goal_ = false;
}

void TopoExploration::onGoalReached(const Vec2& /*goal_m*/) { endGoal(true); }

void TopoExploration::onGoalFailed(const Vec2& /*goal_m*/) { endGoal(false); }

void TopoExploration::addVertex(const OccupancyGrid& grid, const Vec2& p_m) {
  const int id = static_cast<int>(vertices_.size());
  vertices_.push_back({p_m, localDirections(grid, p_m, options_)});
  if (current_vertex_ >= 0) edges_.emplace_back(current_vertex_, id);
  current_vertex_ = id;
  centre_m_ += (p_m - centre_m_) / static_cast<double>(vertices_.size());
}

void TopoExploration::dropReached(const Vec2& p_m) {
  const double r2 = options_.drop_radius_m * options_.drop_radius_m;
  for (Vertex& v : vertices_) {
    std::erase_if(v.directions, [&](const Direction& d) {
      return (d.frontier_point_m - p_m).squaredNorm() < r2;
    });
  }
}

bool TopoExploration::nearVertex(const Vec2& goal_m) const {
  const double r2 = options_.goal_vertex_radius_m * options_.goal_vertex_radius_m;
  return std::any_of(vertices_.begin(), vertices_.end(),
                     [&](const Vertex& v) { return (v.position_m - goal_m).squaredNorm() < r2; });
}

bool TopoExploration::isStale(const OccupancyGrid& grid, const Direction& d) const {
  const GridGeometry& g = grid.geometry();
  const Cell c = g.cellOf(d.anchor_m);
  const int r = static_cast<int>(std::ceil(options_.stale_radius_m / g.resolution_m()));
  const int k = options_.frontier_kernel_cells;
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > r * r) continue;
      // The window whose point (k/2, k/2) is this cell.
      if (frontierWindow(grid, Cell{c.x + dx - k / 2, c.y + dy - k / 2}, k)) return false;
    }
  }
  return true;
}

std::optional<Vec2> TopoExploration::goalAlong(const ExplorationInput& input, const Vec2& from_m,
                                               const Direction& d) const {
  const GridGeometry& g = input.grid.geometry();
  const Vec2 u(std::cos(d.heading_rad), std::sin(d.heading_rad));
  const double step_m = 0.5;
  double s = d.frontier_distance_m + options_.goal_offset_m;
  while (s > 0.0 && !g.contains(Vec2(from_m + s * u))) s -= g.resolution_m();
  const double s_min = std::max(0.0, std::min(d.frontier_distance_m, s));
  for (; s >= s_min - 1e-9; s -= step_m) {
    if (const auto goal = nearestGoalCell(input.grid, input.costmap, from_m + s * u,
                                          options_.goal_snap_radius_m)) {
      return goal;
    }
  }
  return std::nullopt;
}

Decision TopoExploration::setGoal(const Vec2& goal_m, const Direction& d) {
  has_goal_ = true;
  goal_m_ = goal_m;
  goal_at_frontier_ = d.at_frontier;
  goal_anchor_m_ = d.anchor_m;
  last_heading_rad_ = d.heading_rad;
  return Decision::goal(goal_m);
}

std::optional<Decision> TopoExploration::selectAtNewestVertex(const ExplorationInput& input) {
  std::vector<Direction>& directions = vertices_.back().directions;
  while (!directions.empty()) {
    std::size_t best = 0;
    double best_score = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < directions.size(); ++i) {
      const Direction& d = directions[i];
      const double score =
          options_.centroid_weight * (d.frontier_point_m - centre_m_).norm() +
          options_.heading_weight * std::abs(wrapAngle(d.heading_rad - last_heading_rad_));
      if (score > best_score) {
        best_score = score;
        best = i;
      }
    }
    const Direction d = directions[best];
    directions.erase(directions.begin() + static_cast<std::ptrdiff_t>(best));
    const std::optional<Vec2> goal = goalAlong(input, input.robot.position(), d);
    if (!goal || nearVertex(*goal)) continue;
    return setGoal(*goal, d);
  }
  return std::nullopt;
}

std::optional<Decision> TopoExploration::backtrack(const ExplorationInput& input) {
  const Vec2 p = input.robot.position();
  std::vector<std::pair<double, int>> order;
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    if (!vertices_[i].directions.empty())
      order.emplace_back((vertices_[i].position_m - p).norm(), static_cast<int>(i));
  }
  std::sort(order.begin(), order.end());  // ties: lower index first
  for (const auto& [distance, i] : order) {
    Vertex& v = vertices_[static_cast<std::size_t>(i)];
    while (!v.directions.empty()) {
      const Direction d = v.directions.front();
      v.directions.erase(v.directions.begin());
      const bool stale = isStale(input.grid, d);
      std::optional<Vec2> goal;
      if (!stale) {
        goal = d.at_frontier ? nearestGoalCell(input.grid, input.costmap, d.anchor_m,
                                               options_.goal_snap_radius_m)
                             : goalAlong(input, v.position_m, d);
      }
      if (stale || !goal || (!d.at_frontier && nearVertex(*goal))) continue;
      return setGoal(*goal, d);
    }
  }
  return std::nullopt;
}

bool TopoExploration::refreshAll(const OccupancyGrid& grid) {
  if (vertices_.empty()) return false;
  const GridGeometry& g = grid.geometry();
  std::vector<std::uint8_t> ignore = visited_;
  ignore.resize(g.cellCount(), 0);
  for (const Vec2& a : tried_anchors_) markDisc(ignore, g, a, options_.stale_radius_m);
  bool any = false;
  std::vector<FrontierCluster> clusters = frontierClusters(grid, g.bounds(), options_, &ignore);
  if (clusters.empty() && options_.refresh_min_cluster_points < options_.min_cluster_points) {
    // Nothing of the original's size left: smaller clusters that open onto unseen space (a door
    // seen at a slant from the middle of a room) rather than onto a pocket.
    TopoExplorationOptions small = options_;
    small.min_cluster_points = options_.refresh_min_cluster_points;
    clusters = frontierClusters(grid, g.bounds(), small, &ignore);
    const double cell_m2 = g.resolution_m() * g.resolution_m();
    const auto cap = static_cast<std::size_t>(
        std::max(1.0, std::ceil(options_.refresh_open_unknown_m2 / cell_m2)));
    std::vector<std::uint8_t> seen(g.cellCount(), 0);
    std::erase_if(clusters, [&](const FrontierCluster& c) {
      return !opensOntoUnknown(grid, c.anchor_m, cap, seen);
    });
  }
  for (const FrontierCluster& c : clusters) {
    auto nearest =
        std::min_element(vertices_.begin(), vertices_.end(), [&](const Vertex& a, const Vertex& b) {
          return (a.position_m - c.anchor_m).squaredNorm() <
                 (b.position_m - c.anchor_m).squaredNorm();
        });
    Direction d = directionTo(nearest->position_m, c, options_);
    d.at_frontier = true;
    nearest->directions.push_back(d);
    any = true;
  }
  return any;
}

Decision TopoExploration::decide(const ExplorationInput& input) {
  const GridGeometry& g = input.grid.geometry();
  const Vec2 p = input.robot.position();
  if (const auto previous = geometry_.update(g)) visited_ = remapCells(visited_, *previous, g);
  if (options_.observed_radius_m > 0.0) markDisc(visited_, g, p, options_.observed_radius_m);
  dropReached(p);

  // The vertex test: a new vertex re-decides at once.
  int nearest = -1;
  double nearest_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    const double d = (vertices_[i].position_m - p).norm();
    if (d < nearest_d) {
      nearest_d = d;
      nearest = static_cast<int>(i);
    }
  }
  if (nearest < 0 || nearest_d > options_.vertex_spacing_m) {
    addVertex(input.grid, p);
    if (const auto decision = selectAtNewestVertex(input)) return *decision;
    has_goal_ = false;
  } else if (nearest != current_vertex_) {
    const std::pair<int, int> edge(current_vertex_, nearest);
    if (std::find(edges_.begin(), edges_.end(), edge) == edges_.end() &&
        std::find(edges_.begin(), edges_.end(), std::pair<int, int>(nearest, current_vertex_)) ==
            edges_.end()) {
      edges_.push_back(edge);
    }
    current_vertex_ = nearest;
  }

  // Keep the current goal while it is safe and not near a vertex (the loop test).
  if (has_goal_ && !goal_at_frontier_ && nearVertex(goal_m_)) has_goal_ = false;
  if (has_goal_) {
    const Cell c = g.cellOf(goal_m_);
    if (g.contains(c) && !input.costmap.isLethal(g.index(c)) &&
        !input.grid.isOccupied(g.index(c))) {
      return Decision::goal(goal_m_);
    }
    const auto snapped =
        nearestGoalCell(input.grid, input.costmap, goal_m_, options_.goal_snap_radius_m);
    if (snapped && (goal_at_frontier_ || !nearVertex(*snapped))) {
      goal_m_ = *snapped;
      return Decision::goal(goal_m_);
    }
    endGoal(false);  // as move_base aborts a goal that became an obstacle
  }

  // Backtracking; when no vertex has a direction left, the final refresh (a deviation).
  if (const auto decision = backtrack(input)) return *decision;
  if (options_.final_refresh && refreshAll(input.grid)) {
    if (const auto decision = backtrack(input)) return *decision;
  }
  return Decision::done();
}

}  // namespace roomscout
