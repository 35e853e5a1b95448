#pragma once
// How SemanticExplorer ends. The end test, as improved_rrt's: fewer than end_min_frontier_cells
// reachable frontier cells in end_checks consecutive tests, one every end_check_period_s,
// leaving out the cells the robot came within observed_radius_m of and, with
// end_pocket_area_m2, those opening onto a pocket of unknown space. And the end phase of
// `semantic`: after idle_end_s with nothing to assign the robot visits the remaining reachable
// frontier cells, nearest by C first, and ends when none is left; the tree misses wedges of
// rooms seen from their doors, which would otherwise stay unseen.

#include <cstdint>
#include <optional>
#include <vector>

#include "roomscout/exploration/detail/slivers.hpp"
#include "roomscout/exploration/detail/travel_cost.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// The end options (documented in SemanticExplorerOptions::parameters()).
struct SemanticEndPhaseOptions {
  double end_check_period_s = 1.0;
  int end_checks = 5;
  int end_min_frontier_cells = 2;
  double end_pocket_area_m2 = 0.0;
  double observed_radius_m = 0.75;
  double idle_end_s = 30.0;

  void validate() const;
};

class SemanticEndPhase {
 public:
  SemanticEndPhase(const SemanticEndPhaseOptions& options, const SliverOptions& slivers)
      : options_(options), slivers_(slivers) {}

  /// Marks the cells within observed_radius_m of the robot as observed, and tells whether the
  /// robot has had nothing to assign for idle_end_s (idle()). Call first in each decision.
  void observe(const ExplorationInput& input);
  /// Lays the observed cells onto a grid of another geometry; an end cell off it is given up.
  void followGeometry(const GridGeometry& previous, const GridGeometry& geometry);
  /// The end test, run once per end_check_period_s: true when it ends the exploration.
  bool endTest(const ExplorationInput& input);

  /// A goal was assigned: the robot is not idle.
  void goalAssigned() { idle_since_s_ = -1.0; }
  /// Nothing to assign at `time_s`: starts the idle clock, and once the robot is idle (as of
  /// observe()) enters the end phase; returns whether it is in it.
  bool nothingToAssign(double time_s);
  /// In the end phase (it never ends but with the exploration).
  bool active() const { return active_; }
  bool idle() const { return idle_; }
  /// The end phase's decision: done when the end test passes, else the next cell.
  Decision decide(const ExplorationInput& input, TravelCost& cost);
  /// The end phase's goal: the reachable frontier cell (as the end test counts them) nearest by
  /// C that the robot has not come within observed_radius_m of and that opens onto no pocket,
  /// or done when none is left.
  Decision nextCell(const ExplorationInput& input, TravelCost& cost);
  /// A goal that was reached or failed: when it is the end cell, the cell (failed from afar) or
  /// the disc around it (reached, or failed from close by) counts as observed.
  void onGoalDone(const Vec2& goal_m);

  /// One byte per cell: the robot came within observed_radius_m of it, or the end phase ruled
  /// it out.
  const std::vector<std::uint8_t>& observed() const { return observed_; }

 private:
  SemanticEndPhaseOptions options_;
  SliverOptions slivers_;
  std::vector<std::uint8_t> observed_;
  double last_end_check_s_ = -1e9;
  double last_end_pocket_check_s_ = -1e9;
  int failed_end_checks_ = 0;
  double idle_since_s_ = -1.0;
  bool idle_ = false;
  bool active_ = false;
  std::optional<Vec2> end_cell_;           ///< the end phase's current frontier cell
  std::vector<Vec2> end_cells_done_;       ///< end cells reached or failed since the last call
  std::vector<GoalCandidate> candidates_;  ///< scratch of nextCell()
};

}  // namespace roomscout
