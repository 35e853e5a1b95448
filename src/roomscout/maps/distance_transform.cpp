#include "roomscout/maps/distance_transform.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "roomscout/core/errors.hpp"

namespace roomscout::maps {

void distanceTransformL2(const cv::Mat& binary, cv::Mat& dist) {
  if (binary.type() != CV_8U) throw InvalidArgument("distanceTransformL2: image must be CV_8U");
  const int rows = binary.rows, cols = binary.cols;
  dist.create(rows, cols, CV_32F);
  if (binary.empty()) return;
  // Phase 1, per column: distance to the nearest zero pixel of the same column (a sentinel
  // beyond any real distance where the column has none), computed a row at a time so that
  // the loops run along memory.
  const int none = rows + cols + 1;
  thread_local std::vector<int> g_buffer;
  g_buffer.resize(static_cast<std::size_t>(rows) * cols);
  int* g = g_buffer.data();
  bool any_zero = false;
  for (int y = 0; y < rows; ++y) {
    const std::uint8_t* b = binary.ptr<std::uint8_t>(y);
    int* gy = g + static_cast<std::size_t>(y) * cols;
    const int* above = y > 0 ? gy - cols : nullptr;
    for (int x = 0; x < cols; ++x) {
      const int up = above ? std::min(above[x] + 1, none) : none;
      gy[x] = b[x] ? up : 0;
      any_zero = any_zero || !b[x];
    }
  }
  if (!any_zero) throw InvalidArgument("distanceTransformL2: image has no zero pixel");
  for (int y = rows - 2; y >= 0; --y) {
    int* gy = g + static_cast<std::size_t>(y) * cols;
    const int* below = gy + cols;
    for (int x = 0; x < cols; ++x) gy[x] = std::min(gy[x], below[x] + 1);
  }
  // Phase 2, per row: lower envelope of the parabolas (x - i)^2 + g(i)^2.
  thread_local std::vector<int> s_buffer, t_buffer;
  s_buffer.resize(cols);
  t_buffer.resize(cols);
  int* s = s_buffer.data();
  int* t = t_buffer.data();
  for (int y = 0; y < rows; ++y) {
    const int* gy = g + static_cast<std::size_t>(y) * cols;
    float* out = dist.ptr<float>(y);
    auto f = [&](std::int64_t x, int i) {
      return (x - i) * (x - i) + static_cast<std::int64_t>(gy[i]) * gy[i];
    };
    int q = 0;
    s[0] = 0;
    t[0] = 0;
    for (int u = 1; u < cols; ++u) {
      while (q >= 0 && f(t[q], s[q]) > f(t[q], u)) --q;
      if (q < 0) {
        q = 0;
        s[0] = u;
      } else {
        // First x where u's parabola is below s[q]'s (floor division; numerator >= 0 here).
        const std::int64_t gu = gy[u], gs = gy[s[q]];
        const std::int64_t sep =
            (static_cast<std::int64_t>(u) * u - static_cast<std::int64_t>(s[q]) * s[q] + gu * gu - gs * gs) /
            (2 * static_cast<std::int64_t>(u - s[q]));
        const std::int64_t w = 1 + sep;
        if (w < cols) {
          ++q;
          s[q] = u;
          t[q] = static_cast<int>(w);
        }
      }
    }
    for (int u = cols - 1; u >= 0; --u) {
      out[u] = std::sqrt(static_cast<float>(f(u, s[q])));
      if (u == t[q]) --q;
    }
  }
}

}  // namespace roomscout::maps
