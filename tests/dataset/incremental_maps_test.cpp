// The rooms and the skeleton graph kept up to date while a real building's map is revealed
// square by square (the room segmentation benchmark's maps, see dataset_dir.hpp) end as a
// segmentation and a skeleton of the final map from scratch: rooms within half a point of
// per-room recall and precision, as the from-scratch rooms score them against ground truth,
// and skeleton nodes within one cell.

#include <gtest/gtest.h>

#include <filesystem>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "dataset_dir.hpp"
#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/maps/incremental_rooms.hpp"
#include "roomscout/maps/incremental_topology.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/segmentation_score.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace fs = std::filesystem;

namespace roomscout {
namespace {

constexpr double kRes = 0.05;
const auto kFree = static_cast<std::uint8_t>(CellState::kFree);
const auto kUnknown = static_cast<std::uint8_t>(CellState::kUnknown);

/// The map as known once the first `tiles` squares of `side` cells are seen, taken row by row
/// in boustrophedon order (a robot sweeping the building; every change stays local).
cv::Mat seenTiles(const cv::Mat& states, int side, int tiles) {
  const int per_row = (states.cols + side - 1) / side;
  cv::Mat out(states.size(), CV_8U, cv::Scalar(kUnknown));
  for (int t = 0; t < tiles; ++t) {
    const int row = t / per_row, col = row % 2 ? per_row - 1 - t % per_row : t % per_row;
    const cv::Rect tile =
        cv::Rect(col * side, row * side, side, side) & cv::Rect(0, 0, states.cols, states.rows);
    states(tile).copyTo(out(tile));
  }
  return out;
}

TEST(IncrementalMapsDataset, RevealedBuildingsEndAsMapsFromScratch) {
  ROOMSCOUT_DATASET_DIR(data);
  const fs::path folder = data / "room_segmentation";
  ASSERT_TRUE(fs::is_directory(folder)) << "not in the data set: " << data;
  int maps = 0, window_rooms = 0, window_skeletons = 0;
  for (const io::SegmentationDatasetMap& map : io::listSegmentationDataset(folder)) {
    SCOPED_TRACE(map.name);
    const cv::Mat states = io::benchmarkStates(io::readGreyImage(map.plain_png));
    const cv::Mat truth = groundTruthRooms(io::readGreyImage(map.ground_truth_png));
    const GridGeometry geometry(Vec2::Zero(), kRes, states.cols, states.rows);
    IncrementalRoomSegmenter rooms;
    IncrementalTopologyBuilder skeleton;
    // 6 m squares: a robot's view grows by about that much between updates.
    const int side = 120;
    const int tiles = ((states.cols + side - 1) / side) * ((states.rows + side - 1) / side);
    const cv::Mat& seen = states;
    TopologicalMap graph;
    for (int t = 1; t <= tiles; ++t) {
      const cv::Mat part = seenTiles(states, side, t);
      rooms.update(part, geometry);
      graph = skeleton.update(part, geometry, nullptr);
    }
    const SegmentationScore inc = scoreSegmentation(rooms.update(seen, geometry).labels, truth);
    const SegmentationScore scratch =
        scoreSegmentation(RoomSegmenter().segment(seen, kRes).labels, truth);
    EXPECT_NEAR(inc.recall, scratch.recall, 0.005);
    EXPECT_NEAR(inc.precision, scratch.precision, 0.005);
    const TopologicalMap whole = TopologyBuilder().build(seen, geometry, nullptr);
    EXPECT_EQ(graph.nodes().size(), whole.nodes().size());
    EXPECT_EQ(graph.edges().size(), whole.edges().size());
    int matched = 0;
    for (const TopoNode& n : graph.nodes()) {
      for (const TopoNode& m : whole.nodes()) {
        if (m.kind == n.kind && (m.position_m - n.position_m).norm() <= kRes + 1e-9) {
          ++matched;
          break;
        }
      }
    }
    EXPECT_EQ(matched, static_cast<int>(graph.nodes().size()));
    window_rooms += rooms.windowUpdates();
    window_skeletons += skeleton.windowUpdates();
    ++maps;
  }
  EXPECT_EQ(maps, 10);
  // The point: most updates were windows.
  EXPECT_GT(window_rooms, 100);
  EXPECT_GT(window_skeletons, 100);
}

}  // namespace
}  // namespace roomscout
