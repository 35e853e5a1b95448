// Files of the topological and semantic maps: JSON content, label image size and frame.

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/io/semantic_io.hpp"
#include "roomscout/io/topology_io.hpp"
#include "roomscout/maps/grid_image.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace roomscout::io {
namespace {

/// Two rooms joined by a door, left of x = 3 m; origin (-1, 2).
OccupancyGrid twoRooms() {
  OccupancyGrid grid(GridGeometry(Vec2(-1.0, 2.0), 0.05, 120, 80));
  const GridGeometry& g = grid.geometry();
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const bool wall =
          x < 2 || y < 2 || x >= 118 || y >= 78 || (x >= 60 && x < 62 && (y < 30 || y >= 48));
      grid.setState(g.index(Cell{x, y}), wall ? CellState::kOccupied : CellState::kFree);
    }
  }
  return grid;
}

TEST(AnalysisMapsIo, WritesSemanticFilesInTheOccupancyFrame) {
  test::TempDir dir;
  const OccupancyGrid grid = twoRooms();
  SemanticMap rooms;
  const cv::Mat states = maps::stateImage(grid);
  rooms.update(grid.geometry(), RoomSegmenter().segment(grid).labels, states);
  ASSERT_EQ(rooms.regions().size(), 2u);
  saveOccupancyMap(grid, dir / "occupancy.yaml");
  writeSemanticMap(dir.path(), rooms, grid, {{"note", "x"}});

  const cv::Mat occupancy = cv::imread((dir / "occupancy.pgm").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat labels = cv::imread((dir / "semantic_labels.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(labels.type(), CV_16U);
  ASSERT_EQ(labels.size(), occupancy.size());
  // Image row 0 is the top of the map: the left room's id at a point of the left room.
  const int left = rooms.roomAt(Vec2(0.0, 3.0));
  const Cell c = grid.geometry().cellOf(Vec2(0.0, 3.0));
  EXPECT_EQ(labels.at<std::uint16_t>(grid.geometry().height() - 1 - c.y, c.x), left);
  EXPECT_EQ(labels.at<std::uint16_t>(0, 0), 0);  // a wall
  EXPECT_FALSE(cv::imread((dir / "semantic.png").string()).empty());

  const nlohmann::json j = nlohmann::json::parse(readFile(dir / "semantic.json"));
  EXPECT_EQ(j["frame"], "map");
  EXPECT_DOUBLE_EQ(j["resolution"].get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(j["origin"][0].get<double>(), -1.0);
  EXPECT_EQ(j["note"], "x");
  ASSERT_EQ(j["regions"].size(), 2u);
  for (const auto& r : j["regions"]) {
    EXPECT_NEAR(r["area_m2"].get<double>(), 2.9 * 3.8, 0.4);
    EXPECT_EQ(r["colour"].get<std::string>().size(), 7u);
    EXPECT_GE(r["polygon"].size(), 4u);
    EXPECT_FALSE(r["open"].get<bool>());
    EXPECT_EQ(r["neighbours"].size(), 1u);
    for (const auto& p : r["polygon"]) {
      EXPECT_GE(p[0].get<double>(), -1.0);
      EXPECT_LE(p[0].get<double>(), 5.0);
      EXPECT_GE(p[1].get<double>(), 2.0);
    }
  }
}

TEST(AnalysisMapsIo, WritesTopologyFiles) {
  test::TempDir dir;
  const OccupancyGrid grid = twoRooms();
  const TopologicalMap topo = TopologyBuilder().build(grid);
  writeTopologicalMap(dir.path(), topo, grid);
  const nlohmann::json j = nlohmann::json::parse(readFile(dir / "topology.json"));
  EXPECT_EQ(j["nodes"].size(), topo.nodes().size());
  EXPECT_EQ(j["edges"].size(), topo.edges().size());
  ASSERT_FALSE(j["edges"].empty());
  for (const char* key : {"id", "u", "v", "length", "min_clearance", "polyline"})
    EXPECT_TRUE(j["edges"][0].contains(key));
  for (const char* key : {"id", "x", "y", "kind", "region_id", "clearance"})
    EXPECT_TRUE(j["nodes"][0].contains(key));
  EXPECT_FALSE(cv::imread((dir / "topology.png").string()).empty());
}

TEST(SegmentationDataset, ListsMapsWithGroundTruth) {
  test::TempDir dir;
  const cv::Mat img(20, 20, CV_8U, cv::Scalar(255));
  for (const char* f : {"a.png", "a_gt_segmentation.png", "a_furnitures.png", "b.png",
                        "b_gt_segmentation.png", "c.png"}) {
    cv::imwrite((dir / f).string(), img);
  }
  const auto maps = listSegmentationDataset(dir.path());
  ASSERT_EQ(maps.size(), 2u);
  EXPECT_EQ(maps[0].name, "a");
  EXPECT_TRUE(maps[0].furnished_png.has_value());
  EXPECT_FALSE(maps[1].furnished_png.has_value());
  EXPECT_THROW(listSegmentationDataset(dir / "missing"), InputError);
  test::TempDir empty;
  EXPECT_THROW(listSegmentationDataset(empty.path()), InputError);
  EXPECT_THROW(readGreyImage(dir / "nope.png"), InputError);
}

TEST(SegmentationDataset, BenchmarkBinarisation) {
  cv::Mat grey(1, 4, CV_8U);
  grey.at<std::uint8_t>(0, 0) = 249;
  grey.at<std::uint8_t>(0, 1) = 250;
  grey.at<std::uint8_t>(0, 2) = 255;
  grey.at<std::uint8_t>(0, 3) = 0;
  const cv::Mat s = benchmarkStates(grey);
  EXPECT_EQ(s.at<std::uint8_t>(0, 0), static_cast<std::uint8_t>(CellState::kOccupied));
  EXPECT_EQ(s.at<std::uint8_t>(0, 1), static_cast<std::uint8_t>(CellState::kFree));
  EXPECT_EQ(s.at<std::uint8_t>(0, 2), static_cast<std::uint8_t>(CellState::kFree));
  EXPECT_EQ(s.at<std::uint8_t>(0, 3), static_cast<std::uint8_t>(CellState::kOccupied));
}

}  // namespace
}  // namespace roomscout::io
