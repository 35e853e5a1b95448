#pragma once
// How far a robot's own estimate strays from the truth: the absolute trajectory error of its
// estimated poses against the true ones (the map's own errors: map_accuracy.hpp).

#include <cstddef>
#include <vector>

#include "roomscout/core/geometry.hpp"

namespace roomscout::sim {

/// The robot at one time: where it was, and where it believed it was (the same pose when it
/// is told the truth).
struct TrajectorySample {
  double time_s = 0.0;
  Pose2 pose;      ///< true
  Pose2 estimate;  ///< estimated
};

/// Absolute trajectory error over a trajectory. The estimate starts from the true start pose,
/// so the two frames coincide and no alignment is fitted.
struct TrajectoryError {
  std::size_t samples = 0;
  double rmse_m = 0.0;            ///< root mean square of the position errors [m]
  double max_m = 0.0;             ///< largest position error [m]
  double heading_rmse_rad = 0.0;  ///< root mean square of the wrapped heading errors [rad]
};

TrajectoryError trajectoryError(const std::vector<TrajectorySample>& trajectory);

}  // namespace roomscout::sim
