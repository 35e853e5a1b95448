// The roomscout binary end to end: outputs of a run, and a clear error for each bad input.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

using roomscout::test::CommandResult;

class CliTest : public ::testing::Test {
 protected:
  CommandResult run(const std::string& args) { return roomscout::test::runRoomscout(args, dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }

  /// A map_server map: a 6 x 4 m room (0.05 m cells) with 0.1 m walls, split by a wall with a
  /// 1 m door.
  fs::path writeTwoRoomMap() {
    cv::Mat img(80, 120, CV_8U, cv::Scalar(254));
    img.rowRange(0, 2).setTo(0);
    img.rowRange(78, 80).setTo(0);
    img.colRange(0, 2).setTo(0);
    img.colRange(118, 120).setTo(0);
    img.colRange(60, 62).setTo(0);
    img(cv::Range(30, 50), cv::Range(60, 62)).setTo(254);
    cv::imwrite((dir_ / "rooms.pgm").string(), img);
    return write("rooms.yaml",
                 "image: rooms.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                 "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  }

  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(CliTest, ExploreMapServerWorldWritesEveryOutput) {
  const fs::path map = writeTwoRoomMap();
  const fs::path out = dir_ / "out";
  const CommandResult r = run("explore --world " + map.string() +
                              " --method nearest_frontier --seed 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Every output docs/cli.md lists, each with content, and nothing else (no temporary file
  // of an atomic write left behind).
  const std::set<std::string> documented = {
      "occupancy.pgm",  "occupancy.yaml", "trajectory.csv",      "run.png",
      "pointcloud.pcd", "pointcloud.png", "topology.json",       "topology.png",
      "semantic.json",  "semantic.png",   "semantic_labels.png", "metrics.json"};
  std::set<std::string> written;
  for (const auto& entry : fs::directory_iterator(out)) {
    written.insert(entry.path().filename().string());
    EXPECT_GT(fs::file_size(entry.path()), 0u) << entry.path().filename();
  }
  EXPECT_EQ(written, documented);
  std::ifstream in(out / "metrics.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  for (const char* key :
       {"world", "method", "seed", "exploration_rate", "t98_s", "l98_m", "t_done_s", "l_done_m",
        "revisits", "wall_time_s", "update_ms", "curve", "options"}) {
    EXPECT_TRUE(m.contains(key)) << key;
  }
  EXPECT_EQ(m["world"], "rooms");
  EXPECT_EQ(m["seed"], 3);
  EXPECT_GE(m["exploration_rate"].get<double>(), 0.98);
  EXPECT_TRUE(m["update_ms"]["occupancy"].contains("median"));
  EXPECT_TRUE(m["update_ms"]["occupancy"].contains("p95"));
  EXPECT_EQ(m["options"]["laser"]["num_beams"], 360);
  // The saved map is a map_server map of the same size as the world image.
  const cv::Mat pgm = cv::imread((out / "occupancy.pgm").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(pgm.cols, 120);
  EXPECT_EQ(pgm.rows, 80);
}

TEST_F(CliTest, SameSeedGivesSameMetricsFile) {
  const fs::path map = writeTwoRoomMap();
  auto metrics = [&](const std::string& out) {
    const CommandResult r =
        run("explore --world " + map.string() + " --seed 9 --out " + (dir_ / out).string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(dir_ / out / "metrics.json");
    nlohmann::json m = nlohmann::json::parse(in);
    m.erase("wall_time_s");
    m.erase("update_ms");
    return m;
  };
  EXPECT_EQ(metrics("a"), metrics("b"));
}

TEST_F(CliTest, ConfigFileOptionsAreApplied) {
  const fs::path map = writeTwoRoomMap();
  const fs::path cfg =
      write("cfg.yaml", "laser:\n  num_beams: 180\nnearest_frontier:\n  potential_scale: 2.0\n");
  const CommandResult r = run("explore --world " + map.string() + " --config " + cfg.string() +
                              " --out " + (dir_ / "o").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir_ / "o" / "metrics.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  EXPECT_EQ(m["options"]["laser"]["num_beams"], 180);
  EXPECT_EQ(m["options"]["nearest_frontier"]["potential_scale"], 2.0);
}

TEST_F(CliTest, MissingWorldFile) {
  const CommandResult r =
      run("explore --world " + (dir_ / "nope.yaml").string() + " --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("nope.yaml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no such file"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "o" / "metrics.json"));
}

TEST_F(CliTest, MalformedWorldFile) {
  const fs::path w = write("bad.yaml", "name: bad\nstart: [1, 1, 0]\nwalls: [[[0, 0], [4, 0]]\n");
  const CommandResult r = run("explore --world " + w.string() + " --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("bad.yaml"), std::string::npos) << r.output;
}

TEST_F(CliTest, WorldFileWithUnknownKey) {
  const fs::path w =
      write("typo.yaml",
            "name: typo\nstart: [1, 1, 0]\nwalls:\n  - [[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]]\n"
            "furniture:\n  - {name: box, box: {center: [2, 2], size: [1, 1]}, hight_m: 1}\n");
  const CommandResult r = run("explore --world " + w.string() + " --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("typo.yaml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("hight_m"), std::string::npos) << r.output;
}

TEST_F(CliTest, ImageWithNoFreePixel) {
  cv::imwrite((dir_ / "black.pgm").string(), cv::Mat(20, 20, CV_8U, cv::Scalar(0)));
  const fs::path y = write("black.yaml", "image: black.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  const CommandResult r = run("explore --world " + y.string() + " --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("black.pgm"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("no free pixel"), std::string::npos) << r.output;
}

TEST_F(CliTest, StartInsideAWallOrOutsideTheMap) {
  const fs::path map = writeTwoRoomMap();
  CommandResult r =
      run("explore --world " + map.string() + " --start 0.02,2.0,0 --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("rooms.yaml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("inside or too close"), std::string::npos) << r.output;
  r = run("explore --world " + map.string() + " --start 40,2.0,0 --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("outside the map"), std::string::npos) << r.output;
  r = run("explore --world " + map.string() + " --start 1,abc --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("--start"), std::string::npos) << r.output;
}

TEST_F(CliTest, UnknownMethodListsKnownOnes) {
  const CommandResult r =
      run("explore --world small_house --method bogus --out " + (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("bogus"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("nearest_frontier"), std::string::npos) << r.output;
}

TEST_F(CliTest, UnknownOptionInConfig) {
  const fs::path cfg = write("cfg.yaml", "laser:\n  num_beam: 180\n");
  const CommandResult r = run("explore --world small_house --config " + cfg.string() + " --out " +
                              (dir_ / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("cfg.yaml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("num_beam"), std::string::npos) << r.output;
}

TEST_F(CliTest, UnknownNoiseProfileOrSlamModeNamesTheKeyAndLeavesNoOutputDirectory) {
  for (const std::string& text :
       {std::string("noise:\n  profile: loud\n"), std::string("slam:\n  mode: gmapping\n")}) {
    const fs::path cfg = write("cfg.yaml", text);
    const fs::path out = dir_ / "new" / "out";
    const CommandResult r =
        run("explore --world small_house --config " + cfg.string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("cfg.yaml"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(text.find("loud") != std::string::npos ? "noise.profile" : "slam.mode"),
              std::string::npos)
        << r.output;
    // The failed run removed the directory it had created; the existing parent stays.
    EXPECT_FALSE(fs::exists(out)) << r.output;
  }
  // A directory that existed before the run is never removed.
  fs::create_directories(dir_ / "kept");
  const CommandResult r =
      run("explore --world small_house --method bogus --out " + (dir_ / "kept").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(fs::is_directory(dir_ / "kept"));
}

TEST_F(CliTest, NegativeSeedIsRefused) {
  const CommandResult r =
      run("explore --world small_house --seed -5 --out " + (dir_ / "o").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--seed"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "o"));
}

TEST_F(CliTest, OutputDirectoryNotWritable) {
  write("file", "x");
  const CommandResult r =
      run("explore --world small_house --out " + (dir_ / "file" / "sub").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("file"), std::string::npos) << r.output;
}

TEST_F(CliTest, WorldsListsTheBuiltIns) {
  const CommandResult r = run("worlds");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* w : {"small_house", "medium_house", "large_office"}) {
    EXPECT_NE(r.output.find(w), std::string::npos) << r.output;
  }
}

}  // namespace
