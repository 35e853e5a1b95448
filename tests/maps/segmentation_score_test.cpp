// The benchmark protocol of Bormann et al. (ICRA 2016) on label images with known answers.

#include "roomscout/maps/segmentation_score.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout {
namespace {

cv::Mat fourRooms() {
  cv::Mat gt = cv::Mat::zeros(100, 100, CV_32S);
  gt(cv::Rect(0, 0, 50, 50)).setTo(1);
  gt(cv::Rect(50, 0, 50, 50)).setTo(2);
  gt(cv::Rect(0, 50, 50, 50)).setTo(3);
  gt(cv::Rect(50, 50, 50, 50)).setTo(4);
  return gt;
}

TEST(SegmentationScore, PerfectSegmentationScoresOne) {
  const cv::Mat gt = fourRooms();
  cv::Mat seg = gt * 7;  // other ids, same rooms
  const SegmentationScore s = scoreSegmentation(seg, gt);
  EXPECT_EQ(s.ground_truth_rooms, 4);
  EXPECT_EQ(s.segments, 4);
  EXPECT_DOUBLE_EQ(s.recall, 1.0);
  EXPECT_DOUBLE_EQ(s.precision, 1.0);
  EXPECT_DOUBLE_EQ(s.pooled_recall, 1.0);
  EXPECT_DOUBLE_EQ(s.pooled_precision, 1.0);
  EXPECT_DOUBLE_EQ(s.iou, 1.0);
}

TEST(SegmentationScore, OneSegmentScoresLowPrecision) {
  const cv::Mat gt = fourRooms();
  const cv::Mat seg = cv::Mat::ones(100, 100, CV_32S);
  const SegmentationScore s = scoreSegmentation(seg, gt);
  EXPECT_DOUBLE_EQ(s.recall, 1.0);
  EXPECT_DOUBLE_EQ(s.precision, 0.25);
  EXPECT_DOUBLE_EQ(s.pooled_precision, 0.25);
  EXPECT_DOUBLE_EQ(s.iou, 0.25);
}

TEST(SegmentationScore, OversegmentationScoresLowRecall) {
  const cv::Mat gt = cv::Mat::ones(100, 100, CV_32S);
  const SegmentationScore s = scoreSegmentation(fourRooms(), gt);
  EXPECT_DOUBLE_EQ(s.recall, 0.25);
  EXPECT_DOUBLE_EQ(s.precision, 1.0);
}

TEST(SegmentationScore, SmallRegionsAreDropped) {
  cv::Mat gt = fourRooms();
  cv::Mat seg = gt.clone();
  seg(cv::Rect(0, 0, 10, 10)).setTo(9);  // exactly 100 cells: dropped
  const SegmentationScore s = scoreSegmentation(seg, gt);
  EXPECT_EQ(s.segments, 4);
  EXPECT_DOUBLE_EQ(s.precision, 1.0);
  EXPECT_NEAR(s.recall, (0.96 + 3.0) / 4.0, 1e-12);
}

TEST(SegmentationScore, GroundTruthFromBenchmarkImage) {
  cv::Mat img(60, 100, CV_8U, cv::Scalar(255));
  img.col(50).setTo(0);  // a room border line
  img(cv::Rect(88, 0, 12, 8)).setTo(0);
  img(cv::Rect(92, 0, 5, 4)).setTo(255);  // 20 cells walled in: too small to be a room
  const cv::Mat rooms = groundTruthRooms(img);
  double max_id = 0;
  cv::minMaxLoc(rooms, nullptr, &max_id);
  EXPECT_EQ(max_id, 2);
  EXPECT_NE(rooms.at<int>(10, 10), rooms.at<int>(10, 70));
  EXPECT_EQ(rooms.at<int>(2, 94), 0);
}

TEST(SegmentationScore, RejectsMismatchedImages) {
  EXPECT_THROW(scoreSegmentation(cv::Mat::zeros(3, 3, CV_32S), cv::Mat::zeros(4, 3, CV_32S)),
               InvalidArgument);
  EXPECT_THROW(scoreSegmentation(cv::Mat::zeros(3, 3, CV_8U), cv::Mat::zeros(3, 3, CV_32S)),
               InvalidArgument);
}

}  // namespace
}  // namespace roomscout
