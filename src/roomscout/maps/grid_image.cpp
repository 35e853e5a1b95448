#include "roomscout/maps/grid_image.hpp"

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout::maps {

cv::Mat stateImage(const OccupancyGrid& grid) {
  const GridGeometry& g = grid.geometry();
  cv::Mat image(g.height(), g.width(), CV_8U);
  const std::vector<CellState> states = grid.states();
  for (int y = 0; y < g.height(); ++y) {
    auto* row = image.ptr<std::uint8_t>(y);
    for (int x = 0; x < g.width(); ++x) row[x] = static_cast<std::uint8_t>(states[g.index(Cell{x, y})]);
  }
  return image;
}

cv::Rect knownBounds(const cv::Mat& states, int margin) {
  if (states.type() != CV_8U) throw InvalidArgument("knownBounds: states must be CV_8U");
  const cv::Mat known = states != static_cast<std::uint8_t>(CellState::kUnknown);
  const cv::Rect r = cv::boundingRect(known);
  if (r.empty()) return {};
  return cv::Rect(r.x - margin, r.y - margin, r.width + 2 * margin, r.height + 2 * margin) &
         cv::Rect(0, 0, states.cols, states.rows);
}

cv::Mat fillableFreeSpace(const cv::Mat& states, int max_blob_area_px, int max_blob_extent_px) {
  if (states.type() != CV_8U) throw InvalidArgument("fillableFreeSpace: states must be CV_8U");
  const auto kFree = static_cast<std::uint8_t>(CellState::kFree);
  cv::Mat space = (states == kFree);
  if (max_blob_area_px <= 0 || states.empty()) return space;

  // Components of everything not free: a blob of furniture seen from all sides, or a cabinet
  // whose inside was never seen (an occupied rim around unknown cells). A wall seen only in
  // part joins the large unknown outside and is never small.
  const cv::Mat not_free = (states != kFree);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(not_free, labels, stats, centroids, 8, CV_32S);
  std::vector<std::uint8_t> candidate(n, 0);
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const bool touches_border = x == 0 || y == 0 || x + w == states.cols || y + h == states.rows;
    candidate[i] = !touches_border && stats.at<int>(i, cv::CC_STAT_AREA) <= max_blob_area_px &&
                   std::max(w, h) <= max_blob_extent_px;
  }
  for (int y = 0; y < states.rows; ++y) {
    const int* lrow = labels.ptr<int>(y);
    auto* out = space.ptr<std::uint8_t>(y);
    for (int x = 0; x < states.cols; ++x) {
      if (lrow[x] != 0 && candidate[lrow[x]]) out[x] = 255;
    }
  }
  return space;
}

}  // namespace roomscout::maps
