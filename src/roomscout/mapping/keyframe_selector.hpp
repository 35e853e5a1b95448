#pragma once
// Decides which scans enter a keyframe-based map, as LIO-SAM does for its global map: a scan
// is a keyframe when the robot has moved distance_m or turned angle_rad since the last one
// (LIO-SAM's surroundingkeyframeAddingDistThreshold 1.0 m, ...AngleThreshold 0.2 rad).
// One deviation: a turn makes a keyframe only once the robot has also moved turn_min_move_m
// (0.1 m, two voxels of the default map). A 360-degree lidar with an exact pose sees the same
// surfaces from the same point whatever its heading; LIO-SAM needs turn keyframes for scan
// matching, a map with known poses does not. improved_rrt on large_office (seed 1) turns
// thousands of times on the spot or while creeping: 12909 keyframes by LIO-SAM's rule, 5331
// with 0.02 m, 3191 with 0.1 m, for 1074 m driven; see README "3D point cloud map" for the figures.

#include <optional>
#include <string>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct KeyframeOptions {
  bool every_scan = false;
  double distance_m = 1.0;
  double angle_rad = 0.2;
  double turn_min_move_m = 0.1;
  void validate() const;
  std::vector<ParameterRef> parameters();
  /// One line for run records, e.g. "keyframes: every 1 m or 0.2 rad (LIO-SAM rule)".
  std::string describe() const;
};

/// Not thread-safe. The first pose offered is always a keyframe.
class KeyframeSelector {
 public:
  explicit KeyframeSelector(const KeyframeOptions& options = {});
  const KeyframeOptions& options() const { return options_; }
  /// True when a scan taken at `T_map_robot` is a keyframe; it then becomes the last one.
  bool accept(const Pose2& T_map_robot);
  int keyframes() const { return keyframes_; }

 private:
  KeyframeOptions options_;
  std::optional<Pose2> last_;
  int keyframes_ = 0;
};

}  // namespace roomscout
