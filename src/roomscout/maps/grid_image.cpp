#include "roomscout/maps/grid_image.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/detail/run_components.hpp"

namespace roomscout::maps {

cv::Mat stateView(const OccupancyGrid& grid) {
  const GridGeometry& g = grid.geometry();
  return cv::Mat(g.height(), g.width(), CV_8U, const_cast<std::uint8_t*>(grid.stateBytes()));
}

cv::Mat stateImage(const OccupancyGrid& grid) { return stateView(grid).clone(); }

void stateImage(const OccupancyGrid& grid, cv::Mat& image) { stateView(grid).copyTo(image); }

std::size_t knownCellCount(const OccupancyGrid& grid) {
  return grid.geometry().cellCount() == 0 ? 0 : knownCellCount(stateView(grid));
}

std::size_t knownCellCount(const cv::Mat& states) {
  // Unknown is 0, free and occupied are not.
  return states.empty() ? 0 : static_cast<std::size_t>(cv::countNonZero(states));
}

cv::Rect grown(const cv::Rect& r, int by, const cv::Size& size) {
  return cv::Rect(r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by) &
         cv::Rect(0, 0, size.width, size.height);
}

cv::Rect changedBounds(const cv::Mat& before, const cv::Mat& now) {
  cv::Mat changed;
  cv::compare(now, before, changed, cv::CMP_NE);
  return cv::boundingRect(changed);
}

std::optional<cv::Point> cellOffset(const GridGeometry& before, const GridGeometry& now) {
  const double res = now.resolution_m();
  if (std::abs(res - before.resolution_m()) > 1e-9) return std::nullopt;
  const double fx = (now.origin_m().x() - before.origin_m().x()) / res;
  const double fy = (now.origin_m().y() - before.origin_m().y()) / res;
  const double dx = std::round(fx), dy = std::round(fy);
  if (std::abs(fx - dx) > 1e-3 || std::abs(fy - dy) > 1e-3 || std::abs(dx) > 1e8 ||
      std::abs(dy) > 1e8)
    return std::nullopt;
  return cv::Point(static_cast<int>(dx), static_cast<int>(dy));
}

cv::Mat shifted(const cv::Mat& image, cv::Point offset, cv::Size size, const cv::Scalar& fill) {
  cv::Mat out(size, image.type(), fill);
  const cv::Rect dst = cv::Rect(-offset.x, -offset.y, image.cols, image.rows) &
                       cv::Rect(0, 0, size.width, size.height);
  if (!dst.empty()) image(dst + offset).copyTo(out(dst));
  return out;
}

cv::Rect knownBounds(const cv::Mat& states, int margin) {
  if (states.type() != CV_8U) throw InvalidArgument("knownBounds: states must be CV_8U");
  // Unknown is 0, free and occupied are not.
  const cv::Rect r = cv::boundingRect(states);
  if (r.empty()) return {};
  return grown(r, margin, states.size());
}

cv::Mat fillableFreeSpace(const cv::Mat& states, int max_blob_area_px, int max_blob_extent_px) {
  if (states.type() != CV_8U) throw InvalidArgument("fillableFreeSpace: states must be CV_8U");
  const auto kFree = static_cast<std::uint8_t>(CellState::kFree);
  cv::Mat space = (states == kFree);
  if (max_blob_area_px <= 0 || states.empty()) return space;

  // Components of everything not free: a blob of furniture seen from all sides, or a cabinet
  // whose inside was never seen (an occupied rim around unknown cells). A wall seen only in
  // part joins the large unknown outside and is never small.
  const RunComponents blobs =
      runComponents(states, 8, [kFree](std::uint8_t v) { return v != kFree; });
  std::vector<std::uint8_t> candidate(blobs.components.size(), 0);
  for (std::size_t i = 0; i < blobs.components.size(); ++i) {
    const RunComponent& c = blobs.components[i];
    const bool touches_border =
        c.min_x == 0 || c.min_y == 0 || c.max_x == states.cols - 1 || c.max_y == states.rows - 1;
    candidate[i] = !touches_border && c.area <= max_blob_area_px &&
                   std::max(c.max_x - c.min_x + 1, c.max_y - c.min_y + 1) <= max_blob_extent_px;
  }
  for (const PixelRun& r : blobs.runs) {
    if (candidate[r.component]) {
      std::uint8_t* row = space.ptr<std::uint8_t>(r.y);
      std::fill(row + r.x_begin, row + r.x_end, std::uint8_t{255});
    }
  }
  return space;
}

}  // namespace roomscout::maps
