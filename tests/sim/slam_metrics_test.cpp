#include "roomscout/sim/slam_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace roomscout::sim {
namespace {

TEST(TrajectoryError, OfAHandMadeTrajectory) {
  // Errors of 0, 0.3 and 0.4 m; headings off by 0, 0.1 and -0.2 rad (the last across the
  // +-pi seam, which must wrap).
  const std::vector<TrajectorySample> t = {
      {0.0, Pose2{0, 0, 0}, Pose2{0, 0, 0}},
      {1.0, Pose2{1, 0, 0.5}, Pose2{1.3, 0, 0.6}},
      {2.0, Pose2{2, 0, M_PI - 0.1}, Pose2{2, 0.4, -M_PI + 0.1}},
  };
  // Third heading error: (-pi + 0.1) - (pi - 0.1) wraps to 0.2.
  const TrajectoryError e = trajectoryError(t);
  EXPECT_EQ(e.samples, 3u);
  EXPECT_NEAR(e.rmse_m, std::sqrt((0.09 + 0.16) / 3.0), 1e-12);
  EXPECT_NEAR(e.max_m, 0.4, 1e-12);
  EXPECT_NEAR(e.heading_rmse_rad, std::sqrt((0.01 + 0.04) / 3.0), 1e-12);
  EXPECT_EQ(trajectoryError({}).samples, 0u);
  EXPECT_EQ(trajectoryError({}).rmse_m, 0.0);
}

}  // namespace
}  // namespace roomscout::sim
