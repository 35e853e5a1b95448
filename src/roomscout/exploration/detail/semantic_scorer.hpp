#pragma once
// The evaluation of the paper's semantic-region-aware exploration (§III-C.2) and the terms
// `semantic` adds to it, part of SemanticExplorer. For each frontier point P_i: G = (unknown -
// occupied) area in the square of half-side gain_half_side_m around P_i, C = the travel cost
// from the robot to P_i (TravelCost), and S = w_g G - w_c C + A when P_i's anchor lies in the
// robot's room (or one of its leaves), - A otherwise (a point in no room counts as outside); no
// +-A in a hub. Then, each off at 0: minus heading_weight (1 - cos d) / 2 for turning away from
// the robot's heading, plus segment_weight per metre of the frontier segment beside P_i, and
// when choosing the next room C weighed next_room_cost_factor times and plus mass_weight per
// metre of frontier around P_i. Slivers (slivers.hpp) are chosen only when asked for and no
// other point is left.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "roomscout/core/visit_marks.hpp"
#include "roomscout/exploration/detail/cell_counts.hpp"
#include "roomscout/exploration/detail/room_biased_tree.hpp"
#include "roomscout/exploration/detail/room_tracker.hpp"
#include "roomscout/exploration/detail/slivers.hpp"
#include "roomscout/exploration/detail/travel_cost.hpp"

namespace roomscout {

/// The score's options (documented in SemanticExplorerOptions::parameters()).
struct SemanticScoreOptions {
  double gain_weight = 3.0;
  double cost_weight = 1.0;
  double room_reward = 3.0;
  double gain_half_side_m = 1.0;
  bool geodesic_cost = true;
  double next_room_cost_factor = 3.0;
  double heading_weight = 8.0;
  double segment_weight = 4.0;
  double segment_cap_m = 2.0;
  double mass_weight = 1.0;
  double mass_half_side_m = 3.0;
  double mass_cap_m = 10.0;

  void validate() const;
};

class SemanticScorer {
 public:
  using FrontierPoint = RoomBiasedTree::FrontierPoint;

  SemanticScorer(const SemanticScoreOptions& options, const SliverOptions& slivers)
      : options_(options), slivers_(slivers) {}

  /// S = w_g G - w_c C + A inside the current room, - A outside (paper §III-C.2); without the
  /// +-A in a hub.
  double score(double gain_m2, double cost_m, bool in_current_room, bool hub) const;

  /// The outcome of choose().
  struct Choice {
    std::optional<std::size_t> point;  ///< the best point (index into the points), if any
    bool sliver = false;               ///< that point is a sliver, taken for want of any other
    double score = 0.0;                ///< S of the best point that is no sliver (-inf when none)
    double goal_score = 0.0;           ///< S of the current goal (-inf when none or unreachable)
  };
  /// Scores `points` and the current goal (its square's G, no heading term). A sliver is
  /// scored only when `slivers_wanted`, in the current room and outside `observed` (cells the
  /// robot came near); `idle` selects the pocket threshold (SliverOptions::pocketArea_m2).
  Choice choose(const ExplorationInput& input, const std::vector<FrontierPoint>& points,
                const std::optional<FrontierPoint>& goal, const RoomTracker& rooms,
                const std::vector<std::uint8_t>& observed, bool slivers_wanted, bool idle,
                TravelCost& cost);

 private:
  /// The length [m] of the longest frontier segment (8-connected free cells with an unknown
  /// 4-neighbour) beside the frontier point p, up to segment_cap_m.
  double segmentLength(const OccupancyGrid& grid, const Vec2& p) const;
  /// Adds mass_weight min(M, mass_cap_m) to every candidate's without_cost, M the frontier in
  /// the square of half-side mass_half_side_m around it.
  void addFrontierMass(const OccupancyGrid& grid, std::vector<GoalCandidate>& candidates);

  SemanticScoreOptions options_;
  SliverOptions slivers_;
  std::vector<GoalCandidate> candidates_;  ///< scratch of choose()
  std::vector<std::uint8_t> pockets_;      ///< scratch of choose(): points opening onto a pocket
  CellCounts counts_;                      ///< scratch of addFrontierMass()
  // segmentLength()'s search along the frontier.
  mutable VisitMarks segment_seen_;
  mutable std::vector<Cell> segment_queue_;
};

}  // namespace roomscout
