// Exploration of real maps made elsewhere (the shared data set, see dataset_dir.hpp):
// the Explore-Bench maps and a HouseExpo plan, read as map_server worlds. These maps are not in the
// repository. Every method that ends by itself there explores each map to 98 %; rrt and
// improved_rrt are left out for time (about 6 s an episode; improved_rrt does not end on "loop": a
// corner the robot never comes within laser range of stays a frontier, and its end test keeps
// waiting).

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <tuple>

#include "dataset_dir.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/image_world.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

/// One episode of `method` with `seed` on a map_server world (the rooms the semantic strategy
/// reads built as it explores; the others ignore them).
/// With `start`, the robot starts there instead of at the world's default start.
sim::EpisodeResult explore(const fs::path& yaml, const std::string& method, std::uint64_t seed,
                           const std::optional<Pose2>& start = std::nullopt) {
  sim::World world = sim::loadImageWorld(yaml, std::nullopt);
  if (start) {
    world.start = *start;
    world.start_given = true;
  }
  sim::EpisodeConfig config;
  config.resolve();
  const sim::WorldModel model(world, config.world);
  auto strategy = createStrategy(method, seed);
  return sim::runEpisode(model, config, *strategy, seed);
}

class ExploreBenchMaps : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(ExploreBenchMaps, ExploresAtLeast98PercentAndEnds) {
  const auto& [map, method] = GetParam();
  ROOMSCOUT_DATASET_DIR(data);
  const fs::path yaml = data / "floorplans" / "explore_bench" / (map + ".yaml");
  ASSERT_TRUE(fs::exists(yaml)) << "not in the data set: " << yaml;
  const sim::EpisodeResult r = explore(yaml, method, 1);
  EXPECT_GE(r.exploration_rate, 0.98) << map << " " << method;
  EXPECT_FALSE(r.timed_out) << map << " " << method;
}

INSTANTIATE_TEST_SUITE_P(
    Maps, ExploreBenchMaps,
    ::testing::Combine(::testing::Values("corner", "corridor", "loop", "loop_with_corridor", "room",
                                         "room_with_corner"),
                       ::testing::Values("nearest_frontier", "mmpf", "topo", "semantic")),
    [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

// HouseExpo plans where semantic used to stop short: 1dfb7bd5 (38 m^2, seed 1) ended at 97 %
// with a 0.7 m^2 wedge of floor seen past a door jamb taken for a pocket
// (SliverOptions::pocket_area_fraction); 60be0f23 (32 m^2, seed 2) at 97.8 % with
// wedges of rooms seen from their doors that no tree point reached (the end phase); and
// 6a8bc0f2 (seed 1) never ended with a first end phase that points found on a wall the laser
// only grazed kept restarting.
class HouseExpoPlans : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(HouseExpoPlans, SemanticExploresAtLeast98PercentAndEnds) {
  const auto& [plan, seed] = GetParam();
  ROOMSCOUT_DATASET_DIR(data);
  const fs::path yaml = data / "floorplans" / "houseexpo" / (plan + ".yaml");
  ASSERT_TRUE(fs::exists(yaml)) << "not in the data set: " << yaml;
  const sim::EpisodeResult r = explore(yaml, "semantic", static_cast<std::uint64_t>(seed));
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_FALSE(r.timed_out);
}

INSTANTIATE_TEST_SUITE_P(Plans, HouseExpoPlans,
                         ::testing::Values(std::tuple{"1dfb7bd5d9a447175a9719096fbacea7", 1},
                                           std::tuple{"60be0f23f295850c567fa0fd34ed4be6", 2},
                                           std::tuple{"6a8bc0f27a6c62d83771c958dd6bb618", 1}),
                         [](const auto& info) {
                           return std::get<0>(info.param).substr(0, 8) + "_seed" +
                                  std::to_string(std::get<1>(info.param));
                         });

// HouseExpo plans and random starts of the soak (scripts/soak.sh) that end short of 98 % when a
// frontier is dropped for a goal that was reachable:
// - nearest_frontier, 4244ce90 seed 2 (46 %; 9a23603e and 9c877717 at 83-87 %): explore_lite's
//   progress watchdog gives up on a goal whose path first leads away from it. Its frontier must
//   stay, the centroid giving way to the frontier's nearest member.
// - nearest_frontier, 1605d751 seed 1 (97.3 %): two frontiers take turns as the goal while the
//   robot dithers between them, and the stall watchdog gives up on the larger one's centroid.
//   A stalled goal is given up as the progress watchdog gives one up, its frontier kept.
// - semantic, 6a8bc0f2 seed 3 (83 %): the stall watchdog fails the first end-phase cell just as
//   it is set (the robot had idled). A cell failed from afar must rule out only itself, not the
//   disc around it, which covers the whole frontier to the rest of the house.
struct SoakStart {
  const char* plan;
  const char* method;
  int seed;
  Pose2 start;
};

void PrintTo(const SoakStart& c, std::ostream* os) {
  *os << c.plan << " " << c.method << " seed " << c.seed;
}

class SoakStarts : public ::testing::TestWithParam<SoakStart> {};

TEST_P(SoakStarts, ExploresAtLeast98PercentAndEnds) {
  const SoakStart& c = GetParam();
  ROOMSCOUT_DATASET_DIR(data);
  const fs::path yaml = data / "floorplans" / "houseexpo" / (std::string(c.plan) + ".yaml");
  ASSERT_TRUE(fs::exists(yaml)) << "not in the data set: " << yaml;
  const sim::EpisodeResult r = explore(yaml, c.method, static_cast<std::uint64_t>(c.seed), c.start);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_FALSE(r.timed_out);
}

INSTANTIATE_TEST_SUITE_P(
    Plans, SoakStarts,
    ::testing::Values(
        SoakStart{
            "4244ce9026a4eb5e1dff61d805612849", "nearest_frontier", 2, {6.565, 6.605, -1.6168}},
        SoakStart{
            "9a23603e61809a435ac37df8c8cf6e33", "nearest_frontier", 3, {10.755, 4.265, -1.884}},
        SoakStart{
            "9c8777172bb27ff4bdcc495a1954acaf", "nearest_frontier", 2, {5.445, 5.855, -1.6168}},
        SoakStart{
            "1605d7514052573d77a7381044dbbf1d", "nearest_frontier", 1, {4.665, 1.485, 2.7725}},
        SoakStart{"6a8bc0f27a6c62d83771c958dd6bb618", "semantic", 3, {15.495, 8.065, -1.884}}),
    [](const auto& info) {
      return std::string(info.param.plan).substr(0, 8) + "_" + info.param.method + "_seed" +
             std::to_string(info.param.seed);
    });

// Two HouseExpo plans that once broke exploration (floorplans/regressions/ of the data set):
// - 854a08a4: dead-end corridors 0.5 m wide and about 10 m long. Beams running along their
//   walls wore the walls down to free cells with unknown behind, frontiers no robot could close,
//   and five of six methods drove up and down the corridors until the time limit
//   (OccupancyMapper now keeps a wall against beams along it).
// - 76d71987: a hall much wider than the laser's range. nearest_frontier blacklisted one spot of
//   the ring of frontier around the robot and with it the whole ring, and ended at 20 %.
class RegressionPlans : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(RegressionPlans, ExploresAtLeast98PercentAndEnds) {
  const auto& [plan, method] = GetParam();
  ROOMSCOUT_DATASET_DIR(data);
  const fs::path yaml = data / "floorplans" / "regressions" / (plan + ".yaml");
  ASSERT_TRUE(fs::exists(yaml)) << "not in the data set: " << yaml;
  const sim::EpisodeResult r = explore(yaml, method, 1);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_FALSE(r.timed_out);
}

INSTANTIATE_TEST_SUITE_P(Plans, RegressionPlans,
                         ::testing::Combine(::testing::Values("854a08a4376da62034773cb9fae1254b",
                                                              "76d71987631686644bcebcbad31c9a50"),
                                            ::testing::Values("rrt", "improved_rrt", "mmpf", "topo",
                                                              "nearest_frontier", "semantic",
                                                              "semantic_paper")),
                         [](const auto& info) {
                           return std::get<0>(info.param).substr(0, 8) + "_" +
                                  std::get<1>(info.param);
                         });

}  // namespace
}  // namespace roomscout
