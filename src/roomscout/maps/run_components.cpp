#include "roomscout/maps/detail/run_components.hpp"

#include <algorithm>

#include "roomscout/core/errors.hpp"

namespace roomscout::maps {
namespace internal {

void checkRunInput(const cv::Mat& image, int connectivity) {
  if (image.type() != CV_8U) throw InvalidArgument("runComponents: image must be CV_8U");
  if (connectivity != 4 && connectivity != 8)
    throw InvalidArgument("runComponents: connectivity must be 4 or 8");
}

void joinRuns(RunComponents& result, int connectivity) {
  std::vector<PixelRun>& runs = result.runs;
  const int n = static_cast<int>(runs.size());
  std::vector<int> parent(n);
  for (int i = 0; i < n; ++i) parent[i] = i;
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  // Runs of consecutive rows touch when their x ranges overlap (4-connectivity) or overlap
  // once widened by one pixel (8-connectivity: diagonal neighbours).
  const int reach = connectivity == 8 ? 1 : 0;
  int prev_begin = 0, prev_end = 0;  // runs of the previous row: [prev_begin, prev_end)
  for (int i = 0; i < n;) {
    const int y = runs[i].y;
    int end = i;
    while (end < n && runs[end].y == y) ++end;
    if (prev_end > prev_begin && runs[prev_begin].y != y - 1) prev_begin = prev_end;  // a gap row
    int j = prev_begin;
    for (int k = i; k < end; ++k) {
      const PixelRun& r = runs[k];
      while (j < prev_end && runs[j].x_end + reach <= r.x_begin) ++j;
      for (int m = j; m < prev_end && runs[m].x_begin < r.x_end + reach; ++m) {
        const int a = find(k), b = find(m);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    }
    prev_begin = i;
    prev_end = end;
    i = end;
  }
  // Components numbered by their first run; statistics per component.
  std::vector<int> id(n, -1);
  result.components.clear();
  for (int i = 0; i < n; ++i) {
    const int root = find(i);
    if (id[root] < 0) {
      id[root] = static_cast<int>(result.components.size());
      result.components.push_back({0, runs[i].x_begin, runs[i].y, runs[i].x_end - 1, runs[i].y});
    }
    PixelRun& r = runs[i];
    r.component = id[root];
    RunComponent& c = result.components[r.component];
    c.area += r.x_end - r.x_begin;
    c.min_x = std::min(c.min_x, r.x_begin);
    c.max_x = std::max(c.max_x, r.x_end - 1);
    c.min_y = std::min(c.min_y, r.y);
    c.max_y = std::max(c.max_y, r.y);
  }
}

}  // namespace internal

RunComponents runComponents(const cv::Mat& image, int connectivity) {
  return runComponents(image, connectivity, [](std::uint8_t v) { return v != 0; });
}

}  // namespace roomscout::maps
