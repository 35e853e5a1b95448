#pragma once
// MMPF, the multi-target potential field of SMMR-Explore (Yu et al., ICRA 2021; code
// efc-robot/SMMR-Explore, src/mmpf/src/mmpf_node.cpp), run for one robot.
//
// One cycle per simulated second (single_mmpf_node.launch: rate 1):
// - frontier cells: SMMR's reachable frontier cells (see reachableFrontierCells) at an L1
//   margin of 6 cells (inflation_radius) from obstacles; none in 5 consecutive cycles ends;
// - greedy clusters: a cell joins a cluster when it is within L1 < 3 cells of a member;
//   infoGain = cluster size, centre = the member nearest (L1) to the members' mean;
// - a BFS geodesic distance D_j from every centre through known-free cells;
// - potential P(c) = sum_j -size_j / D_j(c) (K_ATTRACT 1; clusters that do not reach c add
//   nothing), plus the "river" term: 5 * gain for every time c already lies on the current
//   descent, where gain starts at 1 and grows by one whenever no neighbour is lower;
// - 4-neighbour gradient descent from the robot for up to 3000 steps or until the descent is
//   next to a cluster centre (D_j <= 1); the end of the descent is the goal.
//
// Deliberate deviations:
// - distances, potential and descent use cells of `coarse_factor` map cells (default 2:
//   0.1 m) so a cycle costs milliseconds on large_office instead of a tenth of a second
//   (the original ran in its own process at 0.05 m); a coarse cell is free when one of its map
//   cells is free and none is occupied; the step count and the "next to a centre" test are in
//   coarse cells;
// - at a local minimum (no lower neighbour) the original increments the river gain but stays
//   put, so the descent ends there and the robot parks on it for good; ours increments the gain
//   and flows on to the lowest neighbour (river term included), as the paper describes the
//   river escaping local minima;
// - a goal that still has a frontier cell within keep_goal_radius_m is kept until reached or
//   failed: re-descending every second flipped the goal between two clusters while our
//   follower was still turning toward the last one, and the robot never moved (move_base's
//   planners drove on in an arc); keep_goal_radius_m = 0 restores the original's replanning;
// - the goal is the free, non-lethal map cell nearest to the descent's end (contract);
// - a cycle also runs at once when the robot has reached or failed its goal (the original
//   idles until its next tick);
// - frontier cells need a neighbour in the known-free, non-lethal region connected to the
//   robot (see reachableFrontierCells), and cells within 0.5 m of a failed goal are ignored;
//   otherwise a cubicle narrower than the robot keeps the original cycling forever;
// - with no frontier cell the robot keeps its goal (as the original, which sends nothing).

#include <cstdint>
#include <vector>

#include "roomscout/core/visit_marks.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct MmpfOptions {
  double cycle_period_s = 1.0;
  int obstacle_l1_cells = 6;
  int cluster_l1_cells = 3;
  int max_descent_steps = 3000;
  double river_step = 5.0;
  int coarse_factor = 2;
  double keep_goal_radius_m = 0.5;
  int end_cycles = 5;

  void validate() const;
  std::vector<ParameterRef> parameters();
};

class Mmpf final : public ExplorationStrategy {
 public:
  explicit Mmpf(const MmpfOptions& options = {}) : options_(options) {}

  std::string_view name() const override { return "mmpf"; }
  Decision decide(const ExplorationInput& input) override;
  void onGoalReached(const Vec2&) override { has_goal_ = false; }
  void onGoalFailed(const Vec2& goal_m) override {
    blacklist_.push_back(goal_m);
    has_goal_ = false;
  }
  double replanPeriod_s() const override { return options_.cycle_period_s; }
  std::vector<ParameterRef> parameters() override { return options_.parameters(); }
  void validateOptions() const override { options_.validate(); }

 private:
  MmpfOptions options_;
  bool started_ = false;
  double last_cycle_s_ = 0.0;
  int empty_cycles_ = 0;
  bool has_goal_ = false;
  Vec2 goal_m_ = Vec2::Zero();
  std::vector<Vec2> blacklist_;  ///< failed goals: frontier cells within 0.5 m are ignored
  // Scratch buffers reused between cycles.
  std::vector<std::uint8_t> free_;
  std::vector<float> potential_;
  VisitMarks seen_;  ///< BFS marks: the cells the current cluster's search reached
  std::vector<std::uint16_t> visits_;
  std::vector<std::uint8_t> near_centre_;
};

}  // namespace roomscout
