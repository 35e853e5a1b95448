#pragma once
// A 2D pose graph solved by Ceres: poses joined by measured relative poses, each weighted by
// its standard deviations; constraints marked robust (loop closures) go through a Huber loss,
// so one wrong constraint cannot bend the whole graph. The back end of the graph SLAM, usable
// on its own.

#include <cstddef>
#include <vector>

#include "roomscout/core/geometry.hpp"

namespace roomscout::slam {

struct PoseGraphConstraint {
  int from = 0;
  int to = 0;
  Pose2 measured;      ///< `to` in `from`'s frame
  double sd_m = 0.05;  ///< of each translation component
  double sd_rad = 0.02;
  bool robust = false;  ///< through the Huber loss
};

struct PoseGraphOptions {
  /// Huber loss scale, in standard deviations: a robust constraint's residual counts
  /// quadratically up to this many standard deviations and linearly beyond.
  double huber_scale = 2.0;
  int max_iterations = 50;
};

class PoseGraph {
 public:
  explicit PoseGraph(PoseGraphOptions options = {}) : options_(options) {}

  /// Adds a pose with its initial estimate; returns its id (0, 1, ...).
  int addPose(const Pose2& initial);
  /// Adds a constraint; throws InvalidArgument for an unknown id, a non-finite measurement or
  /// a standard deviation that is not > 0.
  void addConstraint(const PoseGraphConstraint& constraint);
  /// Holds a pose where it is (at least one should be, or the graph floats).
  void fix(int id);

  /// Solves; returns false when Ceres reports no usable solution (the poses are then
  /// unchanged).
  bool optimise();

  const Pose2& pose(int id) const { return poses_.at(static_cast<std::size_t>(id)); }
  void setPose(int id, const Pose2& p) { poses_.at(static_cast<std::size_t>(id)) = p; }
  std::size_t size() const { return poses_.size(); }
  const std::vector<PoseGraphConstraint>& constraints() const { return constraints_; }

 private:
  PoseGraphOptions options_;
  std::vector<Pose2> poses_;
  std::vector<bool> fixed_;
  std::vector<PoseGraphConstraint> constraints_;
};

}  // namespace roomscout::slam
