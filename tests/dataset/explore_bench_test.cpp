// Exploration of real maps made elsewhere (../shared/data, found through ROOMSCOUT_DATA_DIR):
// the Explore-Bench maps, read as map_server worlds. These maps are not in the repository.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/episode.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

fs::path dataDir() {
  const char* dir = std::getenv("ROOMSCOUT_DATA_DIR");
  return dir ? fs::path(dir) : fs::path();
}

class ExploreBenchMaps : public ::testing::TestWithParam<std::string> {};

TEST_P(ExploreBenchMaps, NearestFrontierExploresAtLeast98Percent) {
  const fs::path yaml = dataDir() / "floorplans" / "explore_bench" / (GetParam() + ".yaml");
  // The data set is part of the test environment: a missing one is a failure, not a skip.
  ASSERT_TRUE(fs::exists(yaml)) << "set ROOMSCOUT_DATA_DIR to the shared data folder; not found: " << yaml;
  const sim::World world = io::loadImageWorld(yaml, std::nullopt);
  sim::EpisodeConfig config;
  config.resolve();
  const sim::WorldModel model(world, config.world);
  auto strategy = createStrategy("nearest_frontier", 1);
  const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, 1);
  EXPECT_GE(r.exploration_rate, 0.98) << GetParam();
  EXPECT_FALSE(r.timed_out);
}

INSTANTIATE_TEST_SUITE_P(Maps, ExploreBenchMaps,
                         ::testing::Values("corner", "corridor", "loop", "loop_with_corridor", "room",
                                           "room_with_corner"));

}  // namespace
}  // namespace roomscout
