// The room segmentation benchmark of Bormann et al. (ICRA 2016), from ../shared/data (found
// through ROOMSCOUT_DATA_DIR): the per-room averages must stay at the level we measured.
// The full table is printed by `roomscout segment-eval`.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/segmentation_score.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

fs::path segmentationDir() {
  const char* dir = std::getenv("ROOMSCOUT_DATA_DIR");
  return dir ? fs::path(dir) / "room_segmentation" : fs::path();
}

struct Means {
  double recall = 0, precision = 0;
  int maps = 0;
};

Means evaluate(bool furnished) {
  const RoomSegmenter segmenter;
  const TopologyBuilder builder;
  Means m;
  for (const io::SegmentationDatasetMap& map : io::listSegmentationDataset(segmentationDir())) {
    if (furnished && !map.furnished_png) continue;
    const cv::Mat states =
        io::benchmarkStates(io::readGreyImage(furnished ? *map.furnished_png : map.plain_png));
    const SegmentationScore s =
        scoreSegmentation(segmenter.segment(states, 0.05).labels,
                          groundTruthRooms(io::readGreyImage(map.ground_truth_png)));
    // Every map yields a usable skeleton graph too.
    const TopologicalMap topo =
        builder.build(states, GridGeometry(Vec2::Zero(), 0.05, states.cols, states.rows), nullptr);
    EXPECT_GT(topo.edges().size(), 5u) << map.name;
    EXPECT_GT(s.recall, 0.8) << map.name;
    EXPECT_GT(s.precision, 0.75) << map.name;
    m.recall += s.recall;
    m.precision += s.precision;
    ++m.maps;
  }
  m.recall /= m.maps;
  m.precision /= m.maps;
  return m;
}

class RoomSegmentationDataset : public ::testing::Test {
 protected:
  void SetUp() override {
    // The data set is part of the test environment: a missing one is a failure, not a skip.
    ASSERT_NE(std::getenv("ROOMSCOUT_DATA_DIR"), nullptr)
        << "set ROOMSCOUT_DATA_DIR to the shared data folder";
    ASSERT_TRUE(fs::is_directory(segmentationDir())) << "not found: " << segmentationDir();
  }
};

TEST_F(RoomSegmentationDataset, PlainMaps) {
  const Means m = evaluate(false);
  EXPECT_EQ(m.maps, 10);
  EXPECT_GE(m.recall, 0.97);
  EXPECT_GE(m.precision, 0.95);
}

TEST_F(RoomSegmentationDataset, FurnishedMaps) {
  const Means m = evaluate(true);
  EXPECT_EQ(m.maps, 10);
  EXPECT_GE(m.recall, 0.92);
  EXPECT_GE(m.precision, 0.95);
}

}  // namespace
}  // namespace roomscout
