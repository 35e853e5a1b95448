// A bench record: metrics.json's keys plus decimated trajectory and map stats; which fields are
// timing (excluded when comparing runs for determinism).

#include "roomscout/experiment/result_record.hpp"

#include <gtest/gtest.h>

namespace roomscout::experiment {
namespace {

RecordedEpisode fakeEpisode() {
  RecordedEpisode e;
  for (int i = 0; i <= 50; ++i) {
    const Pose2 p{0.01 * i, 0.0, 0.0};
    e.result.trajectory.push_back({0.2 * i, p, p});
  }
  e.metrics = {{"world", "file_name"},
               {"method", "rrt"},
               {"seed", 3},
               {"exploration_rate", 0.99},
               {"wall_time_s", 1.5},
               {"update_ms",
                {{"occupancy", {{"median", 0.1}, {"p95", 0.2}, {"count", 10}}},
                 {"semantic", {{"median", 5.0}, {"p95", 6.0}, {"count", 2}}}}}};
  e.file_bytes = {{"occupancy.pgm", 1000}, {"occupancy.yaml", 100}, {"pointcloud.pcd", 5000},
                  {"topology.json", 300},  {"semantic.json", 200},  {"semantic_labels.png", 50},
                  {"semantic.png", 7000},  {"metrics.json", 4000}};
  return e;
}

TEST(ResultRecord, HoldsMetricsTrajectoryAndMapStats) {
  const nlohmann::json r =
      makeResultRecord({"houseA", "/d/houseA.yaml", "houseexpo"}, fakeEpisode(),
                       {"abc123", "node1", "2024-01-01T00:00:00Z", ""});
  EXPECT_EQ(r["world"], "houseA");
  EXPECT_EQ(r["world_group"], "houseexpo");
  EXPECT_EQ(r["method"], "rrt");
  EXPECT_EQ(r["seed"], 3);
  EXPECT_EQ(r["version"], "abc123");
  EXPECT_EQ(r["host"], "node1");
  EXPECT_TRUE(r["outputs"].is_null());
  EXPECT_EQ(r["schema"], kResultRecordSchema);
  // 5 Hz for 10 s decimated to 1 s: t = 0, 1, ..., 10.
  ASSERT_EQ(r["trajectory"].size(), 11u);
  EXPECT_DOUBLE_EQ(r["trajectory"][1][0].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(r["trajectory"][10][1].get<double>(), 0.5);
  EXPECT_EQ(r["map_stats"]["occupancy"]["storage_bytes"], 1100);
  EXPECT_EQ(r["map_stats"]["semantic"]["storage_bytes"], 250);
  EXPECT_EQ(r["map_stats"]["semantic"]["updates"], 2);
  EXPECT_DOUBLE_EQ(r["map_stats"]["semantic"]["update_p95_ms"].get<double>(), 6.0);
  EXPECT_EQ(r["map_stats"]["pointcloud"]["updates"], 0);  // no update_ms entry
  EXPECT_FALSE(r["file_bytes"].contains("metrics.json"));
}

TEST(ResultRecord, TimingFieldsAreWallClockAndMachineOnly) {
  const nlohmann::json r =
      makeResultRecord({"houseA", "/d/houseA.yaml", "houseexpo"}, fakeEpisode(),
                       {"abc123", "node1", "2024-01-01T00:00:00Z", "runs/x"});
  const nlohmann::json stripped = withoutTimingFields(r);
  for (const char* gone : {"wall_time_s", "host", "recorded_at", "version"})
    EXPECT_FALSE(stripped.contains(gone)) << gone;
  EXPECT_FALSE(stripped["update_ms"]["occupancy"].contains("median"));
  EXPECT_FALSE(stripped["update_ms"]["occupancy"].contains("p95"));
  EXPECT_EQ(stripped["update_ms"]["occupancy"]["count"], 10);  // counts depend on the inputs only
  EXPECT_FALSE(stripped["map_stats"]["semantic"].contains("update_median_ms"));
  EXPECT_EQ(stripped["map_stats"]["semantic"]["storage_bytes"], 250);
  EXPECT_EQ(stripped["exploration_rate"], 0.99);
  EXPECT_EQ(stripped["trajectory"], r["trajectory"]);
}

}  // namespace
}  // namespace roomscout::experiment
