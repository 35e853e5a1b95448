#include "roomscout/exploration/detail/semantic_end_phase.hpp"

#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/grid_remap.hpp"
#include "roomscout/exploration/frontier_cells.hpp"

namespace roomscout {

void SemanticEndPhaseOptions::validate() const {
  auto finiteAtLeast = [](double v, double lo) { return std::isfinite(v) && v >= lo; };
  if (!(std::isfinite(end_check_period_s) && end_check_period_s > 0.0))
    throw OptionError("semantic.end_check_period_s must be > 0");
  if (end_checks < 1 || end_min_frontier_cells < 1) {
    throw OptionError("semantic: end_checks and end_min_frontier_cells must be >= 1");
  }
  if (!finiteAtLeast(end_pocket_area_m2, 0.0))
    throw OptionError("semantic.end_pocket_area_m2 must be >= 0");
  if (!finiteAtLeast(observed_radius_m, 0.0))
    throw OptionError("semantic.observed_radius_m must be >= 0");
  if (!finiteAtLeast(idle_end_s, 0.0)) throw OptionError("semantic.idle_end_s must be >= 0");
}

void SemanticEndPhase::observe(const ExplorationInput& input) {
  markDisc(observed_, input.grid.geometry(), input.robot.position(), options_.observed_radius_m);
  idle_ = options_.idle_end_s > 0.0 && idle_since_s_ >= 0.0 &&
          input.time_s - idle_since_s_ >= options_.idle_end_s - 1e-9;
}

void SemanticEndPhase::followGeometry(const GridGeometry& previous, const GridGeometry& geometry) {
  observed_ = remapCells(observed_, previous, geometry);
  if (end_cell_ && !geometry.contains(*end_cell_)) end_cell_.reset();
}

bool SemanticEndPhase::endTest(const ExplorationInput& input) {
  if (input.time_s - last_end_check_s_ < options_.end_check_period_s - 1e-9) return false;
  last_end_check_s_ = input.time_s;
  // improved_rrt's pocket search (its opening and period), when end_pocket_area_m2 is on:
  // frontier cells opening onto a pocket are left out of the test for good, as those the robot
  // came near are.
  EndTestPockets pockets;
  pockets.min_area_m2 = options_.end_pocket_area_m2;
  const std::size_t cells =
      countEndTestFrontierCells(input.grid, input.costmap, 4, observed_, input.robot.position(),
                                static_cast<std::size_t>(options_.end_min_frontier_cells), pockets,
                                input.time_s, last_end_pocket_check_s_);
  if (cells < static_cast<std::size_t>(options_.end_min_frontier_cells)) {
    return ++failed_end_checks_ >= options_.end_checks;
  }
  failed_end_checks_ = 0;
  return false;
}

bool SemanticEndPhase::nothingToAssign(double time_s) {
  if (idle_since_s_ < 0.0) idle_since_s_ = time_s;
  if (idle_) active_ = true;
  return active_;
}

Decision SemanticEndPhase::decide(const ExplorationInput& input, TravelCost& cost) {
  // Tree points found on the way (on walls the laser only grazed, mostly) restarted the idling
  // every idle_end_s, so the tree no longer grows in the end phase.
  if (endTest(input)) return Decision::done();
  return nextCell(input, cost);
}

void SemanticEndPhase::onGoalDone(const Vec2& goal_m) {
  if (end_cell_ && (goal_m - *end_cell_).norm() < 1e-9) {
    end_cells_done_.push_back(*end_cell_);
    end_cell_.reset();
  }
}

Decision SemanticEndPhase::nextCell(const ExplorationInput& input, TravelCost& cost) {
  const GridGeometry& g = input.grid.geometry();
  // A cell reached, or failed from close by, was looked at: the disc around it is done. One
  // failed from afar (the stall watchdog fails whatever goal is current when the robot has
  // idled, even one just set) says nothing of its neighbours, so only the cell is done.
  const Vec2 robot = input.robot.position();
  for (const Vec2& f : end_cells_done_) {
    const bool near = (f - robot).norm() <= options_.observed_radius_m;
    markDisc(observed_, g, f, near ? options_.observed_radius_m : 0.5 * g.resolution_m());
  }
  end_cells_done_.clear();
  if (end_cell_ && g.contains(*end_cell_)) {
    const std::size_t i = g.index(g.cellOf(*end_cell_));
    if (input.grid.isUnknown(i) && !observed_[i] && !input.costmap.isLethal(i))
      return Decision::goal(*end_cell_);
  }
  end_cell_.reset();
  const std::vector<Cell> cells =
      reachableFrontierCells(input.grid, input.costmap, 4, &observed_, &robot);
  // Not those opening onto a pocket (relative to the map by now: the robot is idle).
  std::vector<std::uint8_t> pockets;
  if (slivers_.pocket_area_m2 > 0.0) {
    markUnknownPockets(pockets, input.grid, input.costmap, cells,
                       slivers_.pocketArea_m2(input.grid, idle_), kPocketOpening_m);
  }
  // Nearest by C (the path length with geodesic_cost): in a straight line the nearest cell may
  // lie behind a wall, in the next room.
  candidates_.clear();
  for (const Cell& c : cells) {
    if (pockets.empty() || !pockets[g.index(c)])
      candidates_.push_back({g.centerOf(c), 0, 0.0, false, false});
  }
  cost.apply(input, candidates_, 1.0);
  double best_m = std::numeric_limits<double>::infinity();
  for (const GoalCandidate& c : candidates_) {
    if (c.cost_m < best_m) {
      best_m = c.cost_m;
      end_cell_ = c.p;
    }
  }
  if (end_cell_) return Decision::goal(*end_cell_);
  return Decision::done();
}

}  // namespace roomscout
