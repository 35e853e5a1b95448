#include "roomscout/maps/detail/thinning.hpp"

#include <array>
#include <vector>

#include "roomscout/core/errors.hpp"

namespace roomscout::maps {
namespace {

/// Zhang-Suen's deletion rule for one sub-iteration, tabulated over the 8-neighbourhood
/// code (bit k set = neighbour P(k+2) is foreground; P2..P9 = N, NE, E, SE, S, SW, W, NW).
constexpr std::array<std::uint8_t, 256> deletionTable(int pass) {
  std::array<std::uint8_t, 256> table{};
  for (int code = 0; code < 256; ++code) {
    bool n[8] = {};
    int b = 0;
    for (int k = 0; k < 8; ++k) b += (n[k] = (code >> k) & 1);
    int a = 0;
    for (int k = 0; k < 8; ++k) a += (!n[k] && n[(k + 1) % 8]);
    const bool m1 = pass == 0 ? (n[0] && n[2] && n[4]) : (n[0] && n[2] && n[6]);
    const bool m2 = pass == 0 ? (n[2] && n[4] && n[6]) : (n[0] && n[4] && n[6]);
    table[code] = b >= 2 && b <= 6 && a == 1 && !m1 && !m2;
  }
  return table;
}

constexpr std::array<std::uint8_t, 256> kDelete[2] = {deletionTable(0), deletionTable(1)};

}  // namespace

cv::Mat thinZhangSuen(const cv::Mat& binary) {
  if (binary.type() != CV_8U) throw InvalidArgument("thinZhangSuen: image must be CV_8U");
  const int w = binary.cols, h = binary.rows;
  cv::Mat out = cv::Mat::zeros(h, w, CV_8U);
  if (w < 3 || h < 3) return out;
  // Working image: 1 = foreground; bit 1 (listed[0]) and bit 2 (listed[1]) mark the pixels
  // queued for the next sub-iteration of each kind.
  std::vector<std::uint8_t> img(static_cast<std::size_t>(w) * h, 0);
  for (int y = 1; y + 1 < h; ++y) {
    const auto* row = binary.ptr<std::uint8_t>(y);
    std::uint8_t* dst = img.data() + static_cast<std::size_t>(y) * w;
    for (int x = 1; x + 1 < w; ++x) dst[x] = row[x] != 0;
  }
  // Neighbour offsets P2..P9: N, NE, E, SE, S, SW, W, NW (N = previous row). off[k + 4] is
  // -off[k]: pixel p is neighbour (k + 4) % 8 of its neighbour p + off[k].
  const int off[8] = {-w, -w + 1, 1, w + 1, w, w - 1, -1, -w - 1};
  // Every pixel's 8-neighbourhood code (bit k: neighbour k is foreground), kept up to date as
  // pixels are deleted, so that testing a pixel is one table lookup.
  std::vector<std::uint8_t> code(img.size(), 0);
  for (int y = 1; y + 1 < h; ++y) {
    const std::uint8_t* up = img.data() + static_cast<std::size_t>(y - 1) * w;
    const std::uint8_t* mid = up + w;
    const std::uint8_t* down = mid + w;
    std::uint8_t* c = code.data() + static_cast<std::size_t>(y) * w;
    for (int x = 1; x + 1 < w; ++x) {
      c[x] = static_cast<std::uint8_t>(up[x] | up[x + 1] << 1 | mid[x + 1] << 2 | down[x + 1] << 3 |
                                       down[x] << 4 | down[x - 1] << 5 | mid[x - 1] << 6 |
                                       up[x - 1] << 7);
    }
  }
  // A pixel's verdict in a sub-iteration depends only on its 8-neighbourhood and on the kind
  // of sub-iteration. So each kind keeps its own queue: the border pixels at first, then the
  // foreground neighbours of deleted pixels; a pixel tested and kept is not tested again by
  // that kind until a neighbour is deleted. Every pass still deletes exactly the pixels the
  // textbook full-image pass deletes (deletable pixels always have a background neighbour),
  // so the skeleton is the same, but skeleton pixels are not re-tested once per iteration.
  std::vector<int> queue[2], removed;
  constexpr std::uint8_t kQueued[2] = {2, 4};
  for (int y = 1; y + 1 < h; ++y) {
    for (int x = 1; x + 1 < w; ++x) {
      const int p = y * w + x;
      if (img[p] && code[p] != 0xFF) {
        queue[0].push_back(p);
        queue[1].push_back(p);
        img[p] |= kQueued[0] | kQueued[1];
      }
    }
  }
  for (int idle = 0, pass = 0; idle < 2; pass ^= 1) {
    // The textbook loop stops after an iteration (two sub-iterations) deletes nothing; an
    // idle sub-iteration followed by an idle one of the other kind is the same condition
    // once one full iteration has run.
    const auto& table = kDelete[pass];
    removed.clear();
    for (const int p : queue[pass]) {
      img[p] &= static_cast<std::uint8_t>(~kQueued[pass]);
      if ((img[p] & 1) && table[code[p]]) removed.push_back(p);
    }
    queue[pass].clear();
    if (removed.empty()) {
      ++idle;
      continue;
    }
    idle = 0;
    for (const int p : removed) {
      img[p] &= static_cast<std::uint8_t>(~1);
      for (int k = 0; k < 8; ++k)
        code[p + off[k]] &= static_cast<std::uint8_t>(~(1u << ((k + 4) & 7)));
    }
    for (const int p : removed) {
      for (const int o : off) {
        const int q = p + o;
        const std::uint8_t v = img[q];
        if (!(v & 1) || (v & (kQueued[0] | kQueued[1])) == (kQueued[0] | kQueued[1])) continue;
        for (int k = 0; k < 2; ++k) {
          if (!(v & kQueued[k])) queue[k].push_back(q);
        }
        img[q] = v | kQueued[0] | kQueued[1];
      }
    }
  }
  for (int y = 1; y + 1 < h; ++y) {
    auto* row = out.ptr<std::uint8_t>(y);
    const std::uint8_t* src = img.data() + static_cast<std::size_t>(y) * w;
    for (int x = 1; x + 1 < w; ++x) row[x] = (src[x] & 1) ? 255 : 0;
  }
  return out;
}

}  // namespace roomscout::maps
