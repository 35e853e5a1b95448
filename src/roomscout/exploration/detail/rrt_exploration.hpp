#pragma once
// RRT exploration of Umari & Mukhopadhyay, "Autonomous robotic exploration based on multiple
// rapidly-exploring randomized trees", IROS 2017 (code: hasauino/rrt_exploration).
//
// Three stages, as in the original's three nodes:
// - detectors: a global tree (eta 15 m, rooted at the start, never reset) and a local tree
//   (eta 1 m, re-rooted at the robot after each of its detections) sample uniformly over the
//   map's bounds; an edge that reaches unknown space yields a frontier point (the point where
//   the walk met it) and is not added; edges through occupied cells are rejected;
// - filter: mean-shift (flat kernel, bandwidth 0.3 m, as sklearn's MeanShift) over the
//   previous cycle's centroids plus the new detections; a centroid is dropped when its costmap
//   cell is lethal or its information gain in a disc of 0.5 * info_radius is below 0.2 m^2;
// - assigner: IG = unknown area in a disc of info_radius (1 m), doubled when the Euclidean
//   distance d <= hysteresis_radius (3 m); revenue = info_multiplier (3) * IG - d; the
//   centroid of highest revenue is the goal, re-assigned every 0.5 s (the original assigner's
//   delay_after_assignment) whether or not the robot is busy, as the original does; while the
//   robot is busy (driving to a goal), centroids closer than hysteresis_radius to that goal
//   get IG = unknown area * hysteresis_gain as well (the original's branch for busy robots;
//   without it the robot flipped between two goals of similar revenue every second and
//   dithered in place for minutes on large_office).
//
// Deliberate deviations:
// - the original samples 100 points per wall-clock second per tree; here the rate is per
//   simulated second (samples_per_s) and decide() grows the samples owed for the simulated
//   time since the last call, so the rate does not depend on how often decide() is called;
//   the local tree is re-rooted at the pose of that call;
// - the original never stops; we add SMMR-Explore's end test (see ImprovedRrt): once per
//   simulated second, count the reachable frontier cells; fewer than 2 in 5 consecutive
//   checks ends the exploration; cells that stayed unknown while the robot was within
//   observed_radius_m of them are ignored (see markDisc); and, because a couple of wall-face
//   cells no beam ever marks can keep that count at 2 forever, exploration also ends when
//   the filter has offered no assignable centroid for idle_end_s while the trees kept growing;
//   and every pocket_check_period_s the end test also ignores frontier cells that open onto a
//   pocket of unknown space (see markUnknownPockets: furniture interiors and wall cracks our
//   laser never sees into, the outside seen through a crack in an outer wall): on
//   large_office hundreds of such cells remain at 99 % and neither detector ever sends the
//   robot to look into them, so without this the test never passed (with it, it still often
//   does not there: strips along outer walls no beam reached open onto the known box's
//   border, and min_opening_m keeps those, as it must keep a corridor's frontier);
// - the filter drops a centroid when its costmap cell is lethal (the original: cost above a
//   threshold of 70 on ROS's 0-100 costmap scale; our costmap has no such scale);
// - goals that were reached or whose path failed are blacklisted (no centroid within
//   blacklist_radius_m of one is assigned again); the original re-sends them, and a centroid
//   whose unknown disc lies behind a wall keeps the robot parked on it forever;
// - the assigner's discount is left out: for every robot it subtracts 1 (a cell, from an area
//   in m^2) from the IG of each centroid per unknown cell their info discs share with the
//   robot's assigned point; with one robot that only hits centroids within 2 info_radius of
//   its own goal, which the busy branch above overrides while it drives there, and the
//   blacklist stands in for it once the goal is reached or failed;
// - with no centroid and no goal left, the robot waits where it is (a goal at the nearest
//   non-lethal cell) while the trees grow;
// - a grid whose geometry differs from the last call's (a SLAM map that grew, its origin
//   moving): both trees are re-indexed for the new grid and sample over it, keeping their
//   nodes on it (a tree left with none restarts at the robot); the cells marked for the end
//   test move with the map; frontier points and centroids off the grid are dropped. The
//   original's detectors read the map's bounds on each iteration.

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "roomscout/core/grid_remap.hpp"
#include "roomscout/exploration/detail/rrt_tree.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct RrtExplorationOptions {
  double global_eta_m = 15.0;
  double local_eta_m = 1.0;
  double samples_per_s = 100.0;
  double bandwidth_m = 0.3;
  double info_radius_m = 1.0;
  double min_info_gain_m2 = 0.2;
  double info_multiplier = 3.0;
  double hysteresis_radius_m = 3.0;
  double hysteresis_gain = 2.0;
  double assign_period_s = 0.5;
  double blacklist_radius_m = 0.3;
  double end_check_period_s = 1.0;
  int end_checks = 5;
  int end_min_frontier_cells = 2;
  double observed_radius_m = 0.75;
  int max_samples_per_call = 20000;
  double idle_end_s = 30.0;
  EndTestPockets end_pockets;

  void validate() const;
  std::vector<ParameterRef> parameters();
};

class RrtExploration final : public ExplorationStrategy {
 public:
  explicit RrtExploration(std::uint64_t seed, const RrtExplorationOptions& options = {});
  ~RrtExploration() override;

  std::string_view name() const override { return "rrt"; }
  Decision decide(const ExplorationInput& input) override;
  void onGoalReached(const Vec2& goal_m) override;
  void onGoalFailed(const Vec2& goal_m) override;
  double replanPeriod_s() const override { return options_.assign_period_s; }
  std::vector<Vec2> candidateGoals() const override { return centroids_; }
  std::vector<ParameterRef> parameters() override { return options_.parameters(); }
  void validateOptions() const override { options_.validate(); }

  /// Centroids kept by the last filter cycle (for tests and visualisation).
  const std::vector<Vec2>& centroids() const { return centroids_; }
  /// Nodes of the global tree (0 before the first decide()).
  std::size_t globalTreeSize() const { return global_ ? global_->size() : 0; }
  /// The trees (null before the first decide()).
  const RrtTree* globalTree() const { return global_.get(); }
  const RrtTree* localTree() const { return local_.get(); }

 private:
  /// Carries the trees, marks and points over to a grid of another geometry (see the header).
  void followGeometry(const ExplorationInput& input, const GridGeometry& previous);
  void grow(const ExplorationInput& input);
  void filter(const ExplorationInput& input);
  bool blacklisted(const Vec2& p) const;

  RrtExplorationOptions options_;
  std::mt19937_64 rng_;
  std::unique_ptr<RrtTree> global_, local_;
  GeometryWatch geometry_;  ///< the grid geometry of the last call
  RrtTree::Sampler sampler_;
  double grown_until_s_ = 0.0;
  double last_end_check_s_ = 0.0;
  double last_pocket_check_s_ = -1e300;
  int failed_end_checks_ = 0;
  std::vector<Vec2> detected_;   ///< frontier points detected since the last filter cycle
  std::vector<Vec2> centroids_;  ///< the filter's output, re-clustered each cycle
  std::vector<Vec2> blacklist_;
  std::vector<std::uint8_t> visited_;  ///< cells the robot came within observed_radius_m of
  double idle_since_s_ = -1.0;         ///< when the robot began waiting with nothing to assign
  bool has_goal_ = false;              ///< a real (not waiting) goal is active
  Vec2 goal_m_ = Vec2::Zero();
};

}  // namespace roomscout
