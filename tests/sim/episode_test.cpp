// Whole episodes: exploration of the built-in worlds and determinism.

#include "roomscout/sim/episode.hpp"

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/run_outputs.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/exploration_truth.hpp"
#include "test_worlds.hpp"

namespace roomscout::sim {
namespace {

EpisodeResult explore(const World& world, const std::string& method, std::uint64_t seed) {
  EpisodeConfig config;
  config.resolve();
  const WorldModel model(world, config.world);
  auto strategy = createStrategy(method, seed);
  return runEpisode(model, config, *strategy, seed);
}

class BuiltinWorldExploration : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinWorldExploration, NearestFrontierExploresAtLeast98Percent) {
  const EpisodeResult r = explore(sim::loadBuiltinWorld(GetParam()), "nearest_frontier", 1);
  EXPECT_GE(r.exploration_rate, 0.98);
  ASSERT_TRUE(r.t98_s.has_value());
  ASSERT_TRUE(r.l98_m.has_value());
  EXPECT_FALSE(r.timed_out);
  ASSERT_TRUE(r.t_done_s.has_value());
  EXPECT_LE(*r.t98_s, *r.t_done_s);
  EXPECT_LE(*r.l98_m, r.length_m + 1e-9);
  // The curve is sampled every simulated second and never decreases by much (log-odds may
  // flip a few cells back to unknown).
  ASSERT_GT(r.curve.size(), 10u);
  for (std::size_t i = 1; i < r.curve.size(); ++i) {
    EXPECT_GE(r.curve[i].rate, r.curve[i - 1].rate - 0.01);
    EXPECT_GE(r.curve[i].length_m, r.curve[i - 1].length_m);
  }
}

INSTANTIATE_TEST_SUITE_P(Worlds, BuiltinWorldExploration,
                         ::testing::Values("small_house", "medium_house", "large_office"));

// Every registered method explores the two houses (seed 1, with the semantic map built as in
// `roomscout explore`) and declares the end itself. The large office, 10 seeds and the
// comparison between methods are the bench's job (docs/bench.md), with one exception
// below (rrt in the medium house reaches 98 % but does not end). The ablations of
// semantic_paper run on the small house only, to keep the suite short; semantic_paper itself
// runs in both houses.
class EveryMethodExploresTheHouses
    : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(EveryMethodExploresTheHouses, ReachesAtLeast98PercentAndEnds) {
  const auto& [world_name, method] = GetParam();
  EpisodeConfig config;
  config.resolve();
  const WorldModel model(sim::loadBuiltinWorld(world_name), config.world);
  auto strategy = createStrategy(method, 1);
  const EpisodeResult r = runEpisode(model, config, *strategy, 1);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_TRUE(r.t98_s.has_value());
  // The count up to T98 is the count of the sample that reached 98 %: never more than the
  // whole episode's, and what the robot does once the map is complete adds to the latter only.
  ASSERT_TRUE(r.revisits98.has_value());
  EXPECT_LE(*r.revisits98, r.revisits);
  // rrt does not end by itself on every seed of the medium house: its end test counts frontier
  // cells neither of its detectors sends the robot to (docs/methods.md).
  if (world_name == "medium_house" && method == "rrt" && r.timed_out) {
    GTEST_SKIP() << "rrt may run to the time limit in the medium house: its end test counts "
                    "frontier cells neither of its detectors sends the robot to";
  }
  EXPECT_FALSE(r.timed_out) << "ended only by the time limit " << r.max_time_s << " s";
}

std::vector<std::string> methodsWithoutAblations() {
  std::vector<std::string> names = strategyNames();
  std::erase_if(names, [](const std::string& n) { return n.ends_with("_only"); });
  return names;
}

INSTANTIATE_TEST_SUITE_P(SmallHouse, EveryMethodExploresTheHouses,
                         ::testing::Combine(::testing::Values("small_house"),
                                            ::testing::ValuesIn(strategyNames())),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_" + std::get<1>(info.param);
                         });
INSTANTIATE_TEST_SUITE_P(MediumHouse, EveryMethodExploresTheHouses,
                         ::testing::Combine(::testing::Values("medium_house"),
                                            ::testing::ValuesIn(methodsWithoutAblations())),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_" + std::get<1>(info.param);
                         });

TEST(Episode, TheSameSeedGivesTheSameRun) {
  const World world = sim::loadBuiltinWorld("small_house");
  const EpisodeResult a = explore(world, "nearest_frontier", 5);
  const EpisodeResult b = explore(world, "nearest_frontier", 5);
  EXPECT_EQ(a.exploration_rate, b.exploration_rate);
  EXPECT_EQ(a.t98_s, b.t98_s);
  EXPECT_EQ(a.l98_m, b.l98_m);
  EXPECT_EQ(a.t_done_s, b.t_done_s);
  EXPECT_EQ(a.revisits, b.revisits);
  ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
  for (std::size_t i = 0; i < a.trajectory.size(); ++i) {
    EXPECT_EQ(a.trajectory[i].pose.x_m, b.trajectory[i].pose.x_m);
    EXPECT_EQ(a.trajectory[i].pose.y_m, b.trajectory[i].pose.y_m);
  }
}

TEST(Episode, AClosedRoomIsExploredAndEndsWithinTwoMinutes) {
  // A closed 4 x 4 m room: once it is mapped no frontier is left and the strategy ends.
  const EpisodeResult r = explore(testing::squareRoom(4.0, 0.2), "nearest_frontier", 1);
  EXPECT_TRUE(r.t_done_s.has_value());
  EXPECT_FALSE(r.timed_out);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_LT(*r.t_done_s, 120.0);
}

TEST(Episode, TwoRoomsAreBothExploredAndEntered) {
  const EpisodeResult r = explore(testing::twoRooms(), "nearest_frontier", 1);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_EQ(r.rooms_entered, 2);
}

TEST(Episode, RoomCountsAreNullWithoutGroundTruthRooms) {
  World unlabelled = testing::squareRoom(4.0, 0.2);
  unlabelled.rooms.clear();
  const EpisodeResult without = explore(unlabelled, "nearest_frontier", 1);
  EXPECT_FALSE(without.room_truth);
  const nlohmann::json metrics = experiment::metricsJson({}, without);
  EXPECT_TRUE(metrics.at("revisits").is_null());
  EXPECT_TRUE(metrics.at("rooms_entered").is_null());
  EXPECT_TRUE(metrics.at("revisits_98").is_null());

  const EpisodeResult with = explore(testing::squareRoom(4.0, 0.2), "nearest_frontier", 1);
  EXPECT_TRUE(with.room_truth);
  EXPECT_EQ(with.rooms_entered, 1);
  EXPECT_EQ(experiment::metricsJson({}, with).at("revisits"), 0);
  EXPECT_EQ(experiment::metricsJson({}, with).at("revisits_98"), 0);
}

TEST(Episode, BumpingIntoAnObstacleTheLaserCannotSeeRecoversAndEnds) {
  // A 10 m x 1.2 m corridor with a 0.1 m high box across its middle: below the laser plane
  // (0.18 m), so the map never shows it, but it stops the robot. The robot must back off,
  // give up the goal behind it and end instead of pushing forever.
  World w;
  w.name = "low_box";
  w.source = "test:low_box";
  const double t = 0.2;
  w.walls = {{{0, 0}, {10, 0}, t, 0, 2.5},
             {{10, 0}, {10, 1.4}, t, 0, 2.5},
             {{10, 1.4}, {0, 1.4}, t, 0, 2.5},
             {{0, 1.4}, {0, 0}, t, 0, 2.5}};
  w.furniture.push_back({"low_box", {{2.5, 0.1}, {2.9, 0.1}, {2.9, 1.3}, {2.5, 1.3}}, 0.0, 0.1});
  w.start = {0.8, 0.7, 0.0};
  w.start_given = true;
  const EpisodeResult r = explore(w, "nearest_frontier", 1);
  EXPECT_GE(r.recoveries, 1) << "t_done " << r.t_done_s.value_or(-1) << " goals " << r.goals
                             << " failures " << r.goal_failures << " length " << r.length_m;
  EXPECT_FALSE(r.timed_out);
  EXPECT_TRUE(r.t_done_s.has_value());
  // It never drove through the box.
  for (const TrajectorySample& s : r.trajectory) EXPECT_LT(s.pose.x_m, 2.5);
}

// Each method's run on the small house (seed 1) keeps within a budget: it reaches 98 %, ends
// by itself, and takes no more than a quarter longer, drives no more than a quarter farther and
// sends no more than half again as many goals as it did when these bounds were set (its
// figures then in the comments). A change that breaks a bound is a change of behaviour, to be
// made on purpose and measured with `roomscout bench`.
struct RunBudget {
  const char* method;
  double t98_s, l98_m, t_done_s;  ///< at most
  int goals;                      ///< at most
  friend void PrintTo(const RunBudget& r, std::ostream* os) { *os << r.method; }
};

class SmallHouseRun : public ::testing::TestWithParam<RunBudget> {};

TEST_P(SmallHouseRun, ReachesNinetyEightPercentAndEndsWithinItsBudget) {
  const RunBudget& budget = GetParam();
  const EpisodeResult r = explore(sim::loadBuiltinWorld("small_house"), budget.method, 1);
  ASSERT_TRUE(r.t98_s && r.l98_m && r.t_done_s);
  EXPECT_FALSE(r.timed_out);
  EXPECT_LE(*r.t98_s, *r.t_done_s);
  EXPECT_LE(*r.t98_s, budget.t98_s);
  EXPECT_LE(*r.l98_m, budget.l98_m);
  EXPECT_LE(*r.t_done_s, budget.t_done_s);
  EXPECT_LE(r.goals, budget.goals);
  EXPECT_LE(r.stalls, 2);
  EXPECT_LE(r.goal_failures, r.goals);
}

INSTANTIATE_TEST_SUITE_P(
    Methods, SmallHouseRun,
    ::testing::Values(
        // 569 s, 120.7 m, ended at 987 s, 129 goals
        RunBudget{"nearest_frontier", 1.25 * 569.0, 1.25 * 120.7, 1.25 * 987.4, 194},
        // 402 s, 85.6 m, ended at 709 s, 674 goals
        RunBudget{"semantic", 1.25 * 402.0, 1.25 * 85.6, 1.25 * 709.4, 1011},
        // 430 s, 91.5 m, ended at 738 s, 82 goals
        RunBudget{"mmpf", 1.25 * 430.0, 1.25 * 91.5, 1.25 * 738.2, 123},
        // 715 s, 146.3 m, ended at 1278 s, 1368 goals
        RunBudget{"improved_rrt", 1.25 * 715.0, 1.25 * 146.3, 1.25 * 1278.1, 2052}),
    [](const auto& info) { return std::string(info.param.method); });

// With the map published as SLAM packages publish it (the known area plus a margin, its origin
// moving as it grows), the tree-based methods explore the house as they do on the fixed grid.
class GrowingMap : public ::testing::TestWithParam<std::string> {};

TEST_P(GrowingMap, ExploresTheSmallHouseAsOnTheFixedGrid) {
  EpisodeConfig config;
  config.resolve();
  const WorldModel model(sim::loadBuiltinWorld("small_house"), config.world);
  auto fixed_strategy = createStrategy(GetParam(), 2);
  const EpisodeResult fixed = runEpisode(model, config, *fixed_strategy, 2);
  config.episode.map_mode = "growing";
  auto strategy = createStrategy(GetParam(), 2);
  const EpisodeResult r = runEpisode(model, config, *strategy, 2);
  EXPECT_GE(r.exploration_rate, 0.98);
  EXPECT_FALSE(r.timed_out);
  ASSERT_TRUE(r.l98_m && fixed.l98_m);
  EXPECT_LT(*r.l98_m, 1.3 * *fixed.l98_m) << "fixed grid " << *fixed.l98_m << " m";
  // The map it ends with is the published one: no larger than the world's grid.
  EXPECT_LE(r.map.geometry().cellCount(),
            mapGeometryFor(model, config.mapping.resolution_m).cellCount());
}

INSTANTIATE_TEST_SUITE_P(TreeMethods, GrowingMap,
                         ::testing::Values("semantic", "rrt", "improved_rrt"));

TEST(Episode, RejectsAnUnknownMapMode) {
  EpisodeConfig config;
  config.episode.map_mode = "sliding";
  try {
    config.validate();
    FAIL() << "map_mode sliding was accepted";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("sliding"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace roomscout::sim
