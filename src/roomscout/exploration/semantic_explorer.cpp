#include "roomscout/exploration/detail/semantic_explorer.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

void GoalPersistenceOptions::validate() const {
  auto finiteAtLeast = [](double v, double lo) { return std::isfinite(v) && v >= lo; };
  if (!finiteAtLeast(goal_min_unknown_m2, 0.0))
    throw OptionError("semantic.goal_min_unknown_m2 must be >= 0");
  if (!finiteAtLeast(replan_period_s, 0.0))
    throw OptionError("semantic.replan_period_s must be >= 0");
  if (!finiteAtLeast(switch_margin, 0.0)) throw OptionError("semantic.switch_margin must be >= 0");
  if (!finiteAtLeast(blacklist_radius_m, 0.0))
    throw OptionError("semantic.blacklist_radius_m must be >= 0");
}

void SemanticExplorerOptions::validate() const {
  tree.validate();
  score.validate();
  slivers.validate();
  goal.validate();
  rooms.validate();
  end.validate();
}

SemanticExplorerOptions SemanticExplorerOptions::paper() {
  SemanticExplorerOptions o;
  // The tree of improved_rrt (ImprovedRrtOptions: eta_m 1 m, 100 iterations /s).
  o.tree.eta_m = 1.0;
  o.tree.iterations_per_s = 100.0;
  // C as the paper states it: the Euclidean distance.
  o.score.geodesic_cost = false;
  // Every addition of `semantic` off (see the header).
  o.slivers.min_unknown_m2 = 0.0;
  o.slivers.min_frontier_m = 0.0;
  o.slivers.pocket_area_m2 = 0.0;
  o.slivers.pocket_area_fraction = 0.0;
  o.rooms.label_search_m = 0.0;
  o.rooms.hub_min_neighbours = 0;
  o.score.next_room_cost_factor = 1.0;
  o.score.mass_weight = 0.0;
  o.score.heading_weight = 0.0;
  o.score.segment_weight = 0.0;
  o.rooms.leaf_rooms = false;
  o.end.idle_end_s = 0.0;
  // improved_rrt's end test, pocket search included (its min_unknown_area_m2): without the end
  // phase nothing else leaves out the frontier cells of cupboards and wall cracks that no tree
  // point leads to, and the robot would wait for the end test until the time limit.
  o.end.end_pocket_area_m2 = 4.0;
  // Kept to run and to end, at `semantic`'s values: goal persistence (goal_min_unknown_m2,
  // replan_period_s, switch_margin), the blacklist (blacklist_radius_m) and the end test
  // (end_check_period_s, end_checks, end_min_frontier_cells, observed_radius_m, and the pocket
  // search above).
  return o;
}

std::vector<ParameterRef> SemanticExplorerOptions::parameters() {
  return {
      {"k", &tree.k,
       "weight of t, the time since the robot's room last changed, in P(P_sem) = kt/(1+kt) "
       "(paper Eq. 1); 0 = P_rad only, uniform sampling [1/s]"},
      {"gain_weight", &score.gain_weight,
       "w_g: weight of G, the (unknown - occupied) area in the square of half-side "
       "gain_half_side_m around the point [1/m^2]"},
      {"cost_weight", &score.cost_weight,
       "w_c: weight of C, the distance from the robot to the point (see geodesic_cost) [1/m]"},
      {"room_reward", &score.room_reward,
       "A: added to the score of a point whose anchor lies in the robot's room, subtracted "
       "elsewhere (a point in no room counts as elsewhere); 0 = plain score"},
      {"gain_half_side_m", &score.gain_half_side_m,
       "half-side of the square around a point in which G, slivers and the goal's persistence "
       "are measured [m]"},
      {"min_unknown_m2", &slivers.min_unknown_m2,
       "slivers: a point with less unknown area in its square is a goal only once idle "
       "(idle_end_s), and a frontier cell with less is no P_sem; 0 = off [m^2]"},
      {"goal_min_unknown_m2", &goal.goal_min_unknown_m2,
       "goal persistence: the goal is kept until its square holds less unknown area than this "
       "(or it is reached, fails or turns lethal); 0 = until then [m^2]"},
      {"min_frontier_m", &slivers.min_frontier_m,
       "slivers: a point with less frontier (free cells next to unknown x cell size) in its "
       "square is a goal only once idle, and the goal's square counts as explored with less; 0 "
       "= off [m]"},
      {"pocket_area_m2", &slivers.pocket_area_m2,
       "slivers: a point opening onto less enclosed unknown, non-lethal area (4-connected) is a "
       "goal only once idle, and the end phase skips such cells; 0 = off [m^2]"},
      {"pocket_area_fraction", &slivers.pocket_area_fraction,
       "once idle, a pocket must also be smaller than this fraction of the known free area (in a "
       "small flat a wedge of floor seen past a door jamb is no cupboard); 0 = pocket_area_m2 "
       "alone"},
      {"geodesic_cost", &score.geodesic_cost,
       "C is the path length past the costmap's lethal cells; false = the Euclidean distance, "
       "as in the paper"},
      {"eta_m", &tree.eta_m, "tree step [m]"},
      {"iterations_per_s", &tree.iterations_per_s, "tree iterations per simulated second [1/s]"},
      {"replan_period_s", &goal.replan_period_s,
       "period at which the goal may be replaced while the robot drives to it [s]"},
      {"switch_margin", &goal.switch_margin,
       "another point must beat the goal's score by this much to replace it"},
      {"label_search_m", &rooms.label_search_m,
       "a free cell the segmentation has not labelled yet takes the room of the nearest labelled "
       "cell this far through free cells; 0 = off (an unlabelled cell is in no room) [m]"},
      {"blacklist_radius_m", &goal.blacklist_radius_m,
       "reached or failed goals drop frontier points this close [m]"},
      {"end_check_period_s", &end.end_check_period_s, "period of the end test [s]"},
      {"end_checks", &end.end_checks, "consecutive failing end tests that end the exploration"},
      {"end_min_frontier_cells", &end.end_min_frontier_cells,
       "an end test fails when fewer reachable frontier cells are left"},
      {"end_pocket_area_m2", &end.end_pocket_area_m2,
       "the end test leaves out, for good, frontier cells opening onto less enclosed unknown, "
       "non-lethal area (improved_rrt's min_unknown_area_m2, searched every 10 s); 0 = off "
       "[m^2]"},
      {"observed_radius_m", &end.observed_radius_m,
       "the end test and the end phase ignore frontier cells that stayed unknown with the robot "
       "this close [m]"},
      {"idle_end_s", &end.idle_end_s,
       "with nothing to assign for this long the robot takes its room's slivers, then visits "
       "the remaining reachable frontier cells (end phase); 0 = off: it waits for the tree and "
       "the end test [s]"},
      {"max_iterations_per_call", &tree.max_iterations_per_call,
       "cap on the owed tree iterations run in one call"},
      {"hub_min_neighbours", &rooms.hub_min_neighbours,
       "a room with this many neighbouring rooms is a hub (a hallway): no +-A there, P_sem near "
       "the robot (hub_sample_radius_m), C weighed by next_room_cost_factor; 0 = off"},
      {"next_room_cost_factor", &score.next_room_cost_factor,
       "choosing the next room (in a hub, or no point left in the room but slivers): C weighs "
       "this many times w_c; 1 = off"},
      {"hub_sample_radius_m", &rooms.hub_sample_radius_m,
       "in a hub, P_sem is drawn from the frontier cells (of any room) in the square of this "
       "half-side around the robot; 0 = no P_sem in a hub [m]"},
      {"heading_weight", &score.heading_weight,
       "S -= heading_weight (1 - cos d) / 2, d the angle between the robot's heading and the "
       "line to the point: turning back costs this much (the current goal never pays it); 0 = "
       "off"},
      {"segment_weight", &score.segment_weight,
       "S += segment_weight min(L, segment_cap_m), L the length of the frontier segment the "
       "point opens onto; 0 = off [1/m]"},
      {"segment_cap_m", &score.segment_cap_m, "cap on L, the frontier segment's length [m]"},
      {"mass_weight", &score.mass_weight,
       "choosing the next room: S += mass_weight min(M, mass_cap_m), M the frontier (free cells "
       "next to unknown x cell size) in the square of half-side mass_half_side_m around the "
       "point; 0 = off [1/m]"},
      {"mass_half_side_m", &score.mass_half_side_m, "half-side of the square M is counted in [m]"},
      {"mass_cap_m", &score.mass_cap_m, "cap on M [m]"},
      {"leaf_rooms", &rooms.leaf_rooms,
       "a room whose only neighbour is the current room, while the current room has another, "
       "counts as part of it (+A for its points, P_sem from its frontier); false = off"},
  };
}

SemanticExplorer::SemanticExplorer(std::uint64_t seed, const SemanticExplorerOptions& options,
                                   std::string name)
    : options_(options),
      name_(std::move(name)),
      tree_(seed, options.tree),
      rooms_(options.rooms),
      scorer_(options.score, options.slivers),
      cost_(options.score.geodesic_cost),
      end_(options.end, options.slivers) {}

bool SemanticExplorer::blacklisted(const Vec2& p) const {
  const double r2 = options_.goal.blacklist_radius_m * options_.goal.blacklist_radius_m;
  return std::any_of(blacklist_.begin(), blacklist_.end(),
                     [&](const Vec2& b) { return (b - p).squaredNorm() < r2; });
}

void SemanticExplorer::onGoalReached(const Vec2& goal_m) { onGoalFailed(goal_m); }

void SemanticExplorer::onGoalFailed(const Vec2& goal_m) {
  // Reached while still unknown (unobservable from there) or unreachable: not sent again.
  if (goal_ && (goal_m - goal_->p).norm() < 1e-9) blacklist_.push_back(goal_m);
  goal_.reset();
  end_.onGoalDone(goal_m);
}

void SemanticExplorer::followGeometry(const ExplorationInput& input, const GridGeometry& previous) {
  tree_.followGeometry(input);
  end_.followGeometry(previous, input.grid.geometry());
}

void SemanticExplorer::dropFinishedGoal(const ExplorationInput& input) {
  // The goal is kept until its square is explored, not merely until its own cell is seen: the
  // laser's edge recedes as the robot drives, so the first unknown cell of an edge is seen long
  // before the space behind it. A goal dropped because its cell turned lethal (a wall seen
  // beside it from close by) is blacklisted: walls seen only from close by can fade back to
  // unknown once the robot leaves, the tree then found the same cell again, and on one
  // HouseExpo plan the robot shuttled between two such points until its time limit.
  if (!goal_) return;
  const GridGeometry& g = input.grid.geometry();
  const Cell c = g.cellOf(goal_->p);
  if (g.contains(c) && input.costmap.isLethal(g.index(c))) {
    blacklist_.push_back(goal_->p);
    goal_.reset();
    return;
  }
  bool explored = blacklisted(goal_->p) || !g.contains(c);
  if (!explored) {
    const SquareAreas a = squareAreas(input.grid, goal_->p, options_.score.gain_half_side_m,
                                      options_.slivers.frontierCellsWanted(g.resolution_m()));
    explored = exhausted(a, options_.slivers, options_.goal.goal_min_unknown_m2, g.resolution_m());
  }
  if (explored) goal_.reset();
}

Decision SemanticExplorer::decide(const ExplorationInput& input) {
  const GridGeometry& g = input.grid.geometry();
  if (const auto previous = geometry_.update(g)) followGeometry(input, *previous);
  tree_.plant(input);
  end_.observe(input);
  rooms_.update(input);
  // The end phase (see SemanticEndPhase): once in it, the tree stops growing.
  if (end_.active()) return end_.decide(input, cost_);
  rooms_.collectSampleCells(input, options_.score.gain_half_side_m,
                            options_.slivers.min_unknown_m2);
  const auto isBlacklisted = [this](const Vec2& p) { return blacklisted(p); };
  tree_.grow(input, rooms_.sampleCells(), rooms_.timeInRoom_s(), isBlacklisted);
  dropFinishedGoal(input);
  tree_.dropStale(input, isBlacklisted);
  if (end_.endTest(input)) return Decision::done();
  const bool periodic = input.time_s - last_eval_s_ >= options_.goal.replan_period_s - 1e-9;
  if (!tree_.points().empty() && (!goal_ || periodic)) {
    last_eval_s_ = input.time_s;
    // Slivers are not worth the trip while anything else is left. When nothing else was found
    // while idling for idle_end_s, rather than end short of the last percent, the robot takes
    // the best sliver in the current room that it has not come within observed_radius_m of (the
    // corners of a room the laser saw from its middle, say), then the next, until none is left.
    // Other rooms' slivers and those looked at from close by stay out, so that it does not tour
    // the building's furniture faces at the end. A sliver goal's square is explored already, so
    // it is chosen afresh each call.
    const bool slivers_wanted = !goal_ && (chasing_slivers_ || end_.idle());
    const SemanticScorer::Choice choice = scorer_.choose(
        input, tree_.points(), goal_, rooms_, end_.observed(), slivers_wanted, end_.idle(), cost_);
    if (choice.point &&
        (!goal_ || choice.score > choice.goal_score + options_.goal.switch_margin)) {
      goal_ = tree_.points()[*choice.point];
      chasing_slivers_ = choice.sliver;
    }
  }
  if (goal_) {
    end_.goalAssigned();
    return Decision::goal(goal_->p);
  }
  // Nothing to assign: wait where we are while the tree grows, or, idle for idle_end_s, the
  // end phase.
  if (end_.nothingToAssign(input.time_s)) return end_.nextCell(input, cost_);
  if (const auto wait = nearestGoalCell(input.grid, input.costmap, input.robot.position(), 3.0))
    return Decision::goal(*wait);
  return Decision::done();
}

std::vector<Vec2> SemanticExplorer::candidateGoals() const {
  std::vector<Vec2> out;
  out.reserve(tree_.points().size());
  for (const FrontierPoint& f : tree_.points()) out.push_back(f.p);
  return out;
}

}  // namespace roomscout
