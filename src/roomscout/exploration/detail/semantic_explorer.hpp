#pragma once
// The paper's semantic-region-aware exploration (§III-C): an RRT frontier detector whose
// samples are drawn from the frontier of the robot's current room more and more often the
// longer the robot stays in it, and a goal score that rewards frontier points in that room,
// so the robot finishes the room it is in before it moves on.
//
// The paper's method
// - Frontier point generation (§III-C.1). One tree rooted at the start, as improved_rrt's (step
//   eta_m, iterations_per_s per simulated second). Each iteration draws its sampling point
//   P_sap: with probability 1 / (1 + k t) P_rad, uniform over the bounding box of the known
//   cells; with probability k t / (1 + k t) P_sem, uniform among the current room's frontier
//   cells (known-free, non-lethal, an unknown 4-neighbour), t being the time since the robot's
//   room last changed; without such cells, P_rad. An extension toward P_sem takes the full step,
//   so that the edge crosses the frontier. An edge that reaches unknown space adds its first
//   unknown point P_i (with its anchor, the known cell before it) to the frontier point set F.
// - Evaluation (§III-C.2). For each P_i in F: G = (unknown - occupied) area in the square of
//   half-side gain_half_side_m around P_i, C = the distance from the robot to P_i, and
//   S = w_g G - w_c C + A when P_i's anchor lies in the robot's room, - A otherwise (a point in
//   no room counts as outside). The best S becomes the goal.
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
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "roomscout/core/grid_remap.hpp"
#include "roomscout/core/visit_marks.hpp"
#include "roomscout/exploration/detail/rrt_tree.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// The options of `semantic` (its defaults) and of the paper's method (paper()). Each field is
/// documented once, in parameters(): the text `roomscout` prints.
struct SemanticExplorerOptions {
  double k = 0.1;
  double gain_weight = 3.0;
  double cost_weight = 1.0;
  double room_reward = 3.0;
  double gain_half_side_m = 1.0;
  double min_unknown_m2 = 1.0;
  double goal_min_unknown_m2 = 1.0;
  double min_frontier_m = 1.0;
  double pocket_area_m2 = 2.0;
  double pocket_area_fraction = 0.01;
  bool geodesic_cost = true;
  double eta_m = 1.0;
  double iterations_per_s = 300.0;
  double replan_period_s = 2.0;
  double switch_margin = 6.0;
  double label_search_m = 3.5;
  double blacklist_radius_m = 0.3;
  double end_check_period_s = 1.0;
  int end_checks = 5;
  int end_min_frontier_cells = 2;
  double end_pocket_area_m2 = 0.0;
  double observed_radius_m = 0.75;
  double idle_end_s = 30.0;
  int max_iterations_per_call = 20000;
  int hub_min_neighbours = 4;
  double next_room_cost_factor = 3.0;
  double hub_sample_radius_m = 4.5;
  double heading_weight = 8.0;
  double segment_weight = 4.0;
  double segment_cap_m = 2.0;
  double mass_weight = 1.0;
  double mass_half_side_m = 3.0;
  double mass_cap_m = 10.0;
  bool leaf_rooms = true;

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

/// P(P_sap = P_sem) = k t / (1 + k t) (paper Eq. 1).
double semanticSampleProbability(double k, double t_s);

class SemanticExplorer final : public ExplorationStrategy {
 public:
  /// @param name the registry name (the ablations share this class with other defaults)
  SemanticExplorer(std::uint64_t seed, const SemanticExplorerOptions& options = {},
                   std::string name = "semantic");
  ~SemanticExplorer() override;

  std::string_view name() const override { return name_; }
  Decision decide(const ExplorationInput& input) override;
  void onGoalReached(const Vec2& goal_m) override;
  void onGoalFailed(const Vec2& goal_m) override;
  double replanPeriod_s() const override { return options_.replan_period_s; }
  bool readsRooms() const override { return true; }
  std::vector<Vec2> candidateGoals() const override;
  std::vector<ParameterRef> parameters() override { return options_.parameters(); }
  void validateOptions() const override { options_.validate(); }

  /// S = w_g G - w_c C + A inside the current room, - A outside (paper §III-C.2); without
  /// the +-A while the robot is in a hub.
  double score(double gain_m2, double cost_m, bool in_current_room) const;

  // Introspection for tests and visualisation.
  struct FrontierPoint {
    Vec2 p;       ///< first unknown point of the edge [m]
    Vec2 anchor;  ///< last known point of the edge before it [m]
  };
  const std::vector<FrontierPoint>& frontierPoints() const { return points_; }
  /// The tree (null before the first decide()).
  const RrtTree* tree() const { return tree_.get(); }
  /// The frontier cells P_sem is drawn from (as of the last decide()): the current room's and
  /// its leaves' (leaf_rooms), or in a hub those near the robot.
  const std::vector<Vec2>& semanticCandidates() const { return candidates_; }
  int currentRoom() const { return room_; }
  /// The current room is a hub (hub_min_neighbours), as of the last decide().
  bool inHub() const { return hub_; }
  double timeInRoom_s() const { return time_in_room_s_; }
  long semanticDraws() const { return semantic_draws_; }
  long randomDraws() const { return random_draws_; }

 private:
  /// How many cells of a box pass a test, for any square in it in four lookups (a summed-area
  /// table, cv::integral).
  class CellCounts {
   public:
    /// Counts test(x, y) over the cells [x0, x1] x [y0, y1].
    template <class Test>
    void build(int x0, int y0, int x1, int y1, Test test);
    /// The cells passing the test in the square of half-side r cells around (cx, cy), within
    /// the box.
    int square(int cx, int cy, int r) const;

   private:
    int x0_ = 0, y0_ = 0, x1_ = -1, y1_ = -1;
    cv::Mat mask_, sums_;
  };

  /// Carries the tree, points and marks over to a grid of another geometry (see above).
  void followGeometry(const ExplorationInput& input, const GridGeometry& previous);
  void updateRoom(const ExplorationInput& input);
  /// Whether a point whose room is `room` counts as in the current room: `room` is the current
  /// room or one of its leaves (leaf_rooms). False outside every room.
  bool inCurrentRoom(int room) const;
  void collectCandidates(const ExplorationInput& input);
  void grow(const ExplorationInput& input, long iterations);
  int roomOf(const ExplorationInput& input, const Vec2& p) const;
  /// The length [m] of the longest frontier segment (8-connected free cells with an unknown
  /// 4-neighbour) beside the frontier point p, up to segment_cap_m.
  double segmentLength(const OccupancyGrid& grid, const Vec2& p) const;
  bool stale(const ExplorationInput& input, const Vec2& p) const;
  /// The goal's square is explored (less than goal_min_unknown_m2 of unknown space or
  /// min_frontier_m of frontier left), or the goal is blacklisted or off the grid. Lethal goals are
  /// dropped before this is asked (decide()).
  bool goalExplored(const ExplorationInput& input) const;
  bool blacklisted(const Vec2& p) const;
  /// A point that may become the goal (or the goal itself), while the points are scored.
  struct Candidate {
    Vec2 p;
    std::size_t point;    ///< index into points_ (points_.size() for the goal)
    double without_cost;  ///< S without the cost term: w_g G +- A
    bool sliver;
    bool goal;
    double cost_m = 0.0;    ///< C; infinite when unreachable (or, geodesic, when it cannot win)
    bool inside = false;    ///< in the current room (points only)
    std::size_t block = 0;  ///< geodesic C: the search block of p
  };
  /// Sets every candidate's C (see SemanticExplorerOptions::geodesic_cost); w_c is the weight
  /// the choice applies to C (the geodesic search stops once no open candidate can win).
  void cost(const ExplorationInput& input, std::vector<Candidate>& candidates, double w_c);
  /// Adds mass_weight min(M, mass_cap_m) to every candidate's without_cost, M the frontier in
  /// the square of half-side mass_half_side_m around it (see Next room in the header).
  void addFrontierMass(const OccupancyGrid& grid, std::vector<Candidate>& candidates);
  bool endTest(const ExplorationInput& input);
  /// The end phase's goal: the reachable frontier cell (as the end test counts them) nearest by
  /// C that the robot has not come within observed_radius_m of and that opens onto no pocket,
  /// or none. An end cell failed while the robot was farther than observed_radius_m from it
  /// rules out that cell only.
  std::optional<Vec2> endPhaseCell(const ExplorationInput& input);
  /// The pocket threshold now: pocket_area_m2, or once idle pocket_area_fraction of the known
  /// free area if that is less.
  double pocketArea_m2(const OccupancyGrid& grid) const;

  SemanticExplorerOptions options_;
  std::string name_;
  std::mt19937_64 rng_;
  std::unique_ptr<RrtTree> tree_;
  GeometryWatch geometry_;  ///< the grid geometry of the last call
  double grown_until_s_ = 0.0;
  double last_end_check_s_ = -1e9;
  double last_end_pocket_check_s_ = -1e9;
  int failed_end_checks_ = 0;
  double idle_since_s_ = -1.0;
  bool chasing_slivers_ = false;      ///< the goal is a sliver chosen after idle_end_s of idling
  bool end_phase_ = false;            ///< idled once with nothing to assign (see decide())
  std::optional<Vec2> end_cell_;      ///< the end phase's current frontier cell
  std::vector<Vec2> end_cells_done_;  ///< end-phase cells reached or failed since the last call
  double last_eval_s_ = -1e9;
  int room_ = 0;
  bool hub_ = false;
  std::vector<int> leaves_;  ///< the current room's leaves (see leaf_rooms), as of updateRoom()
  double room_since_s_ = 0.0;
  double time_in_room_s_ = 0.0;
  long semantic_draws_ = 0, random_draws_ = 0;
  std::vector<FrontierPoint> points_;
  std::vector<std::uint8_t> point_cells_;  ///< one byte per cell: a point of F lies there
  std::vector<Vec2> candidates_;
  std::vector<Vec2> blacklist_;
  std::vector<std::uint8_t> visited_;
  std::vector<std::uint8_t> pockets_;
  std::vector<Candidate> candidates_scored_;
  std::vector<float> dist_;  ///< geodesic C: Dijkstra distances [m] ...
  VisitMarks dist_valid_;    ///< ... valid where marked
  std::vector<std::pair<float, std::size_t>> heap_;
  bool idle_ = false;  ///< idle for idle_end_s: slivers, then the end phase
  bool has_goal_ = false;
  // roomOf()'s search for a label: the cells it reached, and its queue of cells with their
  // distance in steps.
  mutable VisitMarks label_seen_;
  mutable std::vector<std::pair<Cell, int>> label_queue_;
  // segmentLength()'s search along the frontier.
  mutable VisitMarks segment_seen_;
  mutable std::vector<Cell> segment_queue_;
  CellCounts counts_;  ///< scratch of collectCandidates() and addFrontierMass(), each in one call
  Vec2 goal_m_ = Vec2::Zero();
  Vec2 goal_anchor_ = Vec2::Zero();
};

}  // namespace roomscout
