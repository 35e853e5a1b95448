#include "roomscout/exploration/detail/semantic_scorer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"

namespace roomscout {

void SemanticScoreOptions::validate() const {
  auto finiteAtLeast = [](double v, double lo) { return std::isfinite(v) && v >= lo; };
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!finiteAtLeast(gain_weight, 0.0) || !finiteAtLeast(cost_weight, 0.0)) {
    throw OptionError("semantic: gain_weight and cost_weight must be >= 0");
  }
  if (!finiteAtLeast(room_reward, 0.0)) throw OptionError("semantic.room_reward must be >= 0");
  if (!positive(gain_half_side_m)) throw OptionError("semantic.gain_half_side_m must be > 0");
  if (!finiteAtLeast(next_room_cost_factor, 0.0))
    throw OptionError("semantic.next_room_cost_factor must be >= 0");
  if (!finiteAtLeast(heading_weight, 0.0))
    throw OptionError("semantic.heading_weight must be >= 0");
  if (!finiteAtLeast(segment_weight, 0.0))
    throw OptionError("semantic.segment_weight must be >= 0");
  if (!finiteAtLeast(segment_cap_m, 0.0)) throw OptionError("semantic.segment_cap_m must be >= 0");
  if (!finiteAtLeast(mass_weight, 0.0)) throw OptionError("semantic.mass_weight must be >= 0");
  if (!positive(mass_half_side_m)) throw OptionError("semantic.mass_half_side_m must be > 0");
  if (!finiteAtLeast(mass_cap_m, 0.0)) throw OptionError("semantic.mass_cap_m must be >= 0");
}

double SemanticScorer::score(double gain_m2, double cost_m, bool in_current_room, bool hub) const {
  const double base = options_.gain_weight * gain_m2 - options_.cost_weight * cost_m;
  if (hub) return base;
  return in_current_room ? base + options_.room_reward : base - options_.room_reward;
}

SemanticScorer::Choice SemanticScorer::choose(const ExplorationInput& input,
                                              const std::vector<FrontierPoint>& points,
                                              const std::optional<FrontierPoint>& goal,
                                              const RoomTracker& rooms,
                                              const std::vector<std::uint8_t>& observed,
                                              bool slivers_wanted, bool idle, TravelCost& cost) {
  const GridGeometry& g = input.grid.geometry();
  const Vec2 robot = input.robot.position();
  if (slivers_.pocket_area_m2 > 0.0) {
    std::vector<Cell> cells;
    cells.reserve(points.size());
    for (const FrontierPoint& f : points) cells.push_back(g.cellOf(f.p));
    pockets_.assign(g.cellCount(), 0);
    markUnknownPockets(pockets_, input.grid, input.costmap, cells,
                       slivers_.pocketArea_m2(input.grid, idle), kPocketOpening_m);
  }
  // The points that may become the goal, with the score's part that does not depend on C.
  std::vector<GoalCandidate>& cands = candidates_;
  cands.clear();
  const int frontier_wanted = slivers_.frontierCellsWanted(g.resolution_m());
  // The cost of turning away from the way the robot is driving; the goal itself never pays it:
  // where the path to it bends round a wall the robot faces away from it, and charging it then
  // made the robot swing between goals until the time limit.
  const Vec2 heading(std::cos(input.robot.yaw_rad), std::sin(input.robot.yaw_rad));
  auto turn = [&](const Vec2& p) {
    const Vec2 d = p - robot;
    const double len = d.norm();
    if (options_.heading_weight <= 0.0 || len < 1e-9) return 0.0;
    return options_.heading_weight * 0.5 * (1.0 - heading.dot(d) / len);
  };
  auto segmentTerm = [&](const Vec2& p) {
    return options_.segment_weight > 0.0 ? options_.segment_weight * segmentLength(input.grid, p)
                                         : 0.0;
  };
  const bool hub = rooms.inHub();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::size_t cell = g.index(g.cellOf(points[i].p));
    const SquareAreas a =
        squareAreas(input.grid, points[i].p, options_.gain_half_side_m, frontier_wanted);
    const bool sliver = exhausted(a, slivers_, slivers_.min_unknown_m2, g.resolution_m()) ||
                        (slivers_.pocket_area_m2 > 0.0 && pockets_[cell]);
    if (sliver && (!slivers_wanted || observed[cell])) continue;
    const bool inside = rooms.inCurrentRoom(rooms.roomOf(input, points[i].anchor));
    if (sliver && !inside) continue;
    const double without_cost = score(a.unknown_m2 - a.occupied_m2, 0.0, inside, hub) -
                                turn(points[i].p) + segmentTerm(points[i].p);
    cands.push_back({points[i].p, i, without_cost, sliver, false});
    cands.back().inside = inside;
  }
  if (goal) {
    const SquareAreas a = squareAreas(input.grid, goal->p, options_.gain_half_side_m);
    const bool inside = rooms.inCurrentRoom(rooms.roomOf(input, goal->anchor));
    cands.push_back({goal->p, points.size(),
                     score(a.unknown_m2 - a.occupied_m2, 0.0, inside, hub) + segmentTerm(goal->p),
                     false, true});
  }
  // Choosing the next room: in a hub, or no point left in this room but slivers.
  const bool next_room =
      hub || std::none_of(cands.begin(), cands.end(),
                          [](const GoalCandidate& k) { return k.inside && !k.sliver && !k.goal; });
  const double w_c = options_.cost_weight * (next_room ? options_.next_room_cost_factor : 1.0);
  if (next_room) addFrontierMass(input.grid, cands);
  cost.apply(input, cands, w_c);
  Choice choice;
  choice.score = -std::numeric_limits<double>::infinity();
  choice.goal_score = -std::numeric_limits<double>::infinity();
  double best_sliver_score = -std::numeric_limits<double>::infinity();
  std::size_t best = points.size(), best_sliver = points.size();
  for (const GoalCandidate& c : cands) {
    if (!std::isfinite(c.cost_m)) continue;  // no path through the costmap (or cannot win)
    const double s = c.without_cost - w_c * c.cost_m;
    if (c.goal) {
      choice.goal_score = s;
      continue;
    }
    double& best_of_kind = c.sliver ? best_sliver_score : choice.score;
    if (s > best_of_kind) {
      best_of_kind = s;
      (c.sliver ? best_sliver : best) = c.point;
    }
  }
  choice.sliver = best == points.size() && slivers_wanted;
  if (choice.sliver) best = best_sliver;
  if (best < points.size()) choice.point = best;
  return choice;
}

double SemanticScorer::segmentLength(const OccupancyGrid& grid, const Vec2& p) const {
  const GridGeometry& g = grid.geometry();
  const int w = g.width(), h = g.height();
  // The segments of the frontier cells within two cells of p (p is unknown, its frontier runs
  // beside it), each followed through its 8-connected frontier cells until it is known to be
  // at least segment_cap_m long.
  const std::size_t cap =
      static_cast<std::size_t>(std::ceil(options_.segment_cap_m / g.resolution_m()));
  const Cell c = g.cellOf(p);
  segment_seen_.begin(g.cellCount());
  std::size_t longest = 0;
  for (int sy = std::max(0, c.y - 2); sy <= std::min(h - 1, c.y + 2); ++sy) {
    for (int sx = std::max(0, c.x - 2); sx <= std::min(w - 1, c.x + 2); ++sx) {
      const std::size_t s = static_cast<std::size_t>(sy) * w + sx;
      if (segment_seen_.marked(s) || !freeBesideUnknown(grid, sx, sy)) continue;
      segment_queue_.assign(1, Cell{sx, sy});
      segment_seen_.mark(s);
      for (std::size_t head = 0; head < segment_queue_.size() && segment_queue_.size() < cap;
           ++head) {
        const Cell q = segment_queue_[head];
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int x = q.x + dx, y = q.y + dy;
            if (x < 0 || y < 0 || x >= w || y >= h) continue;
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            if (segment_seen_.marked(i) || !freeBesideUnknown(grid, x, y)) continue;
            segment_seen_.mark(i);
            segment_queue_.push_back(Cell{x, y});
          }
        }
      }
      longest = std::max(longest, std::min(cap, segment_queue_.size()));
      if (longest >= cap) return options_.segment_cap_m;
    }
  }
  return std::min(options_.segment_cap_m, static_cast<double>(longest) * g.resolution_m());
}

void SemanticScorer::addFrontierMass(const OccupancyGrid& grid,
                                     std::vector<GoalCandidate>& candidates) {
  if (options_.mass_weight <= 0.0 || candidates.empty()) return;
  // The frontier cells counted over the candidates' squares (freeBesideUnknown leaves out the
  // grid's border cells).
  const GridGeometry& g = grid.geometry();
  const int r = static_cast<int>(std::lround(options_.mass_half_side_m / g.resolution_m()));
  int x0 = g.width(), x1 = -1, y0 = g.height(), y1 = -1;
  for (const GoalCandidate& c : candidates) {
    const Cell q = g.cellOf(c.p);
    x0 = std::min(x0, q.x - r);
    x1 = std::max(x1, q.x + r);
    y0 = std::min(y0, q.y - r);
    y1 = std::max(y1, q.y + r);
  }
  x0 = std::max(1, x0);
  y0 = std::max(1, y0);
  x1 = std::min(g.width() - 2, x1);
  y1 = std::min(g.height() - 2, y1);
  if (x0 > x1 || y0 > y1) return;
  counts_.build(x0, y0, x1, y1, [&](int x, int y) { return freeBesideUnknown(grid, x, y); });
  for (GoalCandidate& c : candidates) {
    const Cell q = g.cellOf(c.p);
    const int cells = counts_.square(q.x, q.y, r);
    c.without_cost +=
        options_.mass_weight * std::min(options_.mass_cap_m, cells * g.resolution_m());
  }
}

}  // namespace roomscout
