// The simulation loop without an Explorer: sensing on schedule, motion, collisions, the
// published map, the clock and the time limit.

#include "roomscout/sim/simulation.hpp"

#include <gtest/gtest.h>

#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

EpisodeConfig smallConfig() {
  EpisodeConfig config;
  config.episode.max_time_s = 20.0;
  return config;
}

TEST(Simulation, ScansAtTheLasersRateAndSamplesTheRateEverySecond) {
  const EpisodeConfig config = smallConfig();
  const WorldModel model(testing::squareRoom(4.0, 0.2), config.world);
  Simulation sim(model, config, 1);
  int scans = 0, samples = 0;
  for (int i = 0; i < 40; ++i) {  // 2 s at 0.05 s a step
    const Sensed sensed = sim.sense();
    scans += sensed.scan.has_value();
    samples += sensed.sampled;
    if (sensed.scan) {
      EXPECT_FALSE(sensed.changed.empty());
    }
    sim.act({});
    ASSERT_TRUE(sim.step());
  }
  EXPECT_EQ(scans, 10);  // 5 Hz
  EXPECT_EQ(samples, 2);
  EXPECT_GT(sim.rate(), 0.5);  // a 4 m room seen from its middle
}

TEST(Simulation, ARobotDrivingIntoAWallIsReportedBlockedAfterTheStuckTimeout) {
  EpisodeConfig config = smallConfig();
  const World world = testing::squareRoom(4.0, 0.2);
  const WorldModel model(world, config.world);
  Simulation sim(model, config, 1);
  const VelocityCommand forward{0.2, 0.0};
  std::optional<double> blocked_at_s;
  while (!blocked_at_s && sim.step()) {
    if (sim.act(forward)) blocked_at_s = sim.time_s();
  }
  ASSERT_TRUE(blocked_at_s.has_value()) << "never reported blocked";
  // Less than 2 m to the wall at 0.2 m/s, then the stuck timeout (2 s).
  EXPECT_LT(*blocked_at_s, 2.0 / 0.2 + config.episode.stuck_timeout_s + 0.1);
  EXPECT_GT(sim.odometer_m(), 1.0);
  // Backing off moves the robot again: no report.
  EXPECT_FALSE(sim.act(backOffCommand()));
}

TEST(Simulation, WithoutSlamTheRobotKnowsItsTruePose) {
  const EpisodeConfig config = smallConfig();
  const WorldModel model(testing::squareRoom(4.0, 0.2), config.world);
  Simulation sim(model, config, 1);
  for (int i = 0; i < 20; ++i) {
    sim.sense();
    sim.act({0.1, 0.5});
    sim.step();
    EXPECT_EQ(sim.estimate().x_m, sim.robotPose().x_m);
    EXPECT_EQ(sim.odometryPose().y_m, sim.robotPose().y_m);
  }
  EXPECT_FALSE(sim.hasSlam());
}

TEST(Simulation, AGrowingMapCoversTheKnownCellsAndNoMoreThanTheWorld) {
  EpisodeConfig config = smallConfig();
  config.episode.map_mode = "growing";
  const WorldModel model(testing::squareRoom(10.0, 0.2), config.world);
  Simulation sim(model, config, 1);
  sim.sense();
  const PublishedMap first = sim.publishMap();
  EXPECT_FALSE(first.changed.has_value());  // a new geometry: any cell may have changed
  EXPECT_LT(first.grid.geometry().cellCount(), sim.grid().geometry().cellCount());
  const Vec2 robot = sim.robotPose().position();
  EXPECT_TRUE(first.grid.geometry().contains(robot));
  // Nothing mapped since: the same geometry and nothing changed.
  const PublishedMap again = sim.publishMap();
  ASSERT_TRUE(again.changed.has_value());
  EXPECT_TRUE(again.changed->empty());
}

TEST(Simulation, StopsAtTheTimeLimit) {
  const EpisodeConfig config = smallConfig();
  const WorldModel model(testing::squareRoom(4.0, 0.2), config.world);
  Simulation sim(model, config, 1);
  int steps = 0;
  while (sim.step()) ++steps;
  EXPECT_TRUE(sim.timedOut());
  EXPECT_GT(sim.time_s(), config.episode.max_time_s);
  EXPECT_NEAR(steps * config.episode.dt_s, config.episode.max_time_s, config.episode.dt_s);
}

}  // namespace
}  // namespace roomscout::sim
