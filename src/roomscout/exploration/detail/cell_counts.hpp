#pragma once
// How many cells of a box pass a test, for any square in it in four lookups (a summed-area
// table, cv::integral). Scratch of SemanticExplorer's components, rebuilt for each use.

#include <algorithm>
#include <cstdint>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace roomscout {

class CellCounts {
 public:
  /// Counts test(x, y) over the cells [x0, x1] x [y0, y1].
  template <class Test>
  void build(int x0, int y0, int x1, int y1, Test test) {
    x0_ = x0;
    y0_ = y0;
    x1_ = x1;
    y1_ = y1;
    mask_.create(y1 - y0 + 1, x1 - x0 + 1, CV_8U);
    for (int y = y0; y <= y1; ++y) {
      auto* row = mask_.ptr<std::uint8_t>(y - y0);
      for (int x = x0; x <= x1; ++x) row[x - x0] = test(x, y) ? 1 : 0;
    }
    cv::integral(mask_, sums_, CV_32S);
  }

  /// The cells passing the test in the square of half-side r cells around (cx, cy), within
  /// the box.
  int square(int cx, int cy, int r) const {
    const int qx0 = std::clamp(cx - r, x0_, x1_ + 1) - x0_,
              qx1 = std::clamp(cx + r + 1, x0_, x1_ + 1) - x0_;
    const int qy0 = std::clamp(cy - r, y0_, y1_ + 1) - y0_,
              qy1 = std::clamp(cy + r + 1, y0_, y1_ + 1) - y0_;
    auto at = [&](int x, int y) { return sums_.at<int>(y, x); };
    return at(qx1, qy1) - at(qx0, qy1) - at(qx1, qy0) + at(qx0, qy0);
  }

 private:
  int x0_ = 0, y0_ = 0, x1_ = -1, y1_ = -1;
  cv::Mat mask_, sums_;
};

}  // namespace roomscout
