// Exploration of real maps made elsewhere (../shared/data, found through ROOMSCOUT_DATA_DIR):
// the Explore-Bench maps and a HouseExpo plan, read as map_server worlds. These maps are not in the repository.
// Every method that ends by itself there explores each map to 98 %; rrt and improved_rrt are
// left out for time (about 6 s an episode; improved_rrt does not end on "loop": a corner the
// robot never comes within laser range of stays a frontier, and its end test keeps waiting).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>

#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/analysis_maps_observer.hpp"
#include "roomscout/sim/episode.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

fs::path dataDir() {
  const char* dir = std::getenv("ROOMSCOUT_DATA_DIR");
  return dir ? fs::path(dir) : fs::path();
}

class ExploreBenchMaps : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(ExploreBenchMaps, ExploresAtLeast98PercentAndEnds) {
  const auto& [map, method] = GetParam();
  const fs::path yaml = dataDir() / "floorplans" / "explore_bench" / (map + ".yaml");
  // The data set is part of the test environment: a missing one is a failure, not a skip.
  ASSERT_TRUE(fs::exists(yaml)) << "set ROOMSCOUT_DATA_DIR to the shared data folder; not found: " << yaml;
  const sim::World world = io::loadImageWorld(yaml, std::nullopt);
  sim::EpisodeConfig config;
  config.resolve();
  const sim::WorldModel model(world, config.world);
  auto strategy = createStrategy(method, 1);
  // The rooms the semantic strategy reads (the others ignore them).
  sim::AnalysisMapsObserver semantic(sim::AnalysisMapKind::kSemantic);
  const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, 1, {}, {&semantic});
  EXPECT_GE(r.exploration_rate, 0.98) << map << " " << method;
  EXPECT_FALSE(r.timed_out) << map << " " << method;
}

INSTANTIATE_TEST_SUITE_P(Maps, ExploreBenchMaps,
                         ::testing::Combine(::testing::Values("corner", "corridor", "loop", "loop_with_corridor",
                                                              "room", "room_with_corner"),
                                            ::testing::Values("nearest_frontier", "mmpf", "topo", "semantic")),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_" + std::get<1>(info.param);
                         });

// A HouseExpo plan of 38 m^2 where semantic used to end at 97 %: the floor it had not seen was
// a 0.7 m^2 wedge of the room past a door jamb, a pocket by the absolute threshold
// (SemanticExplorerOptions::pocket_area_fraction).
TEST(HouseExpoPlans, SemanticLooksIntoAWedgeOfFloorInASmallFlat) {
  const fs::path yaml = dataDir() / "floorplans" / "houseexpo" / "1dfb7bd5d9a447175a9719096fbacea7.yaml";
  ASSERT_TRUE(fs::exists(yaml)) << "set ROOMSCOUT_DATA_DIR to the shared data folder; not found: " << yaml;
  const sim::World world = io::loadImageWorld(yaml, std::nullopt);
  sim::EpisodeConfig config;
  config.resolve();
  const sim::WorldModel model(world, config.world);
  auto strategy = createStrategy("semantic", 1);
  sim::AnalysisMapsObserver semantic(sim::AnalysisMapKind::kSemantic);
  const sim::EpisodeResult r = sim::runEpisode(model, config, *strategy, 1, {}, {&semantic});
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_FALSE(r.timed_out);
}

}  // namespace
}  // namespace roomscout
