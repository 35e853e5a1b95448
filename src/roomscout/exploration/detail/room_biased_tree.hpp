#pragma once
// The frontier point generation of the paper's semantic-region-aware exploration (§III-C.1),
// part of SemanticExplorer. One tree rooted at the start, as improved_rrt's (step eta_m,
// iterations_per_s per simulated second). Each iteration draws its sampling point P_sap: with
// probability 1 / (1 + k t) P_rad, uniform over the bounding box of the known cells; with
// probability k t / (1 + k t) P_sem, uniform among the current room's frontier cells
// (RoomTracker::sampleCells()), t being the time since the robot's room last changed; without
// such cells, P_rad. An extension toward P_sem takes the full step, so that the edge crosses the
// frontier. An edge that reaches unknown space adds its first unknown point P_i (with its
// anchor, the known cell before it) to the frontier point set F.

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "roomscout/exploration/detail/rrt_tree.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// The tree's options (documented in SemanticExplorerOptions::parameters()).
struct RoomBiasedTreeOptions {
  double k = 0.1;
  double eta_m = 1.0;
  double iterations_per_s = 300.0;
  int max_iterations_per_call = 20000;

  void validate() const;
};

/// P(P_sap = P_sem) = k t / (1 + k t) (paper Eq. 1).
double semanticSampleProbability(double k, double t_s);

class RoomBiasedTree {
 public:
  struct FrontierPoint {
    Vec2 p;       ///< first unknown point of the edge [m]
    Vec2 anchor;  ///< last known point of the edge before it [m]
  };
  using Blacklisted = std::function<bool(const Vec2&)>;

  RoomBiasedTree(std::uint64_t seed, const RoomBiasedTreeOptions& options);

  /// Plants the tree at the robot on the first call; later calls do nothing.
  void plant(const ExplorationInput& input);
  /// Runs the iterations owed since the last growth (at most max_iterations_per_call), drawing
  /// P_sem from `sample_cells` with the probability for `time_in_room_s`. Points in a cell that
  /// already holds one, or blacklisted, are not added.
  void grow(const ExplorationInput& input, const std::vector<Vec2>& sample_cells,
            double time_in_room_s, const Blacklisted& blacklisted);
  /// Drops the points seen since (no longer unknown), inside the inflation, or blacklisted.
  void dropStale(const ExplorationInput& input, const Blacklisted& blacklisted);
  /// Keeps the tree's nodes and the points on a grid of another geometry (the tree restarts at
  /// the robot when none of its nodes is left on it).
  void followGeometry(const ExplorationInput& input);

  const std::vector<FrontierPoint>& points() const { return points_; }
  /// Null before plant().
  const RrtTree* tree() const { return tree_.get(); }
  long semanticDraws() const { return semantic_draws_; }
  long randomDraws() const { return random_draws_; }

 private:
  RoomBiasedTreeOptions options_;
  std::mt19937_64 rng_;
  std::unique_ptr<RrtTree> tree_;
  double grown_until_s_ = 0.0;
  std::vector<FrontierPoint> points_;
  std::vector<std::uint8_t> point_cells_;  ///< one byte per cell: a point of F lies there
  long semantic_draws_ = 0, random_draws_ = 0;
};

}  // namespace roomscout
