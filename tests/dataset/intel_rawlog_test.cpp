// The Intel Research Lab log (the shared data set's slam/intel.rawlog): the reader's counts,
// and `roomscout slam` over the whole log with the best SLAM available, whose map must fit the
// scans better than odometry's.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"
#include "dataset_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/slam/rawlog.hpp"
#include "roomscout/slam/slam.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

TEST(IntelRawlogTest, ReaderFindsEveryScanWithItsLaserAndOdometry) {
  ROOMSCOUT_DATASET_DIR(data);
  const slam::Rawlog log = slam::readRawlog(data / "slam" / "intel.rawlog");
  EXPECT_EQ(log.entries, 2 * 2726u);
  EXPECT_FALSE(log.observations_only);
  ASSERT_EQ(log.scans.size(), 2726u);
  EXPECT_EQ(log.odometry_readings, 2726u);
  EXPECT_EQ(log.corrupt_beams, 0u);
  double driven_m = 0.0;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const LaserScan& s = log.scans[i].scan;
    ASSERT_EQ(s.ranges_m.size(), 180u);
    EXPECT_NEAR(s.angle_min_rad, -M_PI / 2, 1e-6);
    EXPECT_NEAR(s.angle_increment_rad, M_PI / 179, 1e-6);
    EXPECT_NEAR(s.range_max_m, 30.0, 0.5);
    if (i > 0) {
      const Pose2& a = log.scans[i - 1].T_odom_robot;
      const Pose2& b = log.scans[i].T_odom_robot;
      driven_m += std::hypot(b.x_m - a.x_m, b.y_m - a.y_m);
    }
  }
  const Pose2& first = log.scans.front().T_odom_robot;
  EXPECT_EQ(first.x_m, 0.0);
  EXPECT_EQ(first.y_m, 0.0);
  EXPECT_NEAR(driven_m, 506.0, 25.0);  // "about 506 m of driving" (the data README)
}

TEST(IntelRawlogTest, GraphSlamMapFitsTheScansTwiceAsWellAsOdometryWithLoopClosures) {
  ROOMSCOUT_DATASET_DIR(data);
  test::TempDir dir;
  const fs::path out = dir / "intel";
  const std::string mode = "graph";
  const test::CommandResult r =
      test::runRoomscout("slam --rawlog " + (data / "slam" / "intel.rawlog").string() + " --out " +
                             out.string() + " --mode " + mode + " --seed 1",
                         dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(test::Contains(r.output, "2726 scans"));
  for (const char* name : {"map.pgm", "map.yaml", "map.png", "odometry_map.pgm",
                           "odometry_map.yaml", "odometry_map.png", "poses.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  }
  std::ifstream in(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  EXPECT_EQ(summary.at("scans"), 2726);
  EXPECT_EQ(summary.at("mode"), mode);
  EXPECT_EQ(summary.at("update_ms").at("count"), summary.at("slam_updates"));
  const double slam_m = summary.at("maps").at("slam").at("consistency").at("mean_distance_m");
  const double odometry_m =
      summary.at("maps").at("odometry").at("consistency").at("mean_distance_m");
  // The figure: at most half the odometry map's. (Its other target, 5 cm, is not met:
  // the graph SLAM's map stands at about 9 cm; docs/slam.md.)
  EXPECT_LT(slam_m, 0.5 * odometry_m) << mode;
  EXPECT_GT(summary.at("graph").at("loop_closures").get<int>(), 100);
  std::ifstream poses(out / "poses.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(poses, line);) ++lines;
  EXPECT_EQ(lines, 2727u);  // a header and a row per scan
}

}  // namespace
}  // namespace roomscout
