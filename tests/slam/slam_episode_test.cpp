// Whole episodes with SLAM in the loop: a SLAM (the graph SLAM or MRPT's ICP) estimates the pose,
// the robot maps and explores with the estimate, and the harness scores both against the truth.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/episode.hpp"

namespace roomscout::sim {
namespace {

EpisodeResult exploreSmallHouse(const std::string& method, const std::string& noise,
                                const std::string& slam, std::uint64_t seed) {
  EpisodeConfig config;
  config.noise.profile = noise;
  config.slam.mode = slam;
  config.resolve();
  const WorldModel model(sim::loadBuiltinWorld("small_house"), config.world);
  auto strategy = createStrategy(method, seed);
  return runEpisode(model, config, *strategy, seed);
}

TEST(SlamEpisode, IcpWithoutNoiseTracksTheTruthWithinACellOrTwo) {
  const EpisodeResult r = exploreSmallHouse("nearest_frontier", "none", "icp", 1);
  ASSERT_TRUE(r.slam.has_value());
  EXPECT_EQ(r.slam->mode, "icp");
  EXPECT_EQ(r.slam->error.samples, r.trajectory.size());
  EXPECT_LT(r.slam->error.rmse_m, 0.1);  // two map cells
  EXPECT_LT(r.slam->error.heading_rmse_rad, 0.02);
  EXPECT_GT(r.map_accuracy.occupied_precision, 0.8);
  EXPECT_FALSE(r.slam->diverged);
  EXPECT_GE(r.exploration_rate, 0.93);
  EXPECT_EQ(r.slam_update.count, r.trajectory.size());
}

// Realistic TurtleBot3 noise with ICP-SLAM, on seeds 1-3: both methods map the house and end
// by themselves without diverging. The bounds hold on every seed measured, 1-6 (rate 0.947 to
// 0.992, ATE 0.11 to 0.36 m), with room to spare: ICP has no loop closure, so its drift, and
// with it the share of the map that lies where the walls are, varies from seed to seed.
class NoisySlamEpisode : public ::testing::TestWithParam<std::tuple<std::string, std::uint64_t>> {};

TEST_P(NoisySlamEpisode, Tb3NoiseWithIcpExploresTheSmallHouseAndEnds) {
  const auto& [method, seed] = GetParam();
  const EpisodeResult r = exploreSmallHouse(method, "tb3", "icp", seed);
  ASSERT_TRUE(r.slam.has_value());
  EXPECT_GE(r.exploration_rate, 0.93);
  EXPECT_TRUE(r.t_done_s.has_value());
  EXPECT_LT(r.slam->error.rmse_m, 0.5);
  EXPECT_FALSE(r.slam->diverged);
}

INSTANTIATE_TEST_SUITE_P(MethodsAndSeeds, NoisySlamEpisode,
                         ::testing::Combine(::testing::Values("nearest_frontier", "semantic"),
                                            ::testing::Values(1u, 2u, 3u)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_seed" +
                                  std::to_string(std::get<1>(info.param));
                         });

// Every method explores the small house under the TurtleBot3's noise to 98 % and declares the
// end itself: with the true pose, and with the graph SLAM's pose and map.
class Tb3Episode : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(Tb3Episode, ReachesAtLeast98PercentAndEnds) {
  const auto& [method, slam] = GetParam();
  const EpisodeResult r = exploreSmallHouse(method, "tb3", slam, 1);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_FALSE(r.timed_out) << "ended only by the time limit " << r.max_time_s << " s";
  EXPECT_TRUE(r.t_done_s.has_value());
  if (r.slam) {
    EXPECT_FALSE(r.slam->diverged);
  }
}

std::vector<std::string> methodsWithoutAblations() {
  std::vector<std::string> names = strategyNames();
  std::erase_if(names, [](const std::string& n) { return n.ends_with("_only"); });
  return names;
}

INSTANTIATE_TEST_SUITE_P(SmallHouse, Tb3Episode,
                         ::testing::Combine(::testing::ValuesIn(methodsWithoutAblations()),
                                            ::testing::Values("none", "graph")),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_slam_" + std::get<1>(info.param);
                         });

TEST(SlamEpisode, WithoutSlamThereIsNoSlamRecordAndTheEstimateIsTheTruth) {
  const EpisodeResult r = exploreSmallHouse("nearest_frontier", "tb3", "none", 1);
  EXPECT_FALSE(r.slam.has_value());
  ASSERT_FALSE(r.trajectory.empty());
  for (const TrajectorySample& s : r.trajectory) {
    EXPECT_EQ(s.estimate.x_m, s.pose.x_m);
    EXPECT_EQ(s.estimate.yaw_rad, s.pose.yaw_rad);
  }
}

TEST(SlamEpisode, TheSameSeedGivesTheSameRun) {
  const EpisodeResult a = exploreSmallHouse("nearest_frontier", "tb3", "icp", 3);
  const EpisodeResult b = exploreSmallHouse("nearest_frontier", "tb3", "icp", 3);
  ASSERT_TRUE(a.slam && b.slam);
  EXPECT_EQ(a.slam->error.rmse_m, b.slam->error.rmse_m);
  EXPECT_EQ(a.exploration_rate, b.exploration_rate);
  EXPECT_EQ(a.length_m, b.length_m);
}

}  // namespace
}  // namespace roomscout::sim
