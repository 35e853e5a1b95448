#pragma once
// Turns a path into velocity commands for a unicycle robot (pure pursuit with rotate-in-place).

#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/planning/path.hpp"
#include "roomscout/planning/path_progress.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct PathFollowerOptions {
  double max_linear_speed_mps = 0.22;
  double max_angular_speed_radps = 2.84;
  double lookahead_m = 0.35;
  double goal_tolerance_m = 0.15;
  double rotate_in_place_rad = 0.8;
  double heading_gain = 2.5;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Linear and angular velocity command.
struct VelocityCommand {
  double linear_mps = 0.0;
  double angular_radps = 0.0;
};

/// The slow reverse that backs a blocked robot away from whatever it is pressed against.
inline VelocityCommand backOffCommand() { return VelocityCommand{-0.1, 0.0}; }

/// Follows one path at a time. Call setPath() for a new path, then compute() every control
/// step; reached() tells when the robot is within goal_tolerance_m of the path's end.
class PathFollower {
 public:
  /// Throws OptionError when `options` are invalid.
  explicit PathFollower(const PathFollowerOptions& options = {});

  void setPath(const Path& path);
  void clear();
  bool hasPath() const { return !progress_.empty(); }
  const Path& path() const { return progress_.path(); }
  /// Index of the waypoint nearest the robot that the follower has progressed to.
  std::size_t progressIndex() const { return progress_.index(); }

  VelocityCommand compute(const Pose2& robot);
  bool reached(const Pose2& robot) const;

 private:
  /// Pure-pursuit target: the first point along the path beyond the progress that lies
  /// lookahead_m from the robot, or the path's end.
  Vec2 carrot(const Vec2& robot_m) const;

  PathFollowerOptions options_;
  PathProgress progress_;  ///< searched within two lookaheads of the current progress
};

}  // namespace roomscout
