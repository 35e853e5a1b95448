#pragma once
// The paper's semantic-region-aware exploration (§III-C): an RRT frontier detector whose
// samples are drawn from the frontier of the robot's current room more and more often the
// longer the robot stays in it, and a goal score that rewards frontier points in that room,
// so the robot finishes the room it is in before it moves on.
//
// Frontier point generation (§III-C.1). One tree rooted at the start, as improved_rrt's (step
// eta_m, iterations_per_s per simulated second; 300 /s since session 24: L98 102.8 / 218.9 m
// against 105.8 / 222.7 in the two houses over seeds 1-40, 533.3 against 541.3 m in the office
// over seeds 1-30; eta 0.5 or 2 m were longer; docs/semantic_tuning.md, session 24). Each
// iteration draws its sampling point P_sap:
// - with probability 1 / (1 + k t): P_rad, uniform over the bounding box of the known cells;
// - with probability k t / (1 + k t): P_sem, drawn uniformly among the room's frontier cells
//   (known-free, non-lethal cells with an unknown 4-neighbour inside the current room and its
//   dead-end neighbours, see Leaf rooms below; in a hallway, those near the robot, see Hubs);
// t is the time since the robot's room last changed. When the room has no frontier cell left,
// P_rad is used. An extension toward P_sem takes the full step eta_m along its direction, so
// the edge crosses the frontier instead of stopping on its free side. An edge that reaches
// unknown space adds its first unknown point P_i to the frontier point set F.
// Once the robot has had no goal for idle_end_s (F holds nothing worth the trip), it turns to
// the slivers of its room, then to the end phase (see decide() and End below): uniform samples,
// all inside the known cells' box, seldom lead an edge across a frontier on the box's edge
// (the open end of a corridor), and without either one HouseExpo plan ended at 63 % explored.
//
// Evaluation (§III-C.2). For each P_i in F: G = (unknown - occupied) area in the square of
// half-side gain_half_side_m around P_i; C = the length of the shortest path from the robot
// past the costmap's lethal cells, searched on 0.1 m blocks (or, without geodesic_cost, the
// Euclidean distance, which makes a point behind a wall look near: L98 15 % longer in
// small_house, 10 % in large_office, 1 % shorter in medium_house; docs/semantic_tuning.md,
// session 11); S = w_g G - w_c C + A when P_i lies in the current room, - A otherwise. P_i
// itself is unknown, so its room is that of the known-free cell the edge left from (its
// anchor); an anchor in no room yet counts as outside. Free cells the segmentation has not
// labelled yet (seen since its last update, about a second ago: much of it frontier)
// take the room of the nearest labelled cell reached through free cells within label_search_m
// (session 21). With 0.5 m the fresh end of the corridor the robot drove along belonged to no
// room: P_sem was not drawn there and its points scored -A, so the robot turned back for the
// room's other frontier and came back once the segmentation had caught up (an Explore-Bench
// loop: three trips along the corridor). With 3.5 m (the laser's range), through free cells so
// that a room behind the corridor's wall does not claim it: L98 on the 50 HouseExpo plans 48.84
// against 50.59 m (seeds 1-3), on the six Explore-Bench maps 103.7 against 120.8 m (seeds
// 1-3), in the built-in worlds 111.0 / 238.1 / 561.3 against 111.9 / 243.0 / 572.0 m (seeds
// 1-20; the Euclidean nearest cell within 3.5 m, whose hub square grew with it: 114.5 / 240.1 /
// 566.3; docs/semantic_tuning.md, session 21).
// The best S among the points that are no slivers becomes the goal (slivers only at the very
// end, see decide()). A sliver has less than min_unknown_m2 of unknown space in its square, or
// less than min_frontier_m of frontier there (free cells next to unknown, times the cell size:
// once a room corner's outer walls are seen, the unknown space behind them still fills the
// square but cannot be seen from there; a goal trace found about a quarter of small_house's
// length driven to such corners, and without the test L98 was 11 / 3 / 8 % longer in the three
// built-in worlds, 9 % on the HouseExpo plans; docs/semantic_tuning.md, session 15; 1 m since
// session 22: a closet seen through its door no longer draws the robot in before the rooms
// are done, L98 104.5 / 213.2 / 530.9 m against 106.0 / 231.6 / 564.0 with 0.5 m, seeds 1-20,
// the HouseExpo and Explore-Bench plans level, the IPA building maps -3.4 %; 1.25 m and more
// made the small house 16 % longer, 0.75 m changed little), or
// opens onto a pocket: less than pocket_area_m2 of unknown, non-lethal space 4-connected to it
// within the known map (markUnknownPockets, as in the rrt end tests), mostly the inside of a
// cupboard or a wall whose face the laser only grazed, which no viewpoint shows. With pockets
// as goals the robot crossed the building for them (room revisits -14 / -21 / -28 % and T_done
// -5 / -13 / -16 % without; the price: a shadowed wedge of floor that small is left too, final
// rate 99.5 / 99.8 / 99.5 % instead of 99.9 / 99.9 / 99.8 %; docs/semantic_tuning.md, session
// 10). Once the robot has idled (below), a pocket must also be smaller than
// pocket_area_fraction of the known free area: in a flat of 38 m^2 a 0.7 m^2 wedge of floor
// seen past a door jamb is 2 % of the floor, and a HouseExpo plan ended at 97 % for it
// (session 18; before idling the threshold stays absolute: relative from the start, L98 in
// large_office was 2 % longer). The goal is re-evaluated when it is reached or fails, when its
// square is explored (it would be a sliver now: too little unknown space or frontier left) or
// its point lies in the inflation (then it is blacklisted: a wall seen only from close by can
// fade back to unknown, and one HouseExpo episode shuttled between two such goals until its
// time limit; session 24), and every replan_period_s while driving, when another point
// beats the goal's own score by switch_margin. The goal is not dropped as soon as its own cell
// is seen: the laser's edge recedes in front of the robot, and choosing afresh every time it
// does made the robot swing between points 3.5 m away in different directions (L98 -10 to
// -20 %, revisits about halved; docs/semantic_tuning.md, fourth pass).
//
// End: as improved_rrt (fewer than end_min_frontier_cells reachable frontier cells in
// end_checks consecutive checks, each end_check_period_s; cells the robot came within
// observed_radius_m of are ignored), or the end phase's end. End phase (session 18): once the
// robot has idled for idle_end_s with nothing to assign (no point, and no sliver left in the
// current room that it has not come close to, see decide()), it visits those reachable
// frontier cells, nearest by C first (by path since session 27: the nearest in a straight line
// may lie behind a wall; L98 unchanged to the digit on every map set, L_done -0.7 / -3.4 / -8.6
// m in the three built-in worlds), skipping the ones that open onto a pocket, and ends when none
// is left; tree points no longer become goals then (points found on a wall the laser only
// grazed restarted the idling every idle_end_s and one HouseExpo plan never ended). The tree
// misses wedges of rooms seen from their doors: a HouseExpo plan ended at 97.8 % without the
// phase; with it all 150
// HouseExpo episodes of seeds 1-3 reach 98 % (149 before), while T98 and L98 in the built-in
// worlds do not change (the phase begins after T98 there; T_done +2 / +22 / +8 %).
//
// Hubs. A room the semantic map gives hub_min_neighbours or more neighbouring rooms (a hallway,
// a corridor with doors along it) is a place to pass through, not to finish: while the robot
// is in one, no point gets +-A, so the plain score picks the next room, mostly the nearest
// one seen through a door. Finishing the hallway first (to its far end)
// left the rooms along it half seen, to be fetched at the end (small_house seed 1 at 80 %
// explored had four such rooms; mmpf none). With the rule (4 neighbours) L98 is 121.6 /
// 257.5 / 623.4 m against 120.6 / 289.9 / 632.9 in the three built-in worlds (10 seeds) and
// 52.0 against 53.4 m on the HouseExpo plans; revisits 11.1 / 25.9 / 65.1 against 10.8 /
// 27.9 / 56.5 (docs/semantic_tuning.md, session 16). P_sem in a hub (session 19) is a frontier
// cell of any room in the square of half-side hub_sample_radius_m around the robot, so that the
// tree reaches into the rooms beside the hallway first: uniform samples there mostly fed far
// rooms seen down the hallway, and the robot left near ones for later. The square was then
// 4 m plus the 0.5 m label search, now 4.5 m itself (the same square). With 4 m, L98 117.6 /
// 245.8 / 576.1 m against 117.3 / 248.3 / 605.9 without (seeds 1-10), T98 -0 / -1 / -5 %,
// revisits 10.7 / 29.1 / 66.8 against 11.6 / 31.9 / 69.5; HouseExpo seeds 1-3 51.10 against
// 51.16 m; 2 and 8 m were longer in the small house (+5 %), 6 m about as 4.
//
// Next room. When the robot chooses where to go next, in a hub or because its room has no
// point left but slivers, every point is outside its room and S is the plain gain-cost
// trade-off; there C weighs next_room_cost_factor times w_c, so the nearest room seen comes
// before a larger one further away: a room passed by is a room to come back to. Factor 3:
// L98 117.3 / 248.3 / 605.9 m against 121.6 / 257.5 / 623.4 in the three built-in worlds
// (seeds 1-10), revisits 9.9 / 21.8 / 60.8 against 11.1 / 25.9 / 65.1. Applied only in hubs, or
// with factors 2 or 5, it shortened the worlds less (docs/semantic_tuning.md, session 17).
//
// Heading (session 20). S -= heading_weight (1 - cos d) / 2, d the angle between the robot's
// heading and the line to the point: a point behind the robot costs up to heading_weight more
// than one ahead, so that of two points alike the robot takes the one it is driving toward
// instead of turning round (the zig-zag of session 19's traces). The current goal never pays
// it: the robot faces away from its goal wherever the path bends round a wall, and charging
// the goal then made one HouseExpo episode swing between two rooms until its time limit.
// Weight 8 (sweep 0 / 4 / 8 / 12 / 16, seeds 1-10): L98 111.9 / 243.0 / 572.0 m against
// 123.9 / 248.2 / 574.5 without (seeds 1-20; -9.7 / -2.1 / -0.5 %, T98 -10 / -2 / -1 %; the
// held-out seeds 11-20 alone -13 / -4 / -1 %); revisits to T98 8.6 / 17.1 / 48.0 against
// 8.8 / 15.1 / 46.4; HouseExpo seeds 1-3 150 of 150 at 98 %, L98 50.59 against 51.10 m
// (docs/semantic_tuning.md, session 20).
//
// Frontier segment (session 22). S += segment_weight min(L, segment_cap_m), L the length of the
// frontier segment beside P_i (its 8-connected free cells with an unknown 4-neighbour, times the
// cell size). The tree's points are single cells and G's 2 x 2 m square holds about as much
// unknown space behind a 0.8 m gap (a cupboard, a crack past a door jamb) as behind a wide
// opening onto unseen floor; the segment's length tells them apart, as a frontier's size does
// in explore_lite's cost (nearest_frontier). Weight 4 per metre up to 2 m (sweep of 1-4 and
// caps 2-6 m, seeds 1-10, with min_frontier_m 0.5 m then): L98 106.0 / 231.6 / 564.0 m against
// 111.0 / 238.1 / 561.3 without (seeds 1-20; -4.5 / -2.7 / +0.5 %); HouseExpo seeds 1-3 48.35
// against 48.84 m, 150 of 150 at 98 %; Explore-Bench seeds 1-3 103.7 against 103.7 m. Weight
// 2 up to 4 m was shorter in the office (544.0 m over seeds 1-20) but longer on the floor
// plans (HouseExpo seed 1 49.05 against 47.10, Explore-Bench seed 1 106.7 against 101.1;
// docs/semantic_tuning.md, session 22).
//
// Frontier mass (session 25). Choosing the next room (as above: in a hub, or no point left in
// the room but slivers), S += mass_weight min(M, mass_cap_m), M the frontier (free cells with
// an unknown 4-neighbour, times the cell size) in the square of half-side mass_half_side_m
// around P_i: of the places seen, the robot goes first to the one with the most left to see
// around it, as mmpf's potential sums every frontier weighted by its nearness, and the branch
// with a little left is not the one it must come back for (the small house's hallway end,
// session 24). Weight 1 per metre in a 6 x 6 m square, up to 10 m (sweep: weight 0.5 / 1 / 2,
// half-side 2 / 3 / 4 m, cap 5 / 10 / 20 m, seeds 1-40): L98 98.8 / 212.9 m against 102.8 / 218.9
// in the two houses (per seed -4.0 +- 1.7 / -6.0 +- 3.4 m), the office level (532.2 against
// 533.3 m, seeds 1-30), the ten IPA building maps 223.4 against 227.1 m (seed 1), the HouseExpo
// plans 48.36 against 47.73 m (seeds 1-3, per episode +0.63 +- 0.39 m, most of it on two of
// the larger plans; in hubs alone the term left them level, 47.78, but gained half as much in
// the houses). Every variant of the sweep was shorter in both houses, this one most; the same
// term for every decision (0.5 per metre) was not. Session 23 had measured it on ten seeds and
// not kept it (docs/semantic_tuning.md, session 25).
//
// Leaf rooms (session 26). A room whose only neighbour is the current room, while the current
// room has another (a bathroom off a bedroom, a room seen through its only door), counts as part
// of the current room: its points get +A and P_sem is drawn from its frontier too. Finished first
// and left by its other door, the current room left the dead end to be fetched at the end: in the
// small house the robot that saw the room east of the start room but finished the start room at
// its north end first (8 of seeds 1-20) drove 103 m to 98 % against 94 m for the rest. With the
// rule: L98 93.1 / 211.4 m against 98.8 / 212.9 in the two houses (seeds 1-40, per seed -5.7 +-
// 1.4 / -1.5 +- 3.5 m), 511.3 against 532.2 m in the office (seeds 1-30, -20.9 +- 7.2), 45.62
// against 48.36 m on the HouseExpo plans (seeds 1-3, per episode -2.74 +- 0.83 m; all 150 at
// 98 %). Two rooms with one door between them are no leaves of each other, so the room-first
// test keeps its meaning (docs/semantic_tuning.md, session 26).
//
// Without a semantic map (ExplorationInput::semantic null) no point is in a room: sampling is
// uniform and every point scores -A, i.e. the plain RRT score.
//
// Defaults, chosen by the sweep over the three built-in worlds documented in
// docs/semantic_tuning.md. The empty flats of the HouseExpo plans would take a smaller room
// reward (A 1: L98 -4.5 % there over seeds 1-3, but +1.6 / +3.0 / +4.4 % in the built-in
// worlds); A stays 3 (session 18).

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "roomscout/core/visit_marks.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/exploration/rrt_tree.hpp"

namespace roomscout {

struct SemanticExplorerOptions {
  double k = 0.1;                      ///< weight of the time in the room in P(P_sem) [1/s]
  double gain_weight = 3.0;            ///< w_g [1/m^2]
  double cost_weight = 1.0;            ///< w_c [1/m]
  double room_reward = 3.0;            ///< A: added inside the current room, subtracted outside
  double gain_half_side_m = 1.0;       ///< half-side of G's square [m]
  double min_unknown_m2 = 1.0;         ///< points with less unknown area in the square are
                                       ///< goals only when nothing else was found for
                                       ///< idle_end_s (slivers along walls, furniture faces,
                                       ///< far room corners)
  double min_frontier_m = 1.0;         ///< ... or less frontier (free cells next to unknown, x
                                       ///< the cell size) in the square: its unknown space lies
                                       ///< behind walls seen already; 0 = off [m]
  double pocket_area_m2 = 2.0;         ///< points opening onto less unknown, non-lethal area
                                       ///< (4-connected) count as slivers; 0 = off [m^2]
  double pocket_area_fraction = 0.01;  ///< once idle, a pocket must also be smaller than this
                                       ///< fraction of the known free area (in a small flat a
                                       ///< wedge of floor seen past a door jamb is no
                                       ///< cupboard); 0 = pocket_area_m2 alone
  bool geodesic_cost = true;           ///< C = path length through the costmap, not Euclidean
  double eta_m = 1.0;                  ///< tree step [m]
  double iterations_per_s = 300.0;     ///< tree iterations per simulated second
  double replan_period_s = 2.0;        ///< re-evaluation period while driving [s]
  double switch_margin = 6.0;          ///< another point must beat the goal's score by this
  double label_search_m = 3.5;         ///< unlabelled free cells take the room of the nearest
                                       ///< labelled cell this far through free cells (the
                                       ///< laser's range: the robot saw them from its room) [m]
  double blacklist_radius_m = 0.3;     ///< reached or failed goals drop points this close [m]
  double end_check_period_s = 1.0;     ///< period of the end test [s]
  int end_checks = 5;                  ///< consecutive failing end tests that end exploration
  int end_min_frontier_cells = 2;      ///< fewer reachable frontier cells fail the end test
  double observed_radius_m = 0.75;     ///< end test ignores frontier cells that stayed unknown
                                       ///< with the robot this close [m]
  double idle_end_s = 30.0;            ///< idling this long: the current room's slivers, then
                                       ///< the end phase [s]
  int max_iterations_per_call = 20000; ///< cap on owed iterations run in one call
  int hub_min_neighbours = 4;          ///< a room with this many neighbouring rooms is a hub:
                                       ///< there no +-A and P_sem near the robot; 0 = off
  double next_room_cost_factor = 3.0;  ///< choosing the next room (in a hub, or no point
                                       ///< left in the current room but slivers): C weighs
                                       ///< this many times w_c; 1 = off
  double hub_sample_radius_m = 4.5;    ///< in a hub, P_sem is drawn from the frontier cells
                                       ///< (of any room) in the square of this half-side
                                       ///< around the robot; 0 = no P_sem in a hub [m]
  double heading_weight = 8.0;         ///< S -= heading_weight (1 - cos d) / 2, d the angle
                                       ///< between the robot's heading and the line to the
                                       ///< point: turning back costs this much (the current
                                       ///< goal never pays it); 0 = off
  double segment_weight = 4.0;         ///< S += segment_weight min(L, segment_cap_m), L the
                                       ///< length of the frontier segment the point opens
                                       ///< onto [1/m]; 0 = off
  double segment_cap_m = 2.0;          ///< cap on L [m]
  double mass_weight = 1.0;            ///< choosing the next room: S += mass_weight min(M,
                                       ///< mass_cap_m), M the frontier around the point [1/m];
                                       ///< 0 = off
  double mass_half_side_m = 3.0;       ///< half-side of the square M is counted in [m]
  double mass_cap_m = 10.0;            ///< cap on M [m]
  bool leaf_rooms = true;              ///< a room whose only neighbour is the current room
                                       ///< counts as part of it: +A for its points, P_sem
                                       ///< from its frontier too

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
  /// The goal's square is explored (too little unknown space or frontier left), or the goal is
  /// blacklisted or off the grid. Lethal goals are dropped before this is asked (decide()).
  bool goalExplored(const ExplorationInput& input) const;
  bool blacklisted(const Vec2& p) const;
  /// A point that may become the goal (or the goal itself), while the points are scored.
  struct Candidate {
    Vec2 p;
    std::size_t point;    ///< index into points_ (points_.size() for the goal)
    double without_cost;  ///< S without the cost term: w_g G +- A
    bool sliver;
    bool goal;
    double cost_m = 0.0;  ///< C; infinite when unreachable (or, geodesic, when it cannot win)
    bool inside = false;  ///< in the current room (points only)
    std::size_t block = 0;  ///< geodesic C: the search block of p
  };
  /// Sets every candidate's C (see SemanticExplorerOptions::geodesic_cost); w_c is the weight
  /// the choice applies to C (the geodesic search stops once no open candidate can win).
  void cost(const ExplorationInput& input, std::vector<Candidate>& candidates, double w_c);
  /// Adds mass_weight min(M, mass_cap_m) to every candidate's without_cost, M the frontier in
  /// the square of half-side mass_half_side_m around it (see Frontier mass in the header).
  void addFrontierMass(const OccupancyGrid& grid, std::vector<Candidate>& candidates);
  bool endTest(const ExplorationInput& input);
  /// The end phase's goal: the reachable frontier cell (as the end test counts them) nearest by
  /// C that the robot has not come within observed_radius_m of and that opens onto no pocket,
  /// or none.
  std::optional<Vec2> endPhaseCell(const ExplorationInput& input);
  /// The pocket threshold now: pocket_area_m2, or once idle pocket_area_fraction of the known
  /// free area if that is less.
  double pocketArea_m2(const OccupancyGrid& grid) const;

  SemanticExplorerOptions options_;
  std::string name_;
  std::mt19937_64 rng_;
  std::unique_ptr<RrtTree> tree_;
  double grown_until_s_ = 0.0;
  double last_end_check_s_ = -1e9;
  int failed_end_checks_ = 0;
  double idle_since_s_ = -1.0;
  bool chasing_slivers_ = false;  ///< the goal is a sliver chosen after idle_end_s of idling
  bool end_phase_ = false;        ///< idled once with nothing to assign (see decide())
  std::optional<Vec2> end_cell_;  ///< the end phase's current frontier cell
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
  std::vector<float> dist_;                  ///< geodesic C: Dijkstra distances [m] ...
  VisitMarks dist_valid_;                    ///< ... valid where marked
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
