// Room segmentation of synthetic floor plans whose rooms are known.

#include "roomscout/maps/room_segmenter.hpp"

#include <gtest/gtest.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/segmentation_score.hpp"
#include "synthetic_maps.hpp"

namespace roomscout {
namespace {

using test::box;
using test::canvas;
const auto F = CellState::kFree;

TEST(RoomSegmenter, ThreeRoomsAndACorridor) {
  cv::Mat truth;
  const cv::Mat m = test::threeRoomsAndCorridor(&truth);
  const RoomSegmentation seg = RoomSegmenter().segment(m, test::kRes);
  EXPECT_EQ(seg.room_count, 4);
  const SegmentationScore s = scoreSegmentation(seg.labels, truth);
  EXPECT_GE(s.recall, 0.97);
  EXPECT_GE(s.precision, 0.97);
}

TEST(RoomSegmenter, OnlyFreeCellsAreLabelled) {
  const cv::Mat m = test::threeRoomsAndCorridor();
  const RoomSegmentation seg = RoomSegmenter().segment(m, test::kRes);
  for (int y = 0; y < m.rows; ++y) {
    for (int x = 0; x < m.cols; ++x) {
      if (m.at<std::uint8_t>(y, x) != test::v(F)) {
        EXPECT_EQ(seg.labels.at<int>(y, x), 0);
      } else {
        EXPECT_GT(seg.labels.at<int>(y, x), 0);
      }
    }
  }
}

TEST(RoomSegmenter, FurnitureDoesNotSplitARoom) {
  cv::Mat m = canvas(8, 6);
  box(m, 0.2, 0.2, 7.8, 5.8, F);
  for (int i = 0; i < 3; ++i)
    box(m, 1.5 + 2 * i, 2.5, 2.3 + 2 * i, 3.3, CellState::kOccupied);  // tables
  box(m, 0.2, 0.2, 1.0, 5.8, CellState::kOccupied);                    // a shelf along a wall
  const RoomSegmentation seg = RoomSegmenter().segment(m, test::kRes);
  EXPECT_EQ(seg.room_count, 1);
}

TEST(RoomSegmenter, WideHallIsNotSplitAtAPillar) {
  cv::Mat m = canvas(14, 8);
  box(m, 0.2, 0.2, 13.8, 7.8, F);
  box(m, 6.6, 3.6, 7.4, 4.4, CellState::kOccupied);
  EXPECT_EQ(RoomSegmenter().segment(m, test::kRes).room_count, 1);
}

TEST(RoomSegmenter, UnknownSpaceIsNeitherWallNorRoom) {
  cv::Mat truth;
  cv::Mat m = test::threeRoomsAndCorridor(&truth);
  box(m, 10.9, 0, 16.4, 10.4, CellState::kUnknown);  // the right room and corridor end unseen
  const RoomSegmentation seg = RoomSegmenter().segment(m, test::kRes);
  for (int y = 0; y < m.rows; ++y) {
    for (int x = 0; x < m.cols; ++x) {
      if (m.at<std::uint8_t>(y, x) == test::v(CellState::kUnknown)) {
        EXPECT_EQ(seg.labels.at<int>(y, x), 0);
      }
    }
  }
  EXPECT_EQ(seg.room_count, 3);  // two rooms and the corridor seen so far
}

TEST(RoomSegmenter, EmptyAndAllObstacleMaps) {
  EXPECT_EQ(RoomSegmenter().segment(cv::Mat(0, 0, CV_8U), 0.05).room_count, 0);
  EXPECT_EQ(RoomSegmenter().segment(canvas(3, 3), 0.05).room_count, 0);
}

TEST(RoomSegmenter, ResultsDoNotDependOnEarlierCalls) {
  // The segmenter keeps its buffers per thread between calls: maps of other sizes in between
  // change nothing.
  const cv::Mat a = test::threeRoomsAndCorridor();
  cv::Mat b = a.clone();
  box(b, 7.0, 0, 16.4, 10.4, CellState::kUnknown);
  const RoomSegmentation first = RoomSegmenter().segment(a, test::kRes);
  const cv::Mat big = cv::repeat(a, 2, 3);
  RoomSegmenter().segment(big, test::kRes);
  const RoomSegmentation partial = RoomSegmenter().segment(b, test::kRes);
  const RoomSegmentation again = RoomSegmenter().segment(a, test::kRes);
  EXPECT_EQ(again.room_count, first.room_count);
  EXPECT_EQ(cv::countNonZero(again.labels != first.labels), 0);
  EXPECT_GT(partial.room_count, 0);
  EXPECT_EQ(cv::countNonZero(RoomSegmenter().segment(b, test::kRes).labels != partial.labels), 0);
}

TEST(RoomSegmenter, RejectsBadInputAndOptions) {
  EXPECT_THROW(RoomSegmenter().segment(cv::Mat(3, 3, CV_32S), 0.05), InvalidArgument);
  EXPECT_THROW(RoomSegmenter().segment(canvas(1, 1), 0.0), InvalidArgument);
  RoomSegmenterOptions bad;
  bad.neck_ratio = 1.5;
  EXPECT_THROW(RoomSegmenter{bad}, OptionError);
  RoomSegmenterOptions options;
  EXPECT_EQ(options.parameters().size(), 12u);
}

}  // namespace
}  // namespace roomscout
