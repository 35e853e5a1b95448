#include "roomscout/maps/grid_image.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout::maps {

namespace {

/// OccupancyGrid::state() as branch-free arithmetic that the compiler vectorises: the grid
/// compares each log-odds value with its thresholds cast to float, and so does this.
struct StateRule {
  float occupied, free;
  explicit StateRule(const OccupancyGrid& grid)
      : occupied(static_cast<float>(grid.options().occupied_threshold)),
        free(static_cast<float>(grid.options().free_threshold)) {}
  std::uint8_t operator()(float l) const {
    static_assert(static_cast<int>(CellState::kUnknown) == 0 && static_cast<int>(CellState::kFree) == 1 &&
                  static_cast<int>(CellState::kOccupied) == 2);
    // free_threshold < 0 < occupied_threshold (validated), so at most one term is 1.
    return static_cast<std::uint8_t>((l > occupied) * 2 + (l < free));
  }
};

}  // namespace

cv::Mat stateImage(const OccupancyGrid& grid) {
  cv::Mat image;
  stateImage(grid, image);
  return image;
}

void stateImage(const OccupancyGrid& grid, cv::Mat& image) {
  const GridGeometry& g = grid.geometry();
  image.create(g.height(), g.width(), CV_8U);
  const StateRule rule(grid);
  for (int y = 0; y < g.height(); ++y) {
    auto* row = image.ptr<std::uint8_t>(y);
    const std::size_t first = g.index(Cell{0, y});
    for (int x = 0; x < g.width(); ++x) row[x] = rule(grid.logOdds(first + static_cast<std::size_t>(x)));
  }
}

std::size_t knownCellCount(const OccupancyGrid& grid) {
  const StateRule rule(grid);
  const std::size_t n = grid.geometry().cellCount();
  std::size_t known = 0;
  constexpr std::size_t kBlock = 4096;  // 32-bit partial sums vectorise better
  for (std::size_t start = 0; start < n; start += kBlock) {
    const std::size_t end = std::min(n, start + kBlock);
    std::uint32_t block = 0;
    for (std::size_t i = start; i < end; ++i) block += rule(grid.logOdds(i)) != 0;
    known += block;
  }
  return known;
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
