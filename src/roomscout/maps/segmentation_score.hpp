#pragma once
// Scores a room segmentation against ground-truth rooms with the protocol of Bormann et al.,
// "Room Segmentation: Survey, Implementation, and Analysis" (ICRA 2016), as described in
// ../shared/data/README.md: overlap matrix in cells, per-room average and pooled recall and
// precision, regions of at most `min_region_cells` cells dropped on both sides.

#include <vector>

#include <opencv2/core/mat.hpp>

namespace roomscout {

/// Scores of one segmentation, each in [0, 1].
struct SegmentationScore {
  int ground_truth_rooms = 0;
  int segments = 0;
  double recall = 0.0;            ///< mean over rooms g of max_s |s ∩ g| / |g|
  double precision = 0.0;         ///< mean over segments s of max_g |s ∩ g| / |s|
  double pooled_recall = 0.0;     ///< Σ_g max_s |s ∩ g| / Σ_g |g|
  double pooled_precision = 0.0;  ///< Σ_s max_g |s ∩ g| / Σ_s |s|
  double iou = 0.0;               ///< mean over rooms g of max_s |s ∩ g| / |s ∪ g|
};

/// Ground-truth rooms from a benchmark image (grey, CV_8U): cells > 250 are room space,
/// each 8-connected region of it is a room; regions of at most `min_region_cells` cells are
/// dropped. Returns CV_32S labels, 0 = none.
cv::Mat groundTruthRooms(const cv::Mat& gt_grey, int min_region_cells = 100);

/// Scores `segments` (CV_32S, 0 = none) against `ground_truth` (CV_32S, 0 = none), both the
/// same size. Labels of either with at most `min_region_cells` cells are ignored.
SegmentationScore scoreSegmentation(const cv::Mat& segments, const cv::Mat& ground_truth,
                                    int min_region_cells = 100);

}  // namespace roomscout
