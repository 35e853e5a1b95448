#pragma once
// "Improved RRT": the rrt node of SMMR-Explore (Yu et al., "SMMR-Explore: SubMap-based
// Multi-Robot Exploration System with Multi-robot Multi-target Potential Field Exploration
// Method", ICRA 2021; code efc-robot/SMMR-Explore, src/rrt/src/rrt_node_tf.cpp), run for one
// robot.
//
// One tree rooted at the start (eta 1 m, single_rrt_node.launch) samples uniformly over the
// box of the current map (here: the bounding box of the known cells grown by 5 cells, as
// Cartographer pads the map it publishes; see knownCellsBox), 100 iterations per
// second (rate 100). Each iteration:
// - every 100 iterations, the end test: the reachable frontier cells (see
//   reachableFrontierCells, L1 margin 4 cells) are counted; fewer than 2 in 5 consecutive
//   tests ends the exploration;
// - one sample, nearest node, steer, edge check; an edge into unknown space adds its end as a
//   frontier point; the previous goal is added again while it is still unknown and clear;
// - frontier points no longer unknown or inside the inflation are removed;
// - a goal selection runs when more than 25 points arrived since the last one, or after 500
//   iterations (the original computes the count as an unsigned difference, so it also selects
//   whenever points were removed since the last selection; that quirk made the robot switch
//   goals every few iterations here and is off by default: unsigned_count_quirk). A selection drops
//   points whose four neighbours are all unknown, scores G = (unknown - occupied) area in the
//   square of half-side info_radius (1 m), G *= 2 within 3 m, score = 3 * G - d (Euclidean),
//   and sends the best unless it lies within 3 cells (L1) of the previous goal.
//
// Deliberate deviations:
// - iterations per simulated second instead of per wall-clock second; decide() runs the
//   iterations owed for the simulated time since the last call (replanPeriod_s 0.25 s: a
//   selection can fire at most every 26 iterations);
// - "inside the inflation" is our costmap's lethal zone (the launch file's threshold 0 on
//   move_base's costmap also excludes its soft inflation);
// - a goal that was reached or whose path failed is blacklisted (points within
//   blacklist_radius_m are dropped); the original leaves the robot idle on it until another
//   point scores better, which a point whose unknown square lies behind a wall may never allow;
// - the end test ignores frontier cells that stayed unknown while the robot was within
//   observed_radius_m of them (see markDisc): our laser never marks a few furniture-face cells;
//   and every pocket_check_period_s it also ignores frontier cells that open onto a pocket of
//   unknown space (see markUnknownPockets in frontier_cells.hpp): on large_office hundreds of
//   such cells (furniture interiors, wall cracks) remain at 99 %, the detector never sends the
//   robot to look into them, and the test never passed;
// - the previous goal, which the original appends to its point list on every iteration while
//   it stays unknown, is stored once with a count of its copies, and stale points are dropped
//   once per decide() call (the grid does not change within a call) and on arrival, instead
//   of an erase over the whole list every iteration. The counts, the list order (first copy)
//   and so every decision are the original's; only the wall time changes (large_office: the
//   list grew to thousands of copies, 300-380 s per episode).
// - when the detector has held no frontier point for look_after_idle_s while the end test still
//   counts reachable frontier cells, the robot drives to the nearest of them, one by one, until
//   it has come within observed_radius_m of each (or its goal failed) and the end test passes.
//   The original idles there for good: its tree finds no edge into the last cells (a wall's
//   corner the laser passed at a grazing angle, a crack at the map's edge): 10 of the 50
//   HouseExpo plans ran until the time limit at 99.99-100 %, now none (on large_office and in
//   3 of 10 medium_house seeds the detector still holds points at the limit);
// - after reaching its goal the robot waits in place (a goal at the nearest non-lethal cell)
//   until the next selection, as the original idles;
// - a grid whose geometry differs from the last call's (a SLAM map that grew, its origin
//   moving): the tree is re-indexed for the new grid, keeping its nodes on it (a tree left
//   with none restarts at the robot); frontier points and the previous goal get their cells on
//   the new grid (points off it are dropped, cached gains recomputed); the cells marked for the
//   end test move with the map; a look goal whose cell left the grid is given up.

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "roomscout/core/grid_remap.hpp"
#include "roomscout/exploration/detail/rrt_tree.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct ImprovedRrtOptions {
  double eta_m = 1.0;
  double iterations_per_s = 100.0;
  double info_radius_m = 1.0;
  double hysteresis_radius_m = 3.0;
  double hysteresis_gain = 2.0;
  double gain_weight = 3.0;
  int new_points_trigger = 25;
  int iterations_trigger = 500;
  int min_goal_change_cells = 3;
  int end_check_iterations = 100;
  int end_checks = 5;
  int end_min_frontier_cells = 2;
  int end_obstacle_l1_cells = 4;
  double replan_period_s = 0.25;
  double blacklist_radius_m = 0.3;
  double observed_radius_m = 0.75;
  bool unsigned_count_quirk = false;
  int max_iterations_per_call = 20000;
  EndTestPockets end_pockets;
  double look_after_idle_s = 30.0;

  void validate() const;
  std::vector<ParameterRef> parameters();
};

class GainTable;

class ImprovedRrt final : public ExplorationStrategy {
 public:
  explicit ImprovedRrt(std::uint64_t seed, const ImprovedRrtOptions& options = {});
  ~ImprovedRrt() override;

  std::string_view name() const override { return "improved_rrt"; }
  Decision decide(const ExplorationInput& input) override;
  void onGoalReached(const Vec2& goal_m) override;
  void onGoalFailed(const Vec2& goal_m) override;
  double replanPeriod_s() const override { return options_.replan_period_s; }
  std::vector<Vec2> candidateGoals() const override;
  std::vector<ParameterRef> parameters() override { return options_.parameters(); }
  void validateOptions() const override { options_.validate(); }

  /// Frontier points currently held, counting the previous goal's copies (for tests and
  /// visualisation).
  std::size_t frontierCount() const { return static_cast<std::size_t>(held_); }
  /// Distinct frontier points currently held.
  std::size_t distinctFrontierCount() const { return frontiers_.size(); }
  /// The tree (null before the first decide()).
  const RrtTree* tree() const { return tree_.get(); }

 private:
  struct Point {
    Vec2 p = Vec2::Zero();
    long copies = 1;          ///< times the original's list holds this point: the previous goal
                              ///< is appended again every iteration while it stays unknown
    double gain_m2 = 0.0;     ///< G, cached while no cell of its square changes
    bool gain_valid = false;  ///< gain_m2 holds G for the grid of the table's last build
    Cell cell{};              ///< cell of p; index: its row-major index, -1 outside the grid
    long index = -1;
    long neighbours[4] = {-1, -1, -1, -1};  ///< cells of p + (res,0), (0,res), (-res,0), (0,-res)
  };
  /// A point with its cells computed once (from p, as the original computes them each time).
  static Point makePoint(const GridGeometry& g, const Vec2& p, long copies);
  /// Carries the tree, points and marks over to a grid of another geometry (see the header).
  void followGeometry(const ExplorationInput& input, const GridGeometry& previous);
  enum class Step { kContinue, kDone };
  Step iterate(const ExplorationInput& input, const RrtTree::Sampler& sampler);
  void select(const ExplorationInput& input);
  bool blacklisted(const Vec2& p) const;
  /// The goal that looks at a frontier cell the end test still counts, after idling (see
  /// look_after_idle_s); none while the detector has points or before the idle time is over.
  std::optional<Vec2> lookGoal(const ExplorationInput& input);
  static bool stale(const ExplorationInput& input, const Point& f);
  /// erase_if over frontiers_ that keeps held_ and previous_index_ up to date.
  template <typename Pred>
  void eraseFrontiers(Pred&& pred);

  ImprovedRrtOptions options_;
  std::mt19937_64 rng_;
  std::unique_ptr<RrtTree> tree_;
  GeometryWatch geometry_;  ///< the grid geometry of the last call
  double done_until_s_ = 0.0;
  std::uint64_t call_ = 0;
  long iterations_since_selection_ = 0;
  long iterations_since_end_check_ = 0;
  int failed_end_checks_ = 0;
  double last_pocket_check_s_ = -1e300;
  long selected_count_ = 0;  ///< points held right after the last selection
  std::vector<Point> frontiers_;
  long held_ = 0;                      ///< sum of frontiers_[i].copies
  long previous_index_ = -1;           ///< entry of previous_goal_.p in frontiers_, if any
  std::vector<std::uint8_t> visited_;  ///< cells the robot came within observed_radius_m of
  std::vector<Vec2> blacklist_;
  std::unique_ptr<GainTable> gain_table_;  ///< built at most once per call, at its first selection
  std::uint64_t table_call_ = 0;
  bool has_previous_ = false;
  Point previous_goal_;              ///< the goal last selected, with its cells
  bool goal_active_ = false;         ///< previous_goal_.p is being driven to
  double idle_since_s_ = -1.0;       ///< since when no frontier point is held (-1: points)
  bool looking_ = false;             ///< look_goal_m_ is being driven to
  bool look_ended_ = false;          ///< the look goal was reached or failed since the last call
  Vec2 look_cell_m_ = Vec2::Zero();  ///< the frontier cell looked at
  Vec2 look_goal_m_ = Vec2::Zero();  ///< the free cell next to it
};

}  // namespace roomscout
