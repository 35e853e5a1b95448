// The simulator's config file as roomscout_sim_node reads it: the file `roomscout explore
// --config` reads, resolved to the same episode and point cloud options.

#include "roomscout/sim/simulator_config.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/episode_setup.hpp"
#include "roomscout/io/options_yaml.hpp"

namespace roomscout::sim {
namespace {

/// Every group's values by name, as metrics.json records them.
nlohmann::json valuesOf(std::vector<ParameterGroup> groups) {
  nlohmann::json values = nlohmann::json::object();
  for (const ParameterGroup& g : groups) values[g.name] = io::parametersToJson(g.parameters);
  return values;
}

void expectSameAsExplore(SimulatorConfig config, const std::filesystem::path& file) {
  experiment::RunSettings settings;
  settings.config_file = file;
  experiment::EpisodeSetup setup = experiment::makeEpisodeSetup("nearest_frontier", 1, settings);
  EXPECT_EQ(valuesOf(config.episode.groups()), valuesOf(setup.config.groups()));
  EXPECT_EQ(valuesOf(config.cloud.groups()), valuesOf(setup.cloud.groups()));
  // What resolve() mirrors and the lidar noise the profile sets, which no group shows.
  EXPECT_EQ(config.episode.world.robot_radius_m, setup.config.world.robot_radius_m);
  EXPECT_EQ(config.episode.follower.max_linear_speed_mps,
            setup.config.follower.max_linear_speed_mps);
  EXPECT_EQ(config.cloud.lidar_noise.sd_near_m, setup.cloud.lidar_noise.sd_near_m);
  EXPECT_EQ(config.cloud.lidar_noise.sd_fraction, setup.cloud.lidar_noise.sd_fraction);
  EXPECT_EQ(config.cloud.lidar_noise.dropout_probability,
            setup.cloud.lidar_noise.dropout_probability);
  EXPECT_EQ(config.warnings, setup.warnings);
}

TEST(SimulatorConfig, WithoutAFileHasExploresDefaults) {
  const SimulatorConfig config = loadSimulatorConfig({});
  EXPECT_TRUE(config.warnings.empty());
  EXPECT_TRUE(config.cloud.lidar_noise.none());
  expectSameAsExplore(config, {});
}

TEST(SimulatorConfig, ReadsExploresFileWithEveryMethodsGroup) {
  const test::TempDir dir;
  const std::filesystem::path file =
      dir.write("options.yaml",
                "robot:\n  radius_m: 0.2\n"
                "episode:\n  map_mode: growing\n  stall_min_new_area_m2: 2\n"
                "noise:\n  profile: tb3\n"
                "lidar:\n  rate_hz: 5\n"
                "pointcloud:\n  remove_floor_ceiling: true\n"
                "nearest_frontier:\n  gain_scale: 2\n"
                "semantic: {}\n");
  const SimulatorConfig config = loadSimulatorConfig(file);
  EXPECT_EQ(config.episode.episode.mapMode(), MapMode::kGrowing);
  EXPECT_EQ(config.episode.world.robot_radius_m, 0.2);  // resolved from robot.radius_m
  EXPECT_EQ(config.cloud.lidar.rate_hz, 5.0);
  EXPECT_TRUE(config.cloud.remove_floor_ceiling);
  EXPECT_FALSE(config.cloud.lidar_noise.none());  // tb3's VLP-16
  ASSERT_EQ(config.warnings.size(), 1u);          // the former name
  EXPECT_NE(config.warnings.front().find("episode.stall_min_new_area_m2"), std::string::npos);
  expectSameAsExplore(config, file);
}

TEST(SimulatorConfig, RefusesAnUnknownGroupOrABadValueNamingTheFile) {
  const test::TempDir dir;
  const std::filesystem::path unknown = dir.write("unknown.yaml", "gazebo:\n  rate: 1\n");
  try {
    loadSimulatorConfig(unknown);
    ADD_FAILURE() << "an unknown group was accepted";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("gazebo"), std::string::npos) << e.what();
  }
  const std::filesystem::path bad = dir.write("bad.yaml", "episode:\n  dt_s: 0\n");
  try {
    loadSimulatorConfig(bad);
    ADD_FAILURE() << "a zero time step was accepted";
  } catch (const OptionError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(bad.string() + ": ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("episode.dt_s"), std::string::npos) << e.what();
  }
  EXPECT_THROW(loadSimulatorConfig(dir / "missing.yaml"), InputError);
}

}  // namespace
}  // namespace roomscout::sim
