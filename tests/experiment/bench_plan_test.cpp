// The bench's episode list: sorted product, shards that partition it exactly, world folders.

#include "roomscout/experiment/bench_plan.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <set>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"

namespace roomscout::experiment {
namespace {

namespace fs = std::filesystem;

TEST(BenchPlan, ListIsTheSortedProductOfWorldsMethodsAndSeeds) {
  const std::vector<EpisodeKey> plan = planEpisodes({"b", "a"}, {"rrt", "mmpf", "rrt"}, {1, 2});
  const std::vector<EpisodeKey> expected = {{"a", "mmpf", 1}, {"a", "mmpf", 2}, {"a", "rrt", 1},
                                            {"a", "rrt", 2},  {"b", "mmpf", 1}, {"b", "mmpf", 2},
                                            {"b", "rrt", 1},  {"b", "rrt", 2}};
  EXPECT_EQ(plan, expected);
}

TEST(BenchPlan, ShardsPartitionTheListExactly) {
  const std::vector<std::string> worlds = {"small_house", "medium_house", "large_office", "x1",
                                           "x2"};
  const std::vector<std::string> methods = {"rrt", "improved_rrt", "mmpf", "semantic"};
  const std::vector<EpisodeKey> all = planEpisodes(worlds, methods, {1, 7});
  ASSERT_EQ(all.size(), 5u * 4u * 7u);
  for (int n : {1, 2, 3, 7, 13, 140, 200}) {
    std::multiset<EpisodeKey> union_of_shards;
    std::size_t largest = 0, smallest = all.size();
    for (int i = 1; i <= n; ++i) {
      const std::vector<EpisodeKey> shard = planEpisodes(worlds, methods, {1, 7}, Shard{i, n});
      largest = std::max(largest, shard.size());
      smallest = std::min(smallest, shard.size());
      // Each shard is the slice position % n == i - 1 of the full list, in its order.
      std::vector<EpisodeKey> expected;
      for (std::size_t p = static_cast<std::size_t>(i - 1); p < all.size();
           p += static_cast<std::size_t>(n)) {
        expected.push_back(all[p]);
      }
      EXPECT_EQ(shard, expected) << i << "/" << n;
      union_of_shards.insert(shard.begin(), shard.end());
    }
    EXPECT_EQ(union_of_shards, std::multiset<EpisodeKey>(all.begin(), all.end())) << n;
    EXPECT_LE(largest - smallest, 1u) << n;  // balanced
  }
}

TEST(BenchPlan, ParseShard) {
  const Shard s = parseShard("3/8");
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 8);
  for (const char* bad :
       {"", "3", "0/2", "3/2", "1/0", "a/2", "1/2x", "-1/2", "1//2", "/2", "99999999999/2"}) {
    try {
      parseShard(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("--shard"), std::string::npos) << e.what();
    }
  }
}

TEST(BenchPlan, BadCountsAreOptionErrors) {
  EXPECT_THROW(planEpisodes({"a"}, {"rrt"}, {1, 0}), OptionError);
  EXPECT_THROW(planEpisodes({}, {"rrt"}, {1, 1}), OptionError);
  EXPECT_THROW(planEpisodes({"a"}, {}, {1, 1}), OptionError);
}

TEST(BenchPlan, SeedRanges) {
  EXPECT_EQ(parseSeeds("10").first, 1);
  EXPECT_EQ(parseSeeds("10").last, 10);
  EXPECT_EQ(parseSeeds("41-48").first, 41);
  EXPECT_EQ(parseSeeds("41-48").last, 48);
  const std::vector<EpisodeKey> plan = planEpisodes({"a"}, {"rrt"}, parseSeeds("5-7"));
  ASSERT_EQ(plan.size(), 3u);
  EXPECT_EQ(plan.front().seed, 5u);
  EXPECT_EQ(plan.back().seed, 7u);
  for (const char* bad : {"0", "-3", "5-4", "0-2", "", "a", "3-", "-", "1-2-3", "2 "}) {
    try {
      parseSeeds(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find("--seeds"), std::string::npos) << e.what();
    }
  }
}

TEST(BenchPlan, SplitList) {
  EXPECT_EQ(splitList("a, b,,c ,"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_TRUE(splitList("").empty());
}

class BenchWorldsTest : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(dir_ / "houseexpo"); }
  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(BenchWorldsTest, FolderExpandsToItsYamlFilesSortedByName) {
  for (const char* f : {"c.yaml", "a.yaml", "b.yaml", "a.png", "notes.txt"})
    std::ofstream(dir_ / "houseexpo" / f) << "x";
  const std::vector<BenchWorld> worlds =
      expandWorlds({"small_house", (dir_ / "houseexpo").string()});
  ASSERT_EQ(worlds.size(), 4u);
  EXPECT_EQ(worlds[0].name, "small_house");
  EXPECT_EQ(worlds[0].group, "builtin");
  EXPECT_EQ(worlds[1].name, "a");
  EXPECT_EQ(worlds[2].name, "b");
  EXPECT_EQ(worlds[3].name, "c");
  for (int i = 1; i < 4; ++i) EXPECT_EQ(worlds[i].group, "houseexpo");
  EXPECT_EQ(worlds[3].spec, (dir_ / "houseexpo" / "c.yaml").string());
  // A trailing slash names the same folder.
  EXPECT_EQ(expandWorlds({(dir_ / "houseexpo").string() + "/"}).front().group, "houseexpo");
}

TEST_F(BenchWorldsTest, BadWorldsAreNamed) {
  try {
    expandWorlds({"no_such_world"});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_world"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("small_house"), std::string::npos);  // lists the built-ins
  }
  EXPECT_THROW(expandWorlds({(dir_ / "houseexpo").string()}), InputError);  // no .yaml inside
  fs::create_directories(dir_ / "other");
  std::ofstream(dir_ / "houseexpo" / "a.yaml") << "x";
  std::ofstream(dir_ / "other" / "a.yaml") << "x";
  EXPECT_THROW(expandWorlds({(dir_ / "houseexpo").string(), (dir_ / "other").string()}),
               OptionError);
  // The same world twice is one world.
  EXPECT_EQ(expandWorlds({"small_house", "small_house"}).size(), 1u);
}

}  // namespace
}  // namespace roomscout::experiment
