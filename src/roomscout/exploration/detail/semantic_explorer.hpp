#pragma once
// The paper's semantic-region-aware exploration (§III-C): an RRT frontier detector whose
// samples are drawn from the frontier of the robot's current room more and more often the
// longer the robot stays in it, and a goal score that rewards frontier points in that room,
// so the robot finishes the room it is in before it moves on.
//
// Its parts, each in a file of its own: the tree and its frontier points (RoomBiasedTree), the
// room bookkeeping (RoomTracker), the score (SemanticScorer, with TravelCost for C and
// slivers.hpp), and the end test and end phase (SemanticEndPhase). This class keeps the goal
// (its persistence and the blacklist) and runs the parts in order.
//
// The paper's method: the frontier point generation of §III-C.1 (RoomBiasedTree) and the
// evaluation of §III-C.2 (SemanticScorer): the best S among the frontier points becomes the goal.
// Without a semantic map (ExplorationInput::semantic null) no point is in a room: sampling is
// uniform and every point scores -A, i.e. the plain RRT score.
//
// What `semantic` adds to the paper (SemanticExplorerOptions' defaults; the measured effect of
// each is in docs/semantic_method.md). Each has a value that switches it off, which
// SemanticExplorerOptions::paper() uses:
// - Geodesic C: C is the path length past the costmap's lethal cells, not the straight line,
//   so that a point behind a wall is not taken for a near one. Off: geodesic_cost false.
// - Slivers: points whose square holds too little unknown space (min_unknown_m2) or frontier
//   (min_frontier_m), or that open onto a small enclosed pocket of unknown space
//   (pocket_area_m2, relative to the map once idle: pocket_area_fraction), are goals only once
//   the robot has idled, and are no P_sem; their unknown space lies behind walls already seen
//   or in a cupboard, and the trip shows little. Off: min_unknown_m2 0, min_frontier_m 0,
//   pocket_area_m2 0.
// - Label search: a free cell the segmentation has not labelled yet takes the room of the
//   nearest labelled cell within label_search_m through free cells, since the robot saw it
//   from that room; a point's anchor is usually such a fresh cell. Off: label_search_m 0 (an
//   unlabelled cell is in no room).
// - Hubs: in a room with hub_min_neighbours or more neighbours (a hallway) no point gets +-A
//   and P_sem comes from the frontier within hub_sample_radius_m of the robot, so that the
//   rooms beside a hallway come before its far end. Off: hub_min_neighbours 0.
// - Next room: in a hub, or when the room has no point left but slivers, C weighs
//   next_room_cost_factor times more and S gains mass_weight per metre of frontier around the
//   point (mass_half_side_m, up to mass_cap_m), so that the next room is a near one with much
//   left to see, as mmpf's potential favours. Off: next_room_cost_factor 1, mass_weight 0.
// - Heading: S -= heading_weight (1 - cos d) / 2, d the angle between the robot's heading and
//   the line to the point (the current goal never pays it), so that the robot does not
//   zig-zag. Off: heading_weight 0.
// - Frontier segment: S += segment_weight per metre of the frontier segment beside P_i, up to
//   segment_cap_m, so that a wide opening beats a crack with as much unknown space behind it.
//   Off: segment_weight 0.
// - Leaf rooms: a room whose only neighbour is the current room, while the current room has
//   another, counts as part of it (+A, P_sem), so that a closet or bathroom is finished with
//   the room it opens onto instead of on a later return. Off: leaf_rooms false.
// - Idle and end phase: after idle_end_s with nothing to assign the robot takes its room's
//   slivers, then visits the remaining reachable frontier cells nearest by C first, and ends
//   when none is left; the tree misses wedges of rooms seen from their doors, which would
//   otherwise stay unseen. Off: idle_end_s 0 (the robot waits for the tree and the end test).
// - The tree's rate, iterations_per_s 300 against improved_rrt's 100, so that points are found
//   sooner. paper() uses improved_rrt's 100.
//
// What semantic_paper keeps to run and end (SemanticExplorerOptions::paper(); the paper does
// not state them, but any method needs them):
// - Goal persistence: the goal is kept until its square is explored (less than
//   goal_min_unknown_m2 of unknown space left, or less than min_frontier_m of frontier when
//   that is on) or it turns lethal (then it is blacklisted), and replaced earlier, every
//   replan_period_s, only by a point that beats it by switch_margin; choosing afresh whenever
//   the laser's edge receded made the robot swing between points.
// - The blacklist: reached or failed goals drop the points within blacklist_radius_m.
// - The end test, as improved_rrt's: fewer than end_min_frontier_cells reachable frontier cells
//   in end_checks consecutive tests, one every end_check_period_s, leaving out the cells the
//   robot came within observed_radius_m of and, with end_pocket_area_m2 (paper() 4 m^2, as
//   improved_rrt; `semantic` 0, its end phase skips pockets instead), those opening onto a
//   pocket of unknown space: without the end phase no goal leads to them, and the robot would
//   otherwise wait until the time limit.
// - While nothing is assigned, the robot waits where it stands as the tree grows.
//
// A grid whose geometry differs from the last call's (a SLAM map that grew, its origin moving):
// the tree is re-indexed for the new grid, keeping its nodes on it (a tree left with none
// restarts at the robot); frontier points off the grid are dropped and the others keep their
// cell marks, laid on the new grid by map position, as are the cells the robot came near; an
// end-phase cell off the grid is given up. Rooms are looked up by map position, so a semantic
// map still on an older geometry serves until it is updated.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "roomscout/core/grid_remap.hpp"
#include "roomscout/exploration/detail/room_biased_tree.hpp"
#include "roomscout/exploration/detail/room_tracker.hpp"
#include "roomscout/exploration/detail/semantic_end_phase.hpp"
#include "roomscout/exploration/detail/semantic_scorer.hpp"
#include "roomscout/exploration/detail/slivers.hpp"
#include "roomscout/exploration/detail/travel_cost.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// How long a goal is kept, and which goals are not sent again (documented in
/// SemanticExplorerOptions::parameters()).
struct GoalPersistenceOptions {
  double goal_min_unknown_m2 = 1.0;
  double replan_period_s = 2.0;
  double switch_margin = 6.0;
  double blacklist_radius_m = 0.3;

  void validate() const;
};

/// The options of `semantic` (its defaults) and of the paper's method (paper()), one group per
/// part of the strategy. Each field is documented once, in parameters(): the text `roomscout`
/// prints, under the flat keys a config file uses (e.g. `k`, not `tree.k`).
struct SemanticExplorerOptions {
  RoomBiasedTreeOptions tree;
  RoomTrackerOptions rooms;
  SemanticScoreOptions score;
  SliverOptions slivers;
  GoalPersistenceOptions goal;
  SemanticEndPhaseOptions end;

  /// The paper's method as the paper states it (§III-C), for `semantic_paper` and its
  /// ablations: every addition of `semantic` off (see the header), C Euclidean, and the tree of
  /// improved_rrt (SMMR-Explore's rrt node, which the paper builds on: eta_m 1 m, 100 iterations
  /// per second). w_g, w_c, A and k are `semantic`'s: the paper gives no values for A and k.
  /// What it keeps is only what a method needs to run and to end: goal persistence (with the
  /// one threshold goal_min_unknown_m2 for "its square is explored", and switch_margin on the
  /// replan period), the blacklist and the end test.
  static SemanticExplorerOptions paper();

  void validate() const;
  std::vector<ParameterRef> parameters();
};

class SemanticExplorer final : public ExplorationStrategy {
 public:
  using FrontierPoint = RoomBiasedTree::FrontierPoint;

  /// @param name the registry name (the ablations share this class with other defaults)
  SemanticExplorer(std::uint64_t seed, const SemanticExplorerOptions& options = {},
                   std::string name = "semantic");

  std::string_view name() const override { return name_; }
  Decision decide(const ExplorationInput& input) override;
  void onGoalReached(const Vec2& goal_m) override;
  void onGoalFailed(const Vec2& goal_m) override;
  double replanPeriod_s() const override { return options_.goal.replan_period_s; }
  bool readsRooms() const override { return true; }
  std::vector<Vec2> candidateGoals() const override;
  std::vector<ParameterRef> parameters() override { return options_.parameters(); }
  void validateOptions() const override { options_.validate(); }

  /// S = w_g G - w_c C + A inside the current room, - A outside (paper §III-C.2); without
  /// the +-A while the robot is in a hub.
  double score(double gain_m2, double cost_m, bool in_current_room) const {
    return scorer_.score(gain_m2, cost_m, in_current_room, rooms_.inHub());
  }

  // Introspection for tests and visualisation.
  const std::vector<FrontierPoint>& frontierPoints() const { return tree_.points(); }
  /// The tree (null before the first decide()).
  const RrtTree* tree() const { return tree_.tree(); }
  /// The frontier cells P_sem is drawn from (as of the last decide()): the current room's and
  /// its leaves' (leaf_rooms), or in a hub those near the robot.
  const std::vector<Vec2>& semanticCandidates() const { return rooms_.sampleCells(); }
  int currentRoom() const { return rooms_.room(); }
  /// The current room is a hub (hub_min_neighbours), as of the last decide().
  bool inHub() const { return rooms_.inHub(); }
  double timeInRoom_s() const { return rooms_.timeInRoom_s(); }
  long semanticDraws() const { return tree_.semanticDraws(); }
  long randomDraws() const { return tree_.randomDraws(); }

 private:
  /// Carries the tree, points and marks over to a grid of another geometry (see above).
  void followGeometry(const ExplorationInput& input, const GridGeometry& previous);
  /// Drops the goal when it turned lethal (blacklisting it) or its square is explored: less
  /// than goal_min_unknown_m2 of unknown space or min_frontier_m of frontier left, or it is
  /// blacklisted or off the grid.
  void dropFinishedGoal(const ExplorationInput& input);
  bool blacklisted(const Vec2& p) const;

  SemanticExplorerOptions options_;
  std::string name_;
  GeometryWatch geometry_;  ///< the grid geometry of the last call
  RoomBiasedTree tree_;
  RoomTracker rooms_;
  SemanticScorer scorer_;
  TravelCost cost_;
  SemanticEndPhase end_;
  std::optional<FrontierPoint> goal_;  ///< the goal and its anchor
  bool chasing_slivers_ = false;       ///< the goal is a sliver chosen after idle_end_s of idling
  double last_eval_s_ = -1e9;
  std::vector<Vec2> blacklist_;
};

}  // namespace roomscout
