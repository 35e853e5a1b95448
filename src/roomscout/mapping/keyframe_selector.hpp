#pragma once
// Decides which scans enter a keyframe-based map, as LIO-SAM does for its global map: a scan
// is a keyframe when the robot has moved distance_m or turned angle_rad since the last one
// (LIO-SAM's surroundingkeyframeAddingDistThreshold 1.0 m, ...AngleThreshold 0.2 rad).

#include <optional>
#include <string>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout {

struct KeyframeOptions {
  bool every_scan = false;    ///< true: every scan is a keyframe (no selection)
  double distance_m = 1.0;    ///< translation since the last keyframe that makes a new one [m]
  double angle_rad = 0.2;     ///< rotation since the last keyframe that makes a new one [rad]
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
