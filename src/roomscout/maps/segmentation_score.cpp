#include "roomscout/maps/segmentation_score.hpp"

#include <algorithm>
#include <unordered_map>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout {

cv::Mat groundTruthRooms(const cv::Mat& gt_grey, int min_region_cells) {
  if (gt_grey.type() != CV_8U)
    throw InvalidArgument("groundTruthRooms: image must be CV_8U greyscale");
  cv::Mat rooms = gt_grey > 250;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(rooms, labels, stats, centroids, 8, CV_32S);
  std::vector<int> keep(n, 0);
  int next = 0;
  for (int i = 1; i < n; ++i) {
    if (stats.at<int>(i, cv::CC_STAT_AREA) > min_region_cells) keep[i] = ++next;
  }
  for (int y = 0; y < labels.rows; ++y) {
    int* row = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x) row[x] = keep[row[x]];
  }
  return labels;
}

SegmentationScore scoreSegmentation(const cv::Mat& segments, const cv::Mat& ground_truth,
                                    int min_region_cells) {
  if (segments.type() != CV_32S || ground_truth.type() != CV_32S ||
      segments.size() != ground_truth.size()) {
    throw InvalidArgument("scoreSegmentation: expects two CV_32S label images of the same size");
  }
  std::unordered_map<int, long> seg_size, gt_size;
  std::unordered_map<long long, long> overlap;
  for (int y = 0; y < segments.rows; ++y) {
    const int* s = segments.ptr<int>(y);
    const int* g = ground_truth.ptr<int>(y);
    for (int x = 0; x < segments.cols; ++x) {
      if (s[x] > 0) ++seg_size[s[x]];
      if (g[x] > 0) ++gt_size[g[x]];
    }
  }
  auto kept = [&](const std::unordered_map<int, long>& sizes, int l) {
    const auto it = sizes.find(l);
    return l > 0 && it != sizes.end() && it->second > min_region_cells;
  };
  for (int y = 0; y < segments.rows; ++y) {
    const int* s = segments.ptr<int>(y);
    const int* g = ground_truth.ptr<int>(y);
    for (int x = 0; x < segments.cols; ++x) {
      if (kept(seg_size, s[x]) && kept(gt_size, g[x]))
        ++overlap[(static_cast<long long>(s[x]) << 32) | g[x]];
    }
  }
  std::unordered_map<int, long> best_for_seg, best_for_gt;
  std::unordered_map<int, double> best_iou_for_gt;
  for (const auto& [key, o] : overlap) {
    const int s = static_cast<int>(key >> 32), g = static_cast<int>(key & 0xffffffff);
    best_for_seg[s] = std::max(best_for_seg[s], o);
    best_for_gt[g] = std::max(best_for_gt[g], o);
    const double iou = static_cast<double>(o) / static_cast<double>(seg_size[s] + gt_size[g] - o);
    best_iou_for_gt[g] = std::max(best_iou_for_gt[g], iou);
  }
  SegmentationScore score;
  double sum_r = 0, sum_p = 0, sum_iou = 0;
  long num_r = 0, den_r = 0, num_p = 0, den_p = 0;
  for (const auto& [g, size] : gt_size) {
    if (!kept(gt_size, g)) continue;
    ++score.ground_truth_rooms;
    const long b = best_for_gt.count(g) ? best_for_gt[g] : 0;
    sum_r += static_cast<double>(b) / size;
    sum_iou += best_iou_for_gt.count(g) ? best_iou_for_gt[g] : 0.0;
    num_r += b;
    den_r += size;
  }
  for (const auto& [s, size] : seg_size) {
    if (!kept(seg_size, s)) continue;
    ++score.segments;
    const long b = best_for_seg.count(s) ? best_for_seg[s] : 0;
    sum_p += static_cast<double>(b) / size;
    num_p += b;
    den_p += size;
  }
  if (score.ground_truth_rooms > 0) {
    score.recall = sum_r / score.ground_truth_rooms;
    score.iou = sum_iou / score.ground_truth_rooms;
    score.pooled_recall = static_cast<double>(num_r) / den_r;
  }
  if (score.segments > 0) {
    score.precision = sum_p / score.segments;
    score.pooled_precision = static_cast<double>(num_p) / den_p;
  }
  return score;
}

}  // namespace roomscout
