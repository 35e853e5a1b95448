// `roomscout bench` and `roomscout report` end to end: resume, shards, --jobs independence,
// outputs of the lowest seed, and one clear error (exit code 2) for each bad input.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"
#include "roomscout/experiment/result_record.hpp"
#include "two_room_world.hpp"

namespace fs = std::filesystem;

namespace {

class BenchCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "tiny");
    roomscout::test::writeTwoRoomWorld(dir_ / "tiny");
  }

  std::pair<int, std::string> run(const std::string& args) {
    return roomscout::test::asPair(roomscout::test::runRoomscout(args, dir_));
  }

  std::string world() const { return (dir_ / "tiny" / "rooms.yaml").string(); }

  static std::vector<nlohmann::json> records(const fs::path& bench_dir) {
    std::vector<nlohmann::json> out;
    std::ifstream in(bench_dir / "results.jsonl");
    std::string line;
    while (std::getline(in, line)) out.push_back(nlohmann::json::parse(line));
    return out;
  }

  static std::string key(const nlohmann::json& r) {
    return r["world"].get<std::string>() + "/" + r["method"].get<std::string>() + "/" +
           std::to_string(r["seed"].get<int>());
  }

  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(BenchCliTest, RerunSkipsRecordedEpisodesAndResumesAfterATruncatedLine) {
  const fs::path out = dir_ / "b";
  auto [code, output] = run("bench --worlds " + world() +
                            " --methods nearest_frontier --seeds 1 --jobs 1 --out " + out.string());
  ASSERT_EQ(code, 0) << output;
  ASSERT_EQ(records(out).size(), 1u);
  const std::string first_line = records(out)[0].dump();

  // Same bench with one more seed: only the new episode runs.
  std::tie(code, output) =
      run("bench --worlds " + world() + " --methods nearest_frontier --seeds 2 --jobs 2 --out " +
          out.string());
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("2 episodes (1 run, 1 already recorded)"), std::string::npos) << output;
  std::vector<nlohmann::json> r = records(out);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].dump(), first_line);
  EXPECT_EQ(key(r[1]), "rooms/nearest_frontier/2");

  // An interrupted write left half a line: ignored by report, cut off by the next bench.
  std::ofstream(out / "results.jsonl", std::ios::app)
      << R"({"world": "rooms", "method": "nearest_fr)";
  std::tie(code, output) = run("report " + out.string());
  ASSERT_EQ(code, 0) << output;
  std::tie(code, output) = run("bench --worlds " + world() +
                               " --methods nearest_frontier --seeds 2 --out " + out.string());
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("2 episodes (0 run, 2 already recorded)"), std::string::npos) << output;
  EXPECT_NE(output.find("truncated"), std::string::npos) << output;
  EXPECT_EQ(records(out).size(), 2u);  // every line parses again
}

TEST_F(BenchCliTest, JobsDoNotChangeResultsAndSeedOneKeepsItsOutputs) {
  // small_house cut at 30 s of simulated time: a real world, quickly.
  const fs::path cfg = dir_ / "short.yaml";
  std::ofstream(cfg) << "episode:\n  max_time_s: 30\n";
  const std::string args = "bench --worlds small_house," + world() +
                           " --methods nearest_frontier,rrt --seeds 2 --config " + cfg.string() +
                           " --out ";
  auto [code1, out1] = run(args + (dir_ / "j1").string() + " --jobs 1");
  ASSERT_EQ(code1, 0) << out1;
  auto [code2, out2] = run(args + (dir_ / "j2").string() + " --jobs 2");
  ASSERT_EQ(code2, 0) << out2;

  std::map<std::string, nlohmann::json> a, b;
  for (const nlohmann::json& r : records(dir_ / "j1"))
    a[key(r)] = roomscout::experiment::withoutTimingFields(r);
  for (const nlohmann::json& r : records(dir_ / "j2"))
    b[key(r)] = roomscout::experiment::withoutTimingFields(r);
  ASSERT_EQ(a.size(), 8u);
  ASSERT_EQ(b.size(), 8u);
  for (const auto& [k, r] : a) {
    ASSERT_TRUE(b.count(k)) << k;
    EXPECT_EQ(r.dump(), b[k].dump()) << k;
    EXPECT_EQ(r["options"]["episode"]["max_time_s"], 30.0);
  }
  // The lowest seed keeps explore's outputs; the others leave none.
  const nlohmann::json& sh1 = a.at("small_house/rrt/1");
  EXPECT_EQ(sh1["outputs"], "runs/small_house/rrt/seed1");
  for (const char* f : {"metrics.json", "occupancy.pgm", "pointcloud.pcd", "semantic.json",
                        "topology.json", "run.png"}) {
    EXPECT_TRUE(fs::exists(dir_ / "j1" / "runs" / "small_house" / "rrt" / "seed1" / f)) << f;
  }
  EXPECT_TRUE(a.at("rooms/rrt/2")["outputs"].is_null());
  EXPECT_FALSE(fs::exists(dir_ / "j1" / "runs" / "rooms" / "rrt" / "seed2"));
  EXPECT_FALSE(fs::exists(dir_ / "j1" / ".scratch"));
  // The record's metrics are those of metrics.json.
  std::ifstream in(dir_ / "j1" / "runs" / "small_house" / "rrt" / "seed1" / "metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(in);
  for (const char* k :
       {"exploration_rate", "t98_s", "l98_m", "revisits", "curve", "options", "maps"}) {
    EXPECT_EQ(metrics[k], sh1[k]) << k;
  }
  for (const char* k : {"trajectory", "map_stats", "version", "host", "world_group"}) {
    EXPECT_TRUE(records(dir_ / "j1")[0].contains(k)) << k;
  }
  for (const char* f :
       {"table1.md", "table1.csv", "table2.md", "table3.md", "report.html",
        "figures/fig5_rate_small_house.png", "figures/fig6_trajectories_small_house.svg",
        "figures/fig7_maps_small_house.png", "figures/fig7_maps_small_house.pdf",
        "figures/fig5_rate_rooms.svg", "figures/revisits.png"})
    EXPECT_TRUE(fs::exists(dir_ / "j1" / f)) << f;
}

TEST_F(BenchCliTest, RandomStartsAreTheSameForEveryMethodAndNotMixedWithWorldStarts) {
  const fs::path cfg = dir_ / "short.yaml";
  std::ofstream(cfg) << "episode:\n  max_time_s: 20\n";
  const fs::path fixed = dir_ / "fixed", random = dir_ / "random";
  const std::string args = "bench --worlds " + world() +
                           " --methods nearest_frontier,rrt --seeds 2 --config " + cfg.string() +
                           " --out ";
  auto [code, output] = run(args + fixed.string());
  ASSERT_EQ(code, 0) << output;
  std::tie(code, output) = run(args + random.string() + " --random-starts");
  ASSERT_EQ(code, 0) << output;

  std::map<std::string, nlohmann::json> start;  // by key
  for (const nlohmann::json& r : records(fixed)) {
    EXPECT_EQ(r["start_mode"], "world");
    start[key(r)] = r["start"];
  }
  const nlohmann::json world_start = start.at("rooms/rrt/1");
  EXPECT_EQ(start.at("rooms/rrt/2"), world_start);
  for (const nlohmann::json& r : records(random)) {
    EXPECT_EQ(r["start_mode"], "random");
    ASSERT_TRUE(r["start"].is_array() && r["start"].size() == 3u) << r["start"];
    // The recorded start is where the trajectory begins.
    EXPECT_EQ(r["trajectory"][0][1], r["start"][0]);
    EXPECT_EQ(r["trajectory"][0][2], r["start"][1]);
    start[key(r) + "/random"] = r["start"];
  }
  // The same seed starts both methods at the same pose; seeds differ from each other and from
  // the world's start.
  EXPECT_EQ(start.at("rooms/rrt/1/random"), start.at("rooms/nearest_frontier/1/random"));
  EXPECT_EQ(start.at("rooms/rrt/2/random"), start.at("rooms/nearest_frontier/2/random"));
  EXPECT_NE(start.at("rooms/rrt/1/random"), start.at("rooms/rrt/2/random"));
  EXPECT_NE(start.at("rooms/rrt/1/random"), world_start);

  // One results file holds one kind of start: resuming either into the other is an error
  // naming the file.
  std::tie(code, output) = run(args + fixed.string() + " --random-starts");
  EXPECT_EQ(code, 2) << output;
  EXPECT_NE(output.find((fixed / "results.jsonl").string()), std::string::npos) << output;
  EXPECT_NE(output.find("start_mode 'world'"), std::string::npos) << output;
  std::tie(code, output) = run(args + random.string());
  EXPECT_EQ(code, 2) << output;
  EXPECT_NE(output.find("start_mode 'random'"), std::string::npos) << output;
  EXPECT_EQ(records(fixed).size(), 4u);
  EXPECT_EQ(records(random).size(), 4u);

  // The report says so, and plans an oracle tour from each start (two starts: two tours).
  std::tie(code, output) = run("report " + random.string());
  ASSERT_EQ(code, 0) << output;
  std::ifstream in(random / "table1.md");
  std::stringstream table;
  table << in.rdbuf();
  EXPECT_NE(table.str().find("Every episode started at a pose drawn from its seed"),
            std::string::npos);
  EXPECT_TRUE(std::regex_search(
      table.str(), std::regex(R"(\| tiny \(1 world\) \| 1/1 \| [0-9.]+ ± [0-9.]+ \|)")))
      << table.str();
}

TEST_F(BenchCliTest, ShardsPartitionTheEpisodesAndReportMergesThem) {
  const std::string args =
      "bench --worlds " + world() + " --methods nearest_frontier,mmpf --seeds 3 --jobs 2 --out ";
  std::map<std::string, int> seen;
  for (int i = 1; i <= 2; ++i) {
    const fs::path out = dir_ / ("shard" + std::to_string(i));
    auto [code, output] = run(args + out.string() + " --shard " + std::to_string(i) + "/2");
    ASSERT_EQ(code, 0) << output;
    for (const nlohmann::json& r : records(out)) ++seen[key(r)];
  }
  EXPECT_EQ(seen.size(), 6u);
  for (const auto& [k, n] : seen) EXPECT_EQ(n, 1) << k;

  // Merging the two shards (and one of them again) counts every episode once.
  const fs::path merged = dir_ / "merged";
  auto [code, output] =
      run("report " + (dir_ / "shard1").string() + " " + (dir_ / "shard2").string() + " " +
          (dir_ / "shard1").string() + " --out " + merged.string());
  ASSERT_EQ(code, 0) << output;
  std::ifstream in(merged / "table1.csv");
  std::string header, line;
  std::getline(in, header);
  int episodes = 0;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string field;
    for (int i = 0; i < 6; ++i) std::getline(s, field, ',');
    episodes += std::stoi(field);  // column 6: episodes
  }
  EXPECT_EQ(episodes, 6);
}

TEST_F(BenchCliTest, BadInputsAreNamedWithExitCode2) {
  const fs::path out = dir_ / "bad";
  auto expectError = [&](const std::string& args, const std::vector<std::string>& parts) {
    const auto [code, output] = run(args);
    EXPECT_EQ(code, 2) << args << "\n" << output;
    for (const std::string& p : parts)
      EXPECT_NE(output.find(p), std::string::npos) << args << "\n" << output;
  };
  expectError("bench --worlds small_house --methods bogus --out " + out.string(),
              {"bogus", "nearest_frontier"});
  expectError("bench --worlds nowhere_house --methods rrt --out " + out.string(),
              {"nowhere_house", "small_house"});
  expectError("bench --worlds small_house --methods rrt --shard 3/2 --out " + out.string(),
              {"--shard", "3/2"});
  expectError("bench --worlds small_house --methods rrt --seeds 0 --out " + out.string(),
              {"--seeds"});
  expectError("bench --worlds small_house --methods rrt --jobs 0 --out " + out.string(),
              {"--jobs"});
  EXPECT_FALSE(fs::exists(out / "results.jsonl"));

  // A malformed line that is not the last one.
  fs::create_directories(out);
  std::ofstream(out / "results.jsonl")
      << "{\"world\": \"rooms\", \"method\": \"mmpf\", \"seed\": 1, \"exploration_rate\": 1}\n"
      << "this is not json\n"
      << "{\"world\": \"rooms\", \"method\": \"mmpf\", \"seed\": 2, \"exploration_rate\": 1}\n";
  expectError("bench --worlds " + world() + " --methods mmpf --seeds 1 --out " + out.string(),
              {"results.jsonl:2"});
  expectError("report " + out.string(), {"results.jsonl:2", "not a JSON line"});
  expectError("report " + (dir_ / "empty_dir").string(), {"empty_dir"});
  fs::create_directories(dir_ / "empty_dir");
  expectError("report " + (dir_ / "empty_dir").string(), {"no results.jsonl"});
}

TEST_F(BenchCliTest, ReportOfAHandWrittenFile) {
  const fs::path data =
      fs::path(ROOMSCOUT_SOURCE_DIR) / "tests" / "experiment" / "data" / "results_small.jsonl";
  const auto read = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  auto [code, output] = run("report " + data.string() + " --out " + (dir_ / "rep").string());
  ASSERT_EQ(code, 0) << output;
  // The built-in worlds get their oracle tour: L98 / oracle beside L98. T98 and L98 are over
  // seed 1 of small_house, the one pair both rrt and semantic finished.
  const std::string md = read(dir_ / "rep" / "table1.md");
  EXPECT_TRUE(std::regex_search(
      md, std::regex(R"(\| RRT \| 100\.0 \| 171 \| 20\.0 \| 31 \| 1\.00× \| 1\.00× \| )"
                     R"([0-9]+\.[0-9]{2}× \| 0/1 \(0 %\) \| 3/3 \(100 %\) \|)")))
      << md;
  EXPECT_NE(md.find("## Oracle reference"), std::string::npos) << md;
  for (const char* f :
       {"report.html", "figures/revisits.png", "figures/revisits.svg", "figures/revisits.pdf"})
    EXPECT_TRUE(fs::exists(dir_ / "rep" / f)) << f;
  // The records have no curves and no run outputs: no Fig. 5-7.
  EXPECT_FALSE(fs::exists(dir_ / "rep" / "figures" / "fig5_rate_small_house.png"));

  std::tie(code, output) =
      run("report " + data.string() + " --no-oracle --out " + (dir_ / "rep2").string());
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(
      read(dir_ / "rep2" / "table1.md")
          .find("| RRT | 100.0 | 171 | 20.0 | 31 | 1.00× | 1.00× | 0/1 (0 %) | 3/3 (100 %) |"),
      std::string::npos);
}

}  // namespace
