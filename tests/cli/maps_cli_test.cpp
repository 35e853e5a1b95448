// `roomscout maps`, `roomscout segment-eval` and the analysis maps of `roomscout explore`.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <sstream>
#include <string>

#include "../support/run_command.hpp"
#include "../support/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

class MapsCliTest : public ::testing::Test {
 protected:
  std::pair<int, std::string> run(const std::string& args) {
    return roomscout::test::asPair(roomscout::test::runRoomscout(args, dir_));
  }

  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }

  /// Two 3 x 4 m rooms joined by a 0.9 m door, as a map_server map.
  cv::Mat twoRoomImage() {
    cv::Mat img(84, 124, CV_8U, cv::Scalar(254));
    img.rowRange(0, 2).setTo(0);
    img.rowRange(82, 84).setTo(0);
    img.colRange(0, 2).setTo(0);
    img.colRange(122, 124).setTo(0);
    img.colRange(61, 63).setTo(0);
    img(cv::Range(33, 51), cv::Range(61, 63)).setTo(254);
    return img;
  }

  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(MapsCliTest, MapsBuildsBothMapsFromAMapServerMap) {
  cv::imwrite((dir_ / "rooms.pgm").string(), twoRoomImage());
  write("rooms.yaml",
        "image: rooms.pgm\nresolution: 0.05\norigin: [1.0, -2.0, 0.0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const auto [code, output] =
      run("maps --map " + (dir_ / "rooms.yaml").string() + " --out " + (dir_ / "out").string());
  ASSERT_EQ(code, 0) << output;
  for (const char* f :
       {"topology.json", "topology.png", "semantic.json", "semantic.png", "semantic_labels.png"}) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / f)) << f;
  }
  std::ifstream in(dir_ / "out" / "semantic.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["regions"].size(), 2u);
  EXPECT_DOUBLE_EQ(j["origin"][0].get<double>(), 1.0);
  const cv::Mat labels =
      cv::imread((dir_ / "out" / "semantic_labels.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(labels.type(), CV_16U);
  EXPECT_EQ(labels.size(), cv::Size(124, 84));
}

TEST_F(MapsCliTest, MapsRejectsAMalformedMap) {
  write("bad.yaml", "image: nothing.pgm\nresolution: -1\norigin: [0, 0, 0]\n");
  auto [code, output] =
      run("maps --map " + (dir_ / "bad.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(code, 2);
  EXPECT_NE(output.find("bad.yaml"), std::string::npos) << output;
  EXPECT_NE(output.find("error"), std::string::npos) << output;

  write("garbage.pgm", "this is not an image");
  write("garbage.yaml", "image: garbage.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  std::tie(code, output) =
      run("maps --map " + (dir_ / "garbage.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(code, 2);
  EXPECT_NE(output.find("garbage"), std::string::npos) << output;

  std::tie(code, output) =
      run("maps --map " + (dir_ / "missing.yaml").string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(code, 2);
  EXPECT_NE(output.find("missing.yaml"), std::string::npos) << output;
}

TEST_F(MapsCliTest, SegmentEvalScoresTwoRoomsNearOneHundredPercent) {
  const fs::path data = dir_ / "data";
  fs::create_directories(data);
  const cv::Mat map = twoRoomImage();
  cv::Mat plain = map.clone();
  plain.setTo(255, map == 254);
  cv::imwrite((data / "two.png").string(), plain);
  cv::Mat gt = plain.clone();
  gt(cv::Range(33, 51), cv::Range(61, 63)).setTo(0);  // the door closed: the border line
  cv::imwrite((data / "two_gt_segmentation.png").string(), gt);
  const auto [code, output] =
      run("segment-eval --dataset " + data.string() + " --out " + (dir_ / "eval").string());
  ASSERT_EQ(code, 0) << output;
  EXPECT_NE(output.find("two"), std::string::npos);
  std::ifstream in(dir_ / "eval" / "results.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_NEAR(j["summary"]["plain"]["recall"].get<double>(), 1.0, 0.01);
  EXPECT_NEAR(j["summary"]["plain"]["precision"].get<double>(), 1.0,
              0.01);  // door cells: in no room
  EXPECT_EQ(j["maps"][0]["segments"].get<int>(), 2) << j.dump();
}

TEST_F(MapsCliTest, SegmentEvalRejectsAFolderWithoutMaps) {
  const auto [code, output] =
      run("segment-eval --dataset " + (dir_ / "none").string() + " --out " + (dir_ / "e").string());
  EXPECT_EQ(code, 2);
  EXPECT_NE(output.find("none"), std::string::npos) << output;
}

TEST_F(MapsCliTest, ExploreWritesTopologyAndRooms) {
  const fs::path out = dir_ / "run";
  const auto [code, output] =
      run("explore --world small_house --method nearest_frontier --seed 1 --max-time 60 --out " +
          out.string());
  ASSERT_EQ(code, 0) << output;
  for (const char* f :
       {"topology.json", "topology.png", "semantic.json", "semantic.png", "semantic_labels.png"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  std::ifstream in(out / "metrics.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  EXPECT_TRUE(m["update_ms"].contains("topological"));
  EXPECT_TRUE(m["update_ms"].contains("semantic"));
  EXPECT_GE(m["update_ms"]["semantic"]["count"].get<int>(), 10);
  const cv::Mat occupancy = cv::imread((out / "occupancy.pgm").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat labels = cv::imread((out / "semantic_labels.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(labels.size(), occupancy.size());
}

}  // namespace
