// IncrementalRoomSegmenter: a map revealed piece by piece ends with the rooms a segmentation
// from scratch gives, rooms far from a change keep their cells, and the windows stay small.

#include "roomscout/maps/incremental_rooms.hpp"

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/room_segmenter.hpp"
#include "roomscout/maps/segmentation_score.hpp"
#include "synthetic_maps.hpp"

namespace roomscout {
namespace {

using test::geometryOf;
using test::kRes;
using test::roomRow;
using test::seenUpTo;
using test::v;

TEST(IncrementalRooms, ARevealedMapEndsWithTheRoomsOfASegmentationFromScratch) {
  cv::Mat truth;
  const cv::Mat full = roomRow(24, &truth);
  IncrementalRoomSegmenter rooms;
  for (double x = 3.0; x < full.cols * kRes + 1.0; x += 1.5) {
    const cv::Mat seen = seenUpTo(full, x);
    rooms.update(seen, geometryOf(seen));
  }
  const RoomSegmentation& inc = rooms.update(full, geometryOf(full));
  // Once the known map is twice a window's size (some 30 m), updates segment windows only.
  EXPECT_GT(rooms.windowUpdates(), 50);
  EXPECT_LT(rooms.fullUpdates(), 30);
  const RoomSegmentation scratch = RoomSegmenter().segment(full, kRes);
  EXPECT_EQ(inc.room_count, 25);
  EXPECT_EQ(inc.room_count, scratch.room_count);
  const SegmentationScore a = scoreSegmentation(inc.labels, truth);
  const SegmentationScore b = scoreSegmentation(scratch.labels, truth);
  EXPECT_NEAR(a.recall, b.recall, 0.005);
  EXPECT_NEAR(a.precision, b.precision, 0.005);
  EXPECT_GT(a.recall, 0.95);
  EXPECT_GT(a.precision, 0.95);
}

TEST(IncrementalRooms, RoomsFarFromAChangeKeepTheirCells) {
  cv::Mat truth;
  const cv::Mat full = roomRow(20, &truth);
  IncrementalRoomSegmenter rooms;
  const cv::Mat before = seenUpTo(full, 80.0);
  const cv::Mat first = rooms.update(before, geometryOf(before)).labels.clone();
  const cv::Mat after = seenUpTo(full, 82.0);
  const cv::Mat second = rooms.update(after, geometryOf(after)).labels;
  ASSERT_EQ(rooms.windowUpdates(), 1);
  // Nothing more than reach_m + margin_m from the change at x 80..82 m moves: not the rooms
  // there, and not the corridor's cells beyond (x < 60 m).
  for (int y = 0; y < full.rows; ++y) {
    for (int x = 0; x < static_cast<int>(60.0 / kRes); ++x) {
      ASSERT_EQ(first.at<int>(y, x) != 0, second.at<int>(y, x) != 0) << x << "," << y;
      ASSERT_EQ(first.at<int>(y, x), second.at<int>(y, x)) << x << "," << y;
    }
  }
}

TEST(IncrementalRooms, NothingChangedReturnsTheSameRooms) {
  cv::Mat truth;
  const cv::Mat full = roomRow(4, &truth);
  IncrementalRoomSegmenter rooms;
  const cv::Mat first = rooms.update(full, geometryOf(full)).labels.clone();
  const RoomSegmentation& again = rooms.update(full, geometryOf(full));
  EXPECT_EQ(cv::countNonZero(first != again.labels), 0);
  EXPECT_EQ(rooms.fullUpdates(), 1);
  EXPECT_EQ(rooms.windowUpdates(), 0);
}

TEST(IncrementalRooms, AGrownGridIsMatchedByMapPosition) {
  cv::Mat truth;
  const cv::Mat full = roomRow(6, &truth);
  IncrementalRoomSegmenter rooms;
  const cv::Mat first = rooms.update(full, geometryOf(full)).labels.clone();
  // The same map on a grid 2 m larger on every side (origin moved by -2 m).
  cv::Mat grown(full.rows + 80, full.cols + 80, CV_8U, cv::Scalar(v(CellState::kUnknown)));
  full.copyTo(grown(cv::Rect(40, 40, full.cols, full.rows)));
  const RoomSegmentation& moved = rooms.update(grown, geometryOf(grown, Vec2(-2.0, -2.0)));
  EXPECT_EQ(rooms.fullUpdates(), 1);
  EXPECT_EQ(cv::countNonZero(first != moved.labels(cv::Rect(40, 40, full.cols, full.rows))), 0);
  // A shift by half a cell cannot be matched cell by cell: the whole map is segmented.
  rooms.update(grown, geometryOf(grown, Vec2(-2.025, -2.0)));
  EXPECT_EQ(rooms.fullUpdates(), 2);
}

TEST(IncrementalRooms, FullShareZeroSegmentsTheWholeMapEachTime) {
  cv::Mat truth;
  const cv::Mat full = roomRow(6, &truth);
  IncrementalRoomSegmenter rooms({}, {2.5, 12.0, 0.0});
  for (double x = 5.0; x < 31.0; x += 5.0) {
    const cv::Mat seen = seenUpTo(full, x);
    const RoomSegmentation& inc = rooms.update(seen, geometryOf(seen));
    const RoomSegmentation scratch = RoomSegmenter().segment(seen, kRes);
    ASSERT_EQ(inc.room_count, scratch.room_count);
    ASSERT_EQ(cv::countNonZero(inc.labels != scratch.labels), 0) << x;
  }
  EXPECT_EQ(rooms.windowUpdates(), 0);
}

TEST(IncrementalRooms, RejectsBadInputAndOptions) {
  IncrementalRoomSegmenter rooms;
  const cv::Mat floats(10, 10, CV_32F, cv::Scalar(0));
  EXPECT_THROW(rooms.update(floats, GridGeometry(Vec2::Zero(), kRes, 10, 10)), InvalidArgument);
  const cv::Mat states(10, 10, CV_8U, cv::Scalar(0));
  EXPECT_THROW(rooms.update(states, GridGeometry(Vec2::Zero(), kRes, 12, 10)), InvalidArgument);
  EXPECT_THROW(IncrementalRoomSegmenter({}, {-1.0, 12.0, 0.5}), OptionError);
  EXPECT_THROW(IncrementalRoomSegmenter({}, {2.5, 12.0, 1.5}), OptionError);
  EXPECT_THROW(IncrementalRoomSegmenter({}, {2.5, 2.0, 0.5}), OptionError);
}

}  // namespace
}  // namespace roomscout
