#include "roomscout/exploration/detail/nearest_frontier.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/detail/frontier_search.hpp"

namespace roomscout {

void NearestFrontierOptions::validate() const {
  if (!(potential_scale >= 0.0) || !(gain_scale >= 0.0)) {
    throw OptionError("nearest_frontier: potential_scale and gain_scale must be >= 0");
  }
  if (!(min_frontier_size_m >= 0.0))
    throw OptionError("nearest_frontier.min_frontier_size_m must be >= 0");
  if (!(planner_period_s >= 0.0))
    throw OptionError("nearest_frontier.planner_period_s must be >= 0");
  if (!(progress_timeout_s > 0.0))
    throw OptionError("nearest_frontier.progress_timeout_s must be > 0");
  if (!(max_centroid_offset_m > 0.0))
    throw OptionError("nearest_frontier.max_centroid_offset_m must be > 0");
  if (!(blacklist_radius_m >= 0.0))
    throw OptionError("nearest_frontier.blacklist_radius_m must be >= 0");
}

std::vector<ParameterRef> NearestFrontierOptions::parameters() {
  return {
      {"potential_scale", &potential_scale,
       "weight of the distance to a frontier (explore_lite's default)"},
      {"gain_scale", &gain_scale, "weight of a frontier's size (explore_lite's default)"},
      {"min_frontier_size_m", &min_frontier_size_m,
       "smallest frontier considered [m] (explore_lite: 0.75; a 0.5 m corridor's end must count)"},
      {"planner_period_s", &planner_period_s,
       "seconds between re-decisions while driving (explore_lite's 1 / planner_frequency)"},
      {"progress_timeout_s", &progress_timeout_s,
       "blacklist a goal after no progress for this long [s]"},
      {"blacklist_radius_m", &blacklist_radius_m,
       "goals within a box of this half-size around a failed goal are skipped [m] (explore_lite: 5 "
       "cells)"},
      {"max_centroid_offset_m", &max_centroid_offset_m,
       "a centroid farther than this from every cell of its frontier (an arc or ring around the "
       "robot) is replaced by the frontier's traversable cell nearest the robot [m]"},
  };
}

bool NearestFrontier::near(const std::vector<Vec2>& goals, const Vec2& p) const {
  return std::any_of(goals.begin(), goals.end(), [&](const Vec2& b) {
    return std::abs(b.x() - p.x()) < options_.blacklist_radius_m &&
           std::abs(b.y() - p.y()) < options_.blacklist_radius_m;
  });
}

namespace {

/// explore_lite drives to the frontier's centroid and lets move_base find the nearest
/// reachable spot. Two departures keep that from stalling here:
/// - our contract forbids goals in lethal cells, so a lethal centroid is replaced by the
///   traversable member cell nearest to it;
/// - an arc- or ring-shaped frontier (the robot in open space) has its centroid far from the
///   frontier itself, often under the robot, where explore_lite dithers until its progress
///   timeout; when the centroid is farther than `max_centroid_offset_m` from every member
///   cell, the traversable member nearest the robot is the goal instead.
/// In both cases members on the blacklist are passed over, so that one failed spot does not
/// drop a whole frontier (a ring around the robot is often a single frontier).
/// A centroid the robot failed to reach (`failed`) drops the frontier, as in explore_lite. One
/// a watchdog gave up on (`slow`) gives way to the traversable member nearest to it: the
/// progress watchdog measures progress as the straight-line distance to the frontier, so it
/// also gives up on goals whose path first leads away from them, round a wall; and the
/// runner's stall watchdog gives up on whichever goal is current when two frontiers, ranked
/// by that distance, take turns as the goal while the robot dithers between them.
template <typename Failed, typename Slow>
std::optional<Vec2> traversableTarget(const Frontier& f, const Costmap& costmap, const Vec2& robot,
                                      double max_centroid_offset_m, Failed&& failed, Slow&& slow) {
  const auto blacklisted = [&](const Vec2& p) { return failed(p) || slow(p); };
  const GridGeometry& g = costmap.geometry();
  double offset2 = std::numeric_limits<double>::infinity();
  for (const Cell& m : f.cells)
    offset2 = std::min(offset2, (g.centerOf(m) - f.centroid_m).squaredNorm());
  const bool ring = offset2 > max_centroid_offset_m * max_centroid_offset_m;
  const Cell c = g.cellOf(f.centroid_m);
  if (!ring && g.contains(c) && !costmap.isLethal(g.index(c))) {
    if (failed(f.centroid_m)) return std::nullopt;
    if (!slow(f.centroid_m)) return f.centroid_m;
  }
  const Vec2 reference = ring ? robot : f.centroid_m;
  std::optional<Vec2> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (const Cell& m : f.cells) {
    if (costmap.isLethal(g.index(m))) continue;
    const Vec2 p = g.centerOf(m);
    if (blacklisted(p)) continue;
    const double d = (p - reference).squaredNorm();
    if (d < best_d) {
      best_d = d;
      best = p;
    }
  }
  return best;
}

}  // namespace

Decision NearestFrontier::decide(const ExplorationInput& input) {
  const double res = input.grid.geometry().resolution_m();
  const auto min_cells =
      static_cast<std::size_t>(std::ceil(options_.min_frontier_size_m / res - 1e-9));
  const std::vector<Frontier> frontiers =
      searchFrontiers(input.grid, input.robot.position(), std::max<std::size_t>(1, min_cells));

  const Frontier* best = nullptr;
  Vec2 best_target = Vec2::Zero();
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Frontier& f : frontiers) {
    const double cost = options_.potential_scale * f.min_distance_m * res -
                        options_.gain_scale * static_cast<double>(f.size()) * res;
    if (cost >= best_cost) continue;
    const std::optional<Vec2> target = traversableTarget(
        f, input.costmap, input.robot.position(), options_.max_centroid_offset_m,
        [&](const Vec2& p) { return near(failed_, p); },
        [&](const Vec2& p) { return near(slow_, p); });
    if (!target) continue;
    best = &f;
    best_cost = cost;
    best_target = *target;
  }
  if (best == nullptr) return Decision::done();

  // explore_lite's progress watchdog: a goal whose frontier does not come closer within
  // progress_timeout_s is blacklisted and the next best is taken.
  const bool same_goal = has_previous_ && (previous_goal_m_ - best_target).norm() < 1e-9;
  if (!same_goal || previous_distance_m_ > best->min_distance_m) {
    previous_goal_m_ = best_target;
    previous_distance_m_ = best->min_distance_m;
    last_progress_s_ = input.time_s;
    has_previous_ = true;
  }
  if (input.time_s - last_progress_s_ > options_.progress_timeout_s) {
    slow_.push_back(best_target);
    has_previous_ = false;
    return decide(input);
  }
  return Decision::goal(best_target);
}

}  // namespace roomscout
