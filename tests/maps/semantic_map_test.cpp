// The semantic map: O(1) room lookup, region records, and ids that survive map growth.

#include "roomscout/maps/semantic_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "synthetic_maps.hpp"

namespace roomscout {
namespace {

using test::box;
const auto U = CellState::kUnknown;

GridGeometry geometryOf(const cv::Mat& m) {
  return GridGeometry(Vec2::Zero(), test::kRes, m.cols, m.rows);
}

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

/// The cells of `plan` (origin (0, 0)) seen through a grid of `w` x `h` cells whose cell (0, 0)
/// is the plan's cell (ox, oy); cells off the plan are unknown.
cv::Mat frameOf(const cv::Mat& plan, int ox, int oy, int w, int h) {
  cv::Mat out(h, w, CV_8U, cv::Scalar(test::v(U)));
  const cv::Rect inside = cv::Rect(ox, oy, w, h) & cv::Rect(0, 0, plan.cols, plan.rows);
  plan(inside).copyTo(out(inside - cv::Point(ox, oy)));
  return out;
}

// A SLAM map grows on every side and its origin moves as it grows: rooms are matched by where
// they are in the map frame, not by cell index. The second frame moves the origin by the rooms'
// pitch (5.35 m), so that matching by index would give the west room the middle room's id.
TEST(SemanticMap, IdsAndColoursStableWhenTheGridGrowsAndItsOriginMoves) {
  const cv::Mat full = test::threeRoomsAndCorridor();
  cv::Mat seen = full.clone();
  box(seen, 11.0, 0, 16.4, 10.4, U);  // the east room not seen yet
  const std::vector<Vec2> probes = {{2.5, 6}, {8.2, 6}, {3, 1.2}};
  struct Frame {
    int ox, oy, w, h;  // cells of the plan
  };
  // The first map covers the known part with a small margin; each next one grows on every side,
  // its origin moving left and down (beyond the plan: a SLAM map is not bounded by the building).
  const int pitch = static_cast<int>(std::lround(5.35 / test::kRes));
  const Frame frames[] = {
      {-4, -4, 228, 216}, {-4 - pitch, -10, 228 + pitch + 20, 230}, {-30, -40, 400, 300}};
  SemanticMap map;
  std::vector<int> ids;
  std::vector<std::array<std::uint8_t, 3>> colours;
  std::vector<Vec2> centroids;
  for (std::size_t k = 0; k < std::size(frames); ++k) {
    const Frame& f = frames[k];
    if (k == 2) seen = full;  // the last map has the east room too
    const cv::Mat states = frameOf(seen, f.ox, f.oy, f.w, f.h);
    const GridGeometry g(Vec2(f.ox * test::kRes, f.oy * test::kRes), test::kRes, f.w, f.h);
    map.update(g, RoomSegmenter().segment(states, test::kRes).labels, states);
    ASSERT_EQ(map.geometry(), g);
    for (std::size_t i = 0; i < probes.size(); ++i) {
      const int id = map.roomAt(probes[i]);
      ASSERT_NE(id, 0) << "probe " << i << " frame " << k;
      const SemanticRegion* region = map.region(id);
      ASSERT_NE(region, nullptr);
      if (k == 0) {
        ids.push_back(id);
        colours.push_back(region->rgb);
        centroids.push_back(region->centroid_m);
        continue;
      }
      EXPECT_EQ(id, ids[i]) << "probe " << i << " changed id in frame " << k;
      EXPECT_EQ(region->rgb, colours[i]) << "probe " << i << " changed colour in frame " << k;
      // The rooms seen whole from the start stay where they were in the map frame.
      if (i < 2) {
        EXPECT_LT((region->centroid_m - centroids[i]).norm(), 0.05)
            << "probe " << i << " frame " << k;
      }
    }
  }
  EXPECT_EQ(std::set<int>(ids.begin(), ids.end()).size(), probes.size());
  // The east room, seen last, got an id of its own.
  const int east = map.roomAt(Vec2(13.5, 6));
  EXPECT_NE(east, 0);
  EXPECT_EQ(std::count(ids.begin(), ids.end(), east), 0);
  // Matching by cell index would have been wrong here: in the second frame the middle room
  // lies on the cells the west room had in the first.
  const GridGeometry g0(Vec2(-4 * test::kRes, -4 * test::kRes), test::kRes, 228, 216);
  const GridGeometry g1(Vec2((-4 - pitch) * test::kRes, -10 * test::kRes), test::kRes,
                        228 + pitch + 20, 230);
  const Cell west_in_g0 = g0.cellOf(probes[0]);
  EXPECT_GT(std::abs(g1.centerOf(west_in_g0).x() - probes[0].x()), 5.0);
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
  EXPECT_THROW(
      map.update(GridGeometry(Vec2::Zero(), 0.05, 4, 4), cv::Mat::zeros(3, 4, CV_32S), cv::Mat()),
      InvalidArgument);
}

}  // namespace
}  // namespace roomscout
