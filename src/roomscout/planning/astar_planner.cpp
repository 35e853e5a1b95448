#include "roomscout/planning/astar_planner.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

#include "roomscout/core/errors.hpp"

namespace roomscout {

namespace {

constexpr float kSqrt2 = 1.41421356237f;

/// Radius around a lethal start cell searched for a traversable one [m].
constexpr double kStartSearchRadius_m = 0.5;

/// An open-list entry: f in the high 32 bits (a non-negative float's bits order like the
/// float), the cell index in the low ones, so the heap compares plain integers. Stale entries
/// (the cell was reached more cheaply later) are skipped when popped.
std::uint64_t openKey(float f, std::uint32_t index) {
  return (static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(f)) << 32) | index;
}
float keyF(std::uint64_t key) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(key >> 32));
}

/// The grid cell containing `p_m`, or nothing when `p_m` is outside the grid or not finite
/// (checked in floating point, so that no out-of-range value is ever cast to int).
std::optional<Cell> cellInside(const GridGeometry& geometry, const Vec2& p_m) {
  const double fx = (p_m.x() - geometry.origin_m().x()) / geometry.resolution_m();
  const double fy = (p_m.y() - geometry.origin_m().y()) / geometry.resolution_m();
  if (!(fx >= 0.0 && fx < geometry.width() && fy >= 0.0 && fy < geometry.height())) {
    return std::nullopt;
  }
  const Cell c{static_cast<int>(fx), static_cast<int>(fy)};
  if (!geometry.contains(c)) return std::nullopt;  // rounding at the far edge
  return c;
}

/// Path length of a waypoint list [m].
double polylineLength(const std::vector<Vec2>& waypoints_m) {
  double length_m = 0.0;
  for (std::size_t i = 1; i < waypoints_m.size(); ++i) {
    length_m += (waypoints_m[i] - waypoints_m[i - 1]).norm();
  }
  return length_m;
}

}  // namespace

void AStarOptions::validate() const {
  if (!(std::isfinite(goal_tolerance_m) && goal_tolerance_m >= 0.0)) {
    throw OptionError("planner.goal_tolerance_m must be a finite number >= 0");
  }
}

std::vector<ParameterRef> AStarOptions::parameters() {
  return {
      {"goal_tolerance_m", &goal_tolerance_m,
       "when the goal cell is lethal, the nearest traversable cell within this distance "
       "becomes the goal [m]"},
      {"allow_unknown", &allow_unknown, "whether paths may cross unknown cells"},
  };
}

AStarPlanner::AStarPlanner(const AStarOptions& options) : options_(options) { options_.validate(); }

bool AStarPlanner::pathIsClear(const Costmap& costmap, const Path& path, std::size_t from) {
  for (std::size_t i = from; i < path.waypoints_m.size(); ++i) {
    const std::optional<Cell> c = cellInside(costmap.geometry(), path.waypoints_m[i]);
    if (!c || costmap.isLethal(*c)) return false;
  }
  return true;
}

bool AStarPlanner::traversable(const Costmap& costmap, std::size_t index) const {
  return !costmap.isLethal(index) && (options_.allow_unknown || !costmap.isUnknown(index));
}

std::optional<Cell> AStarPlanner::nearestTraversable(const Costmap& costmap, const Vec2& p_m,
                                                     Cell around, double radius_m) const {
  const GridGeometry& geometry = costmap.geometry();
  if (traversable(costmap, geometry.index(around))) return around;
  const int r = static_cast<int>(std::ceil(radius_m / geometry.resolution_m()));
  std::optional<Cell> best;
  double best_distance_m = radius_m;
  for (int y = std::max(0, around.y - r); y <= std::min(geometry.height() - 1, around.y + r); ++y) {
    for (int x = std::max(0, around.x - r); x <= std::min(geometry.width() - 1, around.x + r);
         ++x) {
      const Cell c{x, y};
      if (!traversable(costmap, geometry.index(c))) continue;
      const double d_m = (geometry.centerOf(c) - p_m).norm();
      if (d_m <= best_distance_m) {
        if (best && d_m == best_distance_m) continue;  // keep the first of equals
        best = c;
        best_distance_m = d_m;
      }
    }
  }
  return best;
}

PlanResult AStarPlanner::plan(const Costmap& costmap, const Vec2& start_m, const Vec2& goal_m) {
  PlanResult result;
  const GridGeometry& geometry = costmap.geometry();

  const std::optional<Cell> start_inside = cellInside(geometry, start_m);
  if (!start_inside) {
    result.status = PlanStatus::kStartBlocked;
    return result;
  }
  const std::optional<Cell> start_cell =
      nearestTraversable(costmap, start_m, *start_inside, kStartSearchRadius_m);
  if (!start_cell) {
    result.status = PlanStatus::kStartBlocked;
    return result;
  }
  const std::optional<Cell> goal_inside = cellInside(geometry, goal_m);
  if (!goal_inside) {
    result.status = PlanStatus::kGoalBlocked;
    return result;
  }
  const std::optional<Cell> goal_cell =
      nearestTraversable(costmap, goal_m, *goal_inside, options_.goal_tolerance_m);
  if (!goal_cell) {
    result.status = PlanStatus::kGoalBlocked;
    return result;
  }
  const bool start_moved = !(*start_cell == *start_inside);
  const bool goal_moved = !(*goal_cell == *goal_inside);

  const std::optional<std::vector<Cell>> cells = search(costmap, *start_cell, *goal_cell);
  if (!cells) {
    result.status = PlanStatus::kNoPath;
    return result;
  }

  result.status = PlanStatus::kFound;
  std::vector<Vec2>& waypoints = result.path.waypoints_m;
  waypoints.reserve(cells->size());
  for (const Cell& c : *cells) waypoints.push_back(geometry.centerOf(c));
  if (!start_moved) waypoints.front() = start_m;
  if (!goal_moved) waypoints.back() = goal_m;
  result.path.length_m = polylineLength(waypoints);
  return result;
}

std::optional<std::vector<Cell>> AStarPlanner::search(const Costmap& costmap, Cell start,
                                                      Cell goal) {
  const GridGeometry& geometry = costmap.geometry();
  const int width = geometry.width();
  const std::size_t n = geometry.cellCount();
  if (stamp_.size() != n) {
    g_.assign(n, 0.0f);
    parent_.assign(n, 0);
    stamp_.assign(n, 0);
    current_stamp_ = 0;
  }
  // Two stamps per search: `seen` marks cells with a valid g_ and parent_, `closed` expanded
  // ones. Older stamps are smaller, so nothing needs clearing between searches.
  if (current_stamp_ >= std::numeric_limits<std::uint32_t>::max() - 2) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    current_stamp_ = 0;
  }
  current_stamp_ += 2;
  const std::uint32_t seen = current_stamp_ - 1;
  const std::uint32_t closed = current_stamp_;

  const float resolution_m = static_cast<float>(geometry.resolution_m());
  const auto heuristic = [&](int x, int y) {
    const int dx = std::abs(x - goal.x);
    const int dy = std::abs(y - goal.y);
    return resolution_m *
           (static_cast<float>(std::max(dx, dy)) + (kSqrt2 - 1.0f) * std::min(dx, dy));
  };

  const auto start_index = static_cast<std::uint32_t>(geometry.index(start));
  const auto goal_index = static_cast<std::uint32_t>(geometry.index(goal));
  std::priority_queue<std::uint64_t, std::vector<std::uint64_t>, std::greater<>> open;
  // Cells whose f does not exceed the f last popped from the heap are minimal already: they
  // wait on this stack instead, which saves heap traffic on plateaus of equal f.
  std::vector<std::uint32_t> ready;
  float f_limit = 0.0f;
  g_[start_index] = 0.0f;
  parent_[start_index] = start_index;
  stamp_[start_index] = seen;
  open.push(openKey(heuristic(start.x, start.y), start_index));

  // Neighbour order: the four orthogonal moves first, then the diagonals, which use them.
  constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  const float straight_m = resolution_m;
  const float diagonal_m = resolution_m * kSqrt2;
  bool found = false;
  while (!ready.empty() || !open.empty()) {
    std::uint32_t index;
    if (!ready.empty()) {
      index = ready.back();
      ready.pop_back();
    } else {
      const std::uint64_t key = open.top();
      open.pop();
      index = static_cast<std::uint32_t>(key);
      f_limit = keyF(key);
    }
    if (stamp_[index] == closed) continue;
    stamp_[index] = closed;
    if (index == goal_index) {
      found = true;
      break;
    }
    const int x = static_cast<int>(index % width);
    const int y = static_cast<int>(index / width);
    const float g = g_[index];
    bool orthogonal_ok[4] = {false, false, false, false};
    for (int k = 0; k < 8; ++k) {
      const int nx = x + kDx[k];
      const int ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= width || ny >= geometry.height()) continue;
      const bool diagonal = k >= 4;
      if (diagonal) {
        // No corner cutting: both orthogonal cells next to the diagonal step must be passable.
        const int along_x = kDx[k] > 0 ? 0 : 1;
        const int along_y = kDy[k] > 0 ? 2 : 3;
        if (!orthogonal_ok[along_x] || !orthogonal_ok[along_y]) continue;
      }
      const std::uint32_t next = static_cast<std::uint32_t>(ny) * width + nx;
      if (!diagonal) {
        orthogonal_ok[k] = traversable(costmap, next);
        if (!orthogonal_ok[k]) continue;
      } else if (!traversable(costmap, next)) {
        continue;
      }
      if (stamp_[next] == closed) continue;
      const float next_g = g + costmap.stepCost(next) * (diagonal ? diagonal_m : straight_m);
      if (stamp_[next] != seen || next_g < g_[next]) {
        stamp_[next] = seen;
        g_[next] = next_g;
        parent_[next] = index;
        const float f = next_g + heuristic(nx, ny);
        if (f <= f_limit) {
          ready.push_back(next);
        } else {
          open.push(openKey(f, next));
        }
      }
    }
  }
  if (!found) return std::nullopt;

  std::vector<Cell> cells;
  for (std::uint32_t i = goal_index;; i = parent_[i]) {
    cells.push_back(geometry.cellAt(i));
    if (i == start_index) break;
  }
  std::reverse(cells.begin(), cells.end());
  return cells;
}

}  // namespace roomscout
