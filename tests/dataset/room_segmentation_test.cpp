// The room segmentation benchmark of Bormann et al. (ICRA 2016), from the shared data set (see
// dataset_dir.hpp): the per-room averages must stay at the level we measured.
// The full table is printed by `roomscout segment-eval`.

#include <gtest/gtest.h>

#include <filesystem>

#include "dataset_dir.hpp"
#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/segmentation_score.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

struct Means {
  double recall = 0, precision = 0;
  int maps = 0;
};

Means evaluate(const fs::path& folder, bool furnished) {
  const RoomSegmenter segmenter;
  const TopologyBuilder builder;
  Means m;
  for (const io::SegmentationDatasetMap& map : io::listSegmentationDataset(folder)) {
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

TEST(RoomSegmentationDataset, PlainMaps) {
  ROOMSCOUT_DATASET_DIR(data);
  ASSERT_TRUE(fs::is_directory(data / "room_segmentation")) << "not in the data set: " << data;
  const Means m = evaluate(data / "room_segmentation", false);
  EXPECT_EQ(m.maps, 10);
  EXPECT_GE(m.recall, 0.97);
  EXPECT_GE(m.precision, 0.95);
}

TEST(RoomSegmentationDataset, FurnishedMaps) {
  ROOMSCOUT_DATASET_DIR(data);
  ASSERT_TRUE(fs::is_directory(data / "room_segmentation")) << "not in the data set: " << data;
  const Means m = evaluate(data / "room_segmentation", true);
  EXPECT_EQ(m.maps, 10);
  EXPECT_GE(m.recall, 0.92);
  EXPECT_GE(m.precision, 0.95);
}

}  // namespace
}  // namespace roomscout
