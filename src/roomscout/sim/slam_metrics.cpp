#include "roomscout/sim/slam_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace roomscout::sim {

TrajectoryError trajectoryError(const std::vector<TrajectorySample>& trajectory) {
  TrajectoryError e;
  e.samples = trajectory.size();
  if (trajectory.empty()) return e;
  double sum_sq = 0.0, sum_sq_heading = 0.0;
  for (const TrajectorySample& s : trajectory) {
    const double d = (s.estimate.position() - s.pose.position()).norm();
    const double h = wrapAngle(s.estimate.yaw_rad - s.pose.yaw_rad);
    sum_sq += d * d;
    sum_sq_heading += h * h;
    e.max_m = std::max(e.max_m, d);
  }
  const double n = static_cast<double>(trajectory.size());
  e.rmse_m = std::sqrt(sum_sq / n);
  e.heading_rmse_rad = std::sqrt(sum_sq_heading / n);
  return e;
}

}  // namespace roomscout::sim
