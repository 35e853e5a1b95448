#include "roomscout/maps/thinning.hpp"

#include <vector>

#include "roomscout/core/errors.hpp"

namespace roomscout::maps {

cv::Mat thinZhangSuen(const cv::Mat& binary) {
  if (binary.type() != CV_8U) throw InvalidArgument("thinZhangSuen: image must be CV_8U");
  const int w = binary.cols, h = binary.rows;
  cv::Mat out = cv::Mat::zeros(h, w, CV_8U);
  if (w < 3 || h < 3) return out;
  std::vector<std::uint8_t> img(static_cast<std::size_t>(w) * h, 0);
  for (int y = 1; y + 1 < h; ++y) {
    const auto* row = binary.ptr<std::uint8_t>(y);
    for (int x = 1; x + 1 < w; ++x) img[y * w + x] = row[x] != 0;
  }
  // Neighbour offsets P2..P9: N, NE, E, SE, S, SW, W, NW (N = previous row).
  const int off[8] = {-w, -w + 1, 1, w + 1, w, w - 1, -1, -w - 1};
  auto isBorder = [&](int p) {
    if (!img[p]) return false;
    for (const int o : off) {
      if (!img[p + o]) return true;
    }
    return false;
  };
  std::vector<int> list;
  std::vector<std::uint8_t> listed(img.size(), 0);
  for (int y = 1; y + 1 < h; ++y) {
    for (int x = 1; x + 1 < w; ++x) {
      const int p = y * w + x;
      if (isBorder(p)) {
        list.push_back(p);
        listed[p] = 1;
      }
    }
  }
  std::vector<int> removed, next;
  for (bool changed = true; changed;) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {
      removed.clear();
      for (const int p : list) {
        if (!img[p]) continue;
        std::uint8_t n[8];
        int b = 0;
        for (int k = 0; k < 8; ++k) b += (n[k] = img[p + off[k]]);
        if (b < 2 || b > 6) continue;
        int a = 0;
        for (int k = 0; k < 8; ++k) a += (!n[k] && n[(k + 1) % 8]);
        if (a != 1) continue;
        const bool m1 = pass == 0 ? (n[0] && n[2] && n[4]) : (n[0] && n[2] && n[6]);
        const bool m2 = pass == 0 ? (n[2] && n[4] && n[6]) : (n[0] && n[4] && n[6]);
        if (m1 || m2) continue;
        removed.push_back(p);
      }
      if (removed.empty()) continue;
      changed = true;
      for (const int p : removed) img[p] = 0;
      // Next candidates: surviving listed pixels and the foreground neighbours of removed ones.
      next.clear();
      for (const int p : list) {
        if (img[p]) {
          next.push_back(p);
        } else {
          listed[p] = 0;
        }
      }
      for (const int p : removed) {
        for (const int o : off) {
          const int q = p + o;
          if (img[q] && !listed[q]) {
            listed[q] = 1;
            next.push_back(q);
          }
        }
      }
      list.swap(next);
    }
  }
  for (int y = 1; y + 1 < h; ++y) {
    auto* row = out.ptr<std::uint8_t>(y);
    for (int x = 1; x + 1 < w; ++x) row[x] = img[y * w + x] ? 255 : 0;
  }
  return out;
}

}  // namespace roomscout::maps
