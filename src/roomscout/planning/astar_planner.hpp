#pragma once
// Grid A* over a Costmap: 8-connected, octile heuristic, no corner cutting past lethal cells.

#include <optional>
#include <vector>

#include "roomscout/planning/costmap.hpp"
#include "roomscout/planning/path.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct AStarOptions {
  double goal_tolerance_m = 0.3;
  bool allow_unknown = true;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Why planning failed, for the caller's bookkeeping.
enum class PlanStatus { kFound, kStartBlocked, kGoalBlocked, kNoPath };

struct PlanResult {
  PlanStatus status = PlanStatus::kNoPath;
  Path path;  ///< valid when status == kFound
};

/// Reusable planner; keeps its scratch buffers between calls (not thread-safe).
class AStarPlanner {
 public:
  /// Throws OptionError when `options` are invalid.
  explicit AStarPlanner(const AStarOptions& options = {});

  /// Plans from `start_m` to `goal_m`. If the start cell is lethal (the robot brushed an
  /// inflated wall), the search starts from the nearest traversable cell within 0.5 m.
  PlanResult plan(const Costmap& costmap, const Vec2& start_m, const Vec2& goal_m);

  /// True when every waypoint of `path` from index `from` on is still traversable.
  static bool pathIsClear(const Costmap& costmap, const Path& path, std::size_t from = 0);

 private:
  /// Not lethal, and not unknown unless options_.allow_unknown.
  bool traversable(const Costmap& costmap, std::size_t index) const;
  /// `around` if traversable, else the traversable cell whose centre is nearest `p_m` within
  /// `radius_m`, if any.
  std::optional<Cell> nearestTraversable(const Costmap& costmap, const Vec2& p_m, Cell around,
                                         double radius_m) const;
  /// A* between two traversable cells; the cells of the cheapest path, start first.
  std::optional<std::vector<Cell>> search(const Costmap& costmap, Cell start, Cell goal);

  AStarOptions options_;
  std::vector<float> g_;
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_stamp_ = 0;
};

}  // namespace roomscout
