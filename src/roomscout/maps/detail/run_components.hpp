#pragma once
// Connected components of a binary image found on its horizontal runs: a union-find over the
// runs (a few per row) instead of a label per pixel. Gives the same components, areas and
// bounding boxes as cv::connectedComponentsWithStats at a fraction of its cost on maps,
// where long runs of free, unknown or wall cells are the rule, and lets callers fill or
// clear whole components run by run.

#include <cstdint>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace roomscout::maps {

/// One horizontal run of set pixels, [x_begin, x_end) on row y, and its component.
struct PixelRun {
  int y = 0;
  int x_begin = 0, x_end = 0;
  int component = 0;
};

/// Statistics of one component, as cv::connectedComponentsWithStats gives them.
struct RunComponent {
  int area = 0;                                    ///< pixels
  int min_x = 0, min_y = 0, max_x = 0, max_y = 0;  ///< bounding box, inclusive
};

/// The runs of an image (row-major) and its components, numbered 0.. in the order of their
/// first run.
struct RunComponents {
  std::vector<PixelRun> runs;
  std::vector<RunComponent> components;
};

/// Components of the pixels of a CV_8U image for which `is_set(value)` holds, 4- or
/// 8-connected. Throws InvalidArgument for another image type or connectivity.
template <class IsSet>
RunComponents runComponents(const cv::Mat& image, int connectivity, IsSet is_set);

/// Components of the non-zero pixels.
RunComponents runComponents(const cv::Mat& image, int connectivity);

namespace internal {
/// Joins the runs (already in row-major order) into components.
void joinRuns(RunComponents& result, int connectivity);
void checkRunInput(const cv::Mat& image, int connectivity);
}  // namespace internal

template <class IsSet>
RunComponents runComponents(const cv::Mat& image, int connectivity, IsSet is_set) {
  internal::checkRunInput(image, connectivity);
  RunComponents result;
  for (int y = 0; y < image.rows; ++y) {
    const std::uint8_t* row = image.ptr<std::uint8_t>(y);
    int x = 0;
    while (x < image.cols) {
      while (x < image.cols && !is_set(row[x])) ++x;
      if (x == image.cols) break;
      const int begin = x;
      while (x < image.cols && is_set(row[x])) ++x;
      result.runs.push_back({y, begin, x, 0});
    }
  }
  internal::joinRuns(result, connectivity);
  return result;
}

}  // namespace roomscout::maps
