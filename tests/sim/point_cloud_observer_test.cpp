#include "roomscout/sim/point_cloud_observer.hpp"

#include <gtest/gtest.h>

#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

/// Drives the observer along +x at 0.2 m/s for `seconds`, 20 steps per second.
void drive(PointCloudObserver& observer, const WorldModel& model, double seconds) {
  const OccupancyGrid grid(GridGeometry(Vec2::Zero(), 0.05, 10, 10));
  for (int i = 0; i <= static_cast<int>(seconds * 20); ++i) {
    const double t = i * 0.05;
    observer.onStep(EpisodeSnapshot{t, Pose2{2.0 + 0.2 * t, 2.5, 0.0}, grid, model, false, {}});
  }
  observer.onFinish(
      EpisodeSnapshot{seconds, Pose2{2.0 + 0.2 * seconds, 2.5, 0.0}, grid, model, true, {}});
}

TEST(PointCloudObserver, InsertsKeyframesOnlyAndTimesThem) {
  const WorldModel model(testing::twoRooms());
  PointCloudObserver observer(model, {}, 1);
  EXPECT_EQ(observer.name(), "pointcloud");
  drive(observer, model, 20.0);  // 4 m at 10 Hz: 201 revolutions, keyframes at 0, 1, 2, 3, 4 m
  EXPECT_EQ(observer.scans(), 201);
  EXPECT_EQ(observer.keyframes(), 5);
  EXPECT_EQ(observer.updateTimes_ms().size(), 5u);
  for (double ms : observer.updateTimes_ms()) EXPECT_GT(ms, 0.0);
  EXPECT_GT(observer.map().size(), 5000u);
  for (const Eigen::Vector3f& p : observer.map().points()) {
    ASSERT_TRUE(observer.columns().nearSurface(p.cast<double>(), 0.05)) << p.transpose();
  }
  EXPECT_NE(observer.description().find("keyframes: every 1 m, or 0.2 rad after 0.1 m"),
            std::string::npos);
}

TEST(PointCloudObserver, FloorAndCeilingKeptByDefaultOrRemoved) {
  const WorldModel model(testing::twoRooms());
  PointCloudObserverOptions options;
  PointCloudObserver kept(model, options, 1);
  options.remove_floor_ceiling = true;
  PointCloudObserver removed(model, options, 1);
  drive(kept, model, 5.0);
  drive(removed, model, 5.0);
  auto count = [](const PointCloudObserver& o, double lo, double hi) {
    int n = 0;
    for (const Eigen::Vector3f& p : o.map().points()) n += p.z() >= lo && p.z() <= hi;
    return n;
  };
  EXPECT_GT(count(kept, -0.01, 0.01), 1000);
  EXPECT_GT(count(kept, 2.49, 2.51), 100);
  // What remains at those heights is the foot and top of the walls.
  EXPECT_LT(count(removed, -0.01, 0.01), count(kept, -0.01, 0.01) / 20);
  EXPECT_LT(count(removed, 2.49, 2.51), count(kept, 2.49, 2.51) / 5);
  EXPECT_EQ(count(kept, 0.3, 2.2), count(removed, 0.3, 2.2));  // the walls are the same
  EXPECT_NE(removed.description().find("removed"), std::string::npos);
}

TEST(PointCloudObserver, EveryScanWhenAsked) {
  const WorldModel model(testing::twoRooms());
  PointCloudObserverOptions options;
  options.keyframes.every_scan = true;
  options.lidar.rate_hz = 5.0;
  PointCloudObserver observer(model, options, 1);
  drive(observer, model, 2.0);
  EXPECT_EQ(observer.scans(), 11);
  EXPECT_EQ(observer.keyframes(), 11);
  EXPECT_EQ(observer.updateTimes_ms().size(), 11u);
}

}  // namespace
}  // namespace roomscout::sim
