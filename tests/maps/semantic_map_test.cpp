// The semantic map: O(1) room lookup, region records, and ids that survive map growth.

#include "roomscout/maps/semantic_map.hpp"

#include <gtest/gtest.h>

#include <set>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "synthetic_maps.hpp"

namespace roomscout {
namespace {

using test::box;
const auto U = CellState::kUnknown;

GridGeometry geometryOf(const cv::Mat& m) { return GridGeometry(Vec2::Zero(), test::kRes, m.cols, m.rows); }

void updateWith(SemanticMap& map, const cv::Mat& states) {
  map.update(geometryOf(states), RoomSegmenter().segment(states, test::kRes).labels, states);
}

TEST(SemanticMap, RegionsAndLookup) {
  const cv::Mat m = test::threeRoomsAndCorridor();
  SemanticMap map;
  updateWith(map, m);
  ASSERT_EQ(map.regions().size(), 4u);
  double area = 0;
  for (const SemanticRegion& r : map.regions()) {
    EXPECT_EQ(map.roomAt(r.centroid_m), r.id);
    EXPECT_FALSE(r.open);
    EXPECT_GE(r.polygon_m.size(), 4u);
    area += r.area_m2;
  }
  EXPECT_NEAR(area, 16.0 * 2.0 + 3 * 5.25 * 7.9 + 3 * 0.9 * 0.1, 0.5);
  const int corridor = map.roomAt(Vec2(8.0, 1.2));
  const SemanticRegion* c = map.region(corridor);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->label, "corridor");
  EXPECT_EQ(c->neighbours.size(), 3u);  // one door into each room
  EXPECT_EQ(map.roomAt(Vec2(-5, -5)), 0);
  EXPECT_EQ(map.roomAt(Vec2(0.1, 0.1)), 0);  // a wall
  EXPECT_EQ(map.colourOf(3), SemanticMap::colourOf(3));
  EXPECT_NE(map.colourOf(3), SemanticMap::colourOf(4));
}

TEST(SemanticMap, IdsStableAcrossGrowingPartialMaps) {
  const cv::Mat full = test::threeRoomsAndCorridor();
  SemanticMap map;
  std::vector<Vec2> probes = {{2.5, 6}, {8.2, 6}, {13.5, 6}, {3, 1.2}};
  std::vector<int> first_id(probes.size(), 0);
  // The robot sees more and more, left to right.
  for (double seen_m : {5.0, 7.0, 9.0, 11.5, 14.0, 16.4}) {
    cv::Mat partial = full.clone();
    box(partial, seen_m, 0, 16.4, 10.4, U);
    updateWith(map, partial);
    for (std::size_t i = 0; i < probes.size(); ++i) {
      const int id = map.roomAt(probes[i]);
      if (probes[i].x() >= seen_m) continue;
      ASSERT_NE(id, 0) << "probe " << i << " seen " << seen_m;
      if (!first_id[i]) first_id[i] = id;
      EXPECT_EQ(id, first_id[i]) << "probe " << i << " changed id at seen " << seen_m;
    }
    // A room cut off by unknown space is open.
    if (seen_m < 16) {
      const SemanticRegion* corridor = map.region(map.roomAt(probes[3]));
      ASSERT_NE(corridor, nullptr);
      EXPECT_TRUE(corridor->open);
    }
  }
  const std::set<int> ids(first_id.begin(), first_id.end());
  EXPECT_EQ(ids.size(), probes.size());
  for (const SemanticRegion& r : map.regions()) EXPECT_FALSE(r.open);
  EXPECT_EQ(map.updateCount(), 6);
}

TEST(SemanticMap, ACopyKeepsItsRoomsWhenTheOriginalIsUpdated) {
  const cv::Mat m = test::threeRoomsAndCorridor();
  SemanticMap map;
  updateWith(map, m);
  const SemanticMap copy = map;  // shares the label image until the next update
  const cv::Mat before = map.labels().clone();
  // The same map with every room gone: an update of the same size.
  map.update(geometryOf(m), cv::Mat::zeros(m.size(), CV_32S), m);
  EXPECT_EQ(cv::countNonZero(map.labels()), 0);
  EXPECT_EQ(cv::countNonZero(copy.labels() != before), 0);
  EXPECT_EQ(copy.regions().size(), 4u);
}

TEST(SemanticMap, RejectsLabelsOfAnotherSize) {
  SemanticMap map;
  EXPECT_THROW(map.update(GridGeometry(Vec2::Zero(), 0.05, 4, 4), cv::Mat::zeros(3, 4, CV_32S), cv::Mat()),
               InvalidArgument);
}

}  // namespace
}  // namespace roomscout
