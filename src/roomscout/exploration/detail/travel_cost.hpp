#pragma once
// C of SemanticExplorer's score: how far the robot must travel to a candidate goal. The
// straight-line distance, or with `geodesic` the path length past the costmap's lethal cells,
// so that a point behind a wall is not taken for a near one. The geodesic search stops as soon
// as the best candidate is known, which makes it 20-30x cheaper than a search over the whole
// map in the houses, for the same choice.

#include <cstddef>
#include <utility>
#include <vector>

#include "roomscout/core/visit_marks.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// A point that may become the goal (or the goal itself), while the points are scored.
struct GoalCandidate {
  Vec2 p;
  std::size_t point;    ///< index into the frontier points (their count for the goal)
  double without_cost;  ///< S without the cost term
  bool sliver;
  bool goal;
  double cost_m = 0.0;  ///< C; infinite when unreachable (or, geodesic, when it cannot win)
  bool inside = false;  ///< in the current room (points only)
};

class TravelCost {
 public:
  explicit TravelCost(bool geodesic) : geodesic_(geodesic) {}

  /// Sets every candidate's cost_m. Geodesic: Dijkstra from the robot, and the search stops once
  /// the goal's C is final and no candidate still open can beat the best final one of its kind
  /// (slivers and other points apart; slivers matter only when no other point can be chosen),
  /// given S = without_cost - w_c C; those left open get an infinite C.
  void apply(const ExplorationInput& input, std::vector<GoalCandidate>& candidates, double w_c);

 private:
  bool geodesic_;
  std::vector<float> dist_;  ///< Dijkstra distances [m] ...
  VisitMarks dist_valid_;    ///< ... valid where marked
  std::vector<std::pair<float, std::size_t>> heap_;
  std::vector<std::size_t> blocks_;  ///< the search block of each candidate
};

}  // namespace roomscout
