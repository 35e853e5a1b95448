#include "roomscout/maps/room_segmenter.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/grid_image.hpp"

namespace roomscout {
namespace {

constexpr float kBinsPerCell = 4.0f;  // clearance quantisation: a quarter cell
constexpr int kSweepAhead = 16;       // cells between a prefetch and its use in the sweep

/// A room core found by the sweep: the connected part of {clearance bin > level} that holds
/// `pixel` (level -1: the whole component).
struct Core {
  int pixel = 0;
  int level = -1;
};

/// What the sweep keeps per component, at its root cell.
struct SweepRoot {
  int area = 0;       ///< cells of the component
  int peak_cell = 0;  ///< a cell of highest clearance
  int peak_core = 0;  ///< highest clearance bin << 1 | "holds a core"
  int peak() const { return peak_core >> 1; }
  bool core() const { return peak_core & 1; }
};

int findRoot(int* parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/// Buffers of one segmentation, kept per thread between calls so that an episode's updates
/// do not allocate (and page-fault) ten image-sized arrays each time. Invariants between
/// calls: every `parent` is -1, every `label` is 0, every bucket is empty (`clean`; a call
/// that did not finish, e.g. on bad_alloc, leaves it false and the next one resets them).
struct Scratch {
  cv::Mat space, cut_space, dist;
  std::vector<int> bin, start, order, label, stack, parent;
  std::vector<SweepRoot> root;
  std::vector<std::vector<int>> buckets;
  std::vector<Core> cores;
  bool clean = true;
};

Scratch& scratch() {
  thread_local Scratch s;
  if (!s.clean) {
    std::fill(s.parent.begin(), s.parent.end(), -1);
    std::fill(s.label.begin(), s.label.end(), 0);
    for (std::vector<int>& bucket : s.buckets) bucket.clear();
  }
  s.clean = false;
  return s;
}

/// Door cuts in the spirit of ROSE²'s wall lines, for axis-aligned walls: a straight run of
/// space between two wall ends that continue the same thin wall on both sides (jambs: a
/// straight obstacle at least `jamb` cells long with space on both of its faces within
/// `thick` cells) is a door in that wall. Clears the cut cells in `cut_space` (a copy of
/// `space`); `space` has a frame.
void cutDoors(const cv::Mat& space, cv::Mat& cut_space, int min_gap, int max_gap, int max_extension,
              int jamb, int thick) {
  if (max_gap <= 0 && max_extension <= 0) return;
  const int w = space.cols, h = space.rows;
  const std::uint8_t* sp = space.ptr<std::uint8_t>(0);
  std::uint8_t* out = cut_space.ptr<std::uint8_t>(0);
  for (const bool horizontal : {true, false}) {
    const int across = horizontal ? w : 1;
    const int lines = horizontal ? h : w, length = horizontal ? w : h;
    auto at = [&](int line, int pos) { return horizontal ? line * w + pos : pos * w + line; };
    auto isJamb = [&](int line, int pos, int dir) {
      // pos: first obstacle cell beyond the gap; the wall continues in direction dir.
      for (int i = 0; i < jamb; ++i) {
        const int q = pos + dir * i;
        if (q <= 0 || q >= length - 1) return false;
        const int p = at(line, q);
        if (sp[p]) return false;
        bool free_before = false, free_after = false;
        for (int t = 1; t <= thick && !(free_before && free_after); ++t) {
          if (line - t >= 0 && sp[p - t * across]) free_before = true;
          if (line + t < lines && sp[p + t * across]) free_after = true;
        }
        if (!free_before || !free_after) return false;
      }
      return true;
    };
    for (int line = 1; line + 1 < lines; ++line) {
      int pos = 1;
      while (pos < length - 1) {
        if (!sp[at(line, pos)]) {
          ++pos;
          continue;
        }
        const int start = pos;
        while (pos < length - 1 && sp[at(line, pos)]) ++pos;
        const int gap = pos - start;
        if (gap < min_gap || gap > std::max(max_gap, max_extension)) continue;
        const bool left = isJamb(line, start - 1, -1), right = isJamb(line, pos, +1);
        // A gap between two ends of the same wall is a door; a wall end that continues
        // across a gap to any obstacle is a wall line extended (a wide opening).
        if ((left && right && gap <= max_gap) || ((left || right) && gap <= max_extension)) {
          for (int q = start; q < pos; ++q) out[at(line, q)] = 0;
        }
      }
    }
  }
}

/// The segmentation of `states` (the known part of a map) into `labels` (CV_32S, zeros, same
/// size); returns the number of rooms.
int segmentKnown(const RoomSegmenterOptions& options, const cv::Mat& states, double resolution_m,
                 cv::Mat& labels) {
  Scratch& s = scratch();
  const double cell_area = resolution_m * resolution_m;
  // A one-cell frame of non-space lets the loops below skip bounds checks.
  cv::copyMakeBorder(
      maps::fillableFreeSpace(
          states, static_cast<int>(options.furniture_max_area_m2 / cell_area),
          static_cast<int>(std::ceil(options.furniture_max_extent_m / resolution_m))),
      s.space, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
  const cv::Mat& space = s.space;
  // Doors found as gaps in straight walls are cut before the cores are sought.
  space.copyTo(s.cut_space);
  cutDoors(space, s.cut_space,
           static_cast<int>(std::lround(options.door_cut_min_width_m / resolution_m)),
           static_cast<int>(std::lround(options.door_cut_max_width_m / resolution_m)),
           static_cast<int>(std::lround(options.wall_extension_max_m / resolution_m)),
           std::max(1, static_cast<int>(std::lround(options.jamb_min_length_m / resolution_m))),
           std::max(1, static_cast<int>(std::lround(options.wall_max_thickness_m / resolution_m))));
  cv::distanceTransform(s.cut_space, s.dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);

  const int w = space.cols;
  const int n = space.rows * space.cols;
  const std::uint8_t* sp = space.ptr<std::uint8_t>(0);
  const std::uint8_t* csp = s.cut_space.ptr<std::uint8_t>(0);
  const float* dp = s.dist.ptr<float>(0);
  // Clearance bins, read only on space cells (0 on the cuts).
  std::vector<int>& bin = s.bin;
  if (bin.size() < static_cast<std::size_t>(n)) bin.resize(n);
  int max_bin = 0;
  for (int i = 0; i < n; ++i) {
    if (!sp[i]) continue;
    bin[i] = static_cast<int>(dp[i] * kBinsPerCell);
    max_bin = std::max(max_bin, bin[i]);
  }
  // Cut-space cells sorted by decreasing clearance (counting sort, stable).
  std::vector<int>& start = s.start;
  start.assign(max_bin + 2, 0);
  for (int i = 0; i < n; ++i) {
    if (csp[i]) ++start[max_bin - bin[i] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int>& order = s.order;
  order.resize(start.back());
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int i = 0; i < n; ++i) {
      if (csp[i]) order[next[max_bin - bin[i]]++] = i;
    }
  }

  const double per_cell = kBinsPerCell / resolution_m;
  const int door_bin = static_cast<int>(0.5 * options.door_max_width_m * per_cell);
  const int core_bin = static_cast<int>(options.min_core_clearance_m * per_cell);
  const int min_room_cells = static_cast<int>(options.min_room_area_m2 / cell_area);
  const int min_isolated_cells = static_cast<int>(options.min_isolated_area_m2 / cell_area);
  const double ratio = options.neck_ratio;
  const int offsets[4] = {1, -1, w, -w};

  // Sweep of the superlevel sets of clearance (union-find). When a neck joins two components
  // that are both rooms (large enough, with a core far from walls) and the neck is narrow
  // for both, each becomes a core, unless it holds cores already.
  // The union-find's parents (-1: not swept yet) apart from the roots' data: the neighbour
  // tests and root walks, most of the sweep's memory traffic, read 4 bytes per cell.
  if (s.parent.size() < static_cast<std::size_t>(n)) s.parent.resize(n, -1);
  if (s.root.size() < static_cast<std::size_t>(n)) s.root.resize(n);
  int* parent = s.parent.data();
  SweepRoot* root = s.root.data();
  std::vector<Core>& cores = s.cores;
  cores.clear();
  auto isRoom = [&](int r) { return root[r].area >= min_room_cells && root[r].peak() >= core_bin; };
  const int swept = static_cast<int>(order.size());
  for (int rank = 0; rank <= max_bin; ++rank) {
    const int level = max_bin - rank;
    for (int i = start[rank]; i < start[rank + 1]; ++i) {
      // Cells come in clearance order, scattered over the map: fetch the parents of a cell's
      // neighbours (three rows) and its root slot a few cells ahead.
      if (i + kSweepAhead < swept) {
        const int ahead = order[i + kSweepAhead];
        __builtin_prefetch(parent + ahead - w, 1);
        __builtin_prefetch(parent + ahead, 1);
        __builtin_prefetch(parent + ahead + w, 1);
        __builtin_prefetch(root + ahead, 1);
      }
      const int p = order[i];
      parent[p] = p;
      root[p] = {1, p, level << 1};
      for (const int off : offsets) {
        const int q = p + off;
        if (parent[q] < 0) continue;
        int a = findRoot(parent, p), b = findRoot(parent, q);
        if (a == b) continue;
        if (level <= door_bin && isRoom(a) && isRoom(b) && level <= ratio * root[a].peak() &&
            level <= ratio * root[b].peak()) {
          for (const int r : {a, b}) {
            if (!root[r].core()) cores.push_back({root[r].peak_cell, level});
            root[r].peak_core |= 1;
          }
        }
        if (root[a].area < root[b].area) std::swap(a, b);
        SweepRoot& ra = root[a];
        const SweepRoot& rb = root[b];
        parent[b] = a;
        ra.area += rb.area;
        const int core = (ra.peak_core | rb.peak_core) & 1;
        if (rb.peak() > ra.peak()) {
          ra.peak_core = rb.peak_core;
          ra.peak_cell = rb.peak_cell;
        }
        ra.peak_core = (ra.peak_core & ~1) | core;
      }
    }
  }
  for (const int p : order) {
    const SweepRoot& rp = root[p];
    if (parent[p] == p && !rp.core() && rp.area >= min_isolated_cells)
      cores.push_back({rp.peak_cell, -1});
  }
  for (const int p : order) parent[p] = -1;

  // Cores become labels; they grow back into all of the space by decreasing clearance.
  std::vector<int>& label = s.label;
  if (label.size() < static_cast<std::size_t>(n)) label.resize(n, 0);
  std::vector<std::vector<int>>& buckets = s.buckets;
  if (buckets.size() < static_cast<std::size_t>(max_bin + 1)) buckets.resize(max_bin + 1);
  std::vector<int>& stack = s.stack;
  for (std::size_t k = 0; k < cores.size(); ++k) {
    const int id = static_cast<int>(k) + 1;
    stack.assign(1, cores[k].pixel);
    label[cores[k].pixel] = id;
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      buckets[bin[p]].push_back(p);
      for (const int off : offsets) {
        const int q = p + off;
        if (csp[q] && !label[q] && bin[q] > cores[k].level) {
          label[q] = id;
          stack.push_back(q);
        }
      }
    }
  }
  for (int level = max_bin; level >= 0; --level) {
    // Cells pushed while this level is processed land in this same bucket: index, not iterate.
    std::vector<int>& bucket = buckets[level];
    for (std::size_t i = 0; i < bucket.size(); ++i) {
      const int p = bucket[i];
      for (const int off : offsets) {
        const int q = p + off;
        if (sp[q] && !label[q]) {
          label[q] = label[p];
          buckets[std::min(level, bin[q])].push_back(q);
        }
      }
    }
    bucket.clear();
  }

  // Merge small segments into the neighbour they share the longest border with.
  const int count = static_cast<int>(cores.size());
  std::vector<int> seg_area(count + 1, 0);
  std::vector<std::map<int, int>> border(count + 1);
  const auto kFree = static_cast<std::uint8_t>(CellState::kFree);
  for (int y = 1; y + 1 < space.rows; ++y) {
    const std::uint8_t* st = states.ptr<std::uint8_t>(y - 1);
    const int* lrow = label.data() + static_cast<std::size_t>(y) * w;
    for (int x = 1; x + 1 < w; ++x) {
      const int l = lrow[x];
      if (!l) continue;
      if (st[x - 1] == kFree) ++seg_area[l];
      for (const int m : {lrow[x + 1], lrow[x + w]}) {
        if (m && m != l) {
          ++border[l][m];
          ++border[m][l];
        }
      }
    }
  }
  std::vector<int> merged_into(count + 1);
  std::iota(merged_into.begin(), merged_into.end(), 0);
  auto rep = [&](int l) {
    while (merged_into[l] != l) l = merged_into[l] = merged_into[merged_into[l]];
    return l;
  };
  std::vector<int> by_area(count);
  std::iota(by_area.begin(), by_area.end(), 1);
  std::stable_sort(by_area.begin(), by_area.end(),
                   [&](int a, int b) { return seg_area[a] < seg_area[b]; });
  for (const int seg : by_area) {
    if (rep(seg) != seg || seg_area[seg] >= min_room_cells) continue;
    int best = 0, best_len = 0;
    std::map<int, int> total;
    for (const auto& [nb, len] : border[seg]) {
      const int r = rep(nb);
      if (r != seg) total[r] += len;
    }
    for (const auto& [r, len] : total) {
      if (len > best_len) {
        best = r;
        best_len = len;
      }
    }
    if (!best) continue;
    merged_into[seg] = best;
    seg_area[best] += seg_area[seg];
    for (const auto& [nb, len] : total) {
      if (nb != best) {
        border[best][nb] += len;
        border[nb][best] += len;
      }
    }
  }

  // Only free cells carry labels; number rooms in row-major order of first appearance. The
  // scratch labels are cleared on the way (only space cells, all inside the frame, hold any).
  std::vector<int> final_id(count + 1, -1);
  final_id[0] = 0;
  int next = 0;
  for (int y = 0; y < states.rows; ++y) {
    const auto* srow = states.ptr<std::uint8_t>(y);
    int* lrow = label.data() + static_cast<std::size_t>(y + 1) * w + 1;
    int* out = labels.ptr<int>(y);
    for (int x = 0; x < states.cols; ++x) {
      const int l = lrow[x];
      if (!l) continue;
      lrow[x] = 0;
      if (srow[x] != kFree) continue;
      const int r = rep(l);
      if (seg_area[r] < min_isolated_cells) continue;
      if (final_id[r] < 0) final_id[r] = ++next;
      out[x] = final_id[r];
    }
  }
  s.clean = true;
  return next;
}

}  // namespace

void RoomSegmenterOptions::validate() const {
  if (!(furniture_max_area_m2 >= 0.0))
    throw OptionError("segmentation.furniture_max_area_m2 must be >= 0");
  if (!(furniture_max_extent_m >= 0.0))
    throw OptionError("segmentation.furniture_max_extent_m must be >= 0");
  if (!(door_cut_min_width_m >= 0.0 && door_cut_max_width_m >= 0.0)) {
    throw OptionError("segmentation.door_cut_min_width_m and door_cut_max_width_m must be >= 0");
  }
  if (!(wall_extension_max_m >= 0.0))
    throw OptionError("segmentation.wall_extension_max_m must be >= 0");
  if (!(jamb_min_length_m > 0.0)) throw OptionError("segmentation.jamb_min_length_m must be > 0");
  if (!(wall_max_thickness_m > 0.0))
    throw OptionError("segmentation.wall_max_thickness_m must be > 0");
  if (!(door_max_width_m > 0.0)) throw OptionError("segmentation.door_max_width_m must be > 0");
  if (!(neck_ratio > 0.0 && neck_ratio < 1.0))
    throw OptionError("segmentation.neck_ratio must be in (0, 1)");
  if (!(min_core_clearance_m >= 0.0))
    throw OptionError("segmentation.min_core_clearance_m must be >= 0");
  if (!(min_room_area_m2 >= 0.0)) throw OptionError("segmentation.min_room_area_m2 must be >= 0");
  if (!(min_isolated_area_m2 >= 0.0))
    throw OptionError("segmentation.min_isolated_area_m2 must be >= 0");
}

std::vector<ParameterRef> RoomSegmenterOptions::parameters() {
  return {
      {"furniture_max_area_m2", &furniture_max_area_m2,
       "enclosed obstacle blobs up to this area are filled [m^2]"},
      {"furniture_max_extent_m", &furniture_max_extent_m,
       "... and up to this bounding-box side [m]"},
      {"door_cut_min_width_m", &door_cut_min_width_m,
       "gaps in straight walls at least this wide ... [m]"},
      {"door_cut_max_width_m", &door_cut_max_width_m,
       "... and at most this wide are doors, cut first (0: off) [m]"},
      {"wall_extension_max_m", &wall_extension_max_m,
       "a wall end is extended across a gap up to this long to any obstacle, closing a wide "
       "opening (0: off) [m]"},
      {"jamb_min_length_m", &jamb_min_length_m,
       "a wall end counts as a door jamb when this long [m]"},
      {"wall_max_thickness_m", &wall_max_thickness_m, "... and at most this thick [m]"},
      {"door_max_width_m", &door_max_width_m, "necks wider than this never separate rooms [m]"},
      {"neck_ratio", &neck_ratio,
       "a neck separates cores when its half-width <= ratio * both cores' clearance"},
      {"min_core_clearance_m", &min_core_clearance_m,
       "a room core is at least this far from walls [m]"},
      {"min_room_area_m2", &min_room_area_m2, "smaller segments merge into a neighbour [m^2]"},
      {"min_isolated_area_m2", &min_isolated_area_m2,
       "smaller free patches without neighbours are no room [m^2]"},
  };
}

RoomSegmenter::RoomSegmenter(const RoomSegmenterOptions& options) : options_(options) {
  options_.validate();
}

RoomSegmentation RoomSegmenter::segment(const OccupancyGrid& grid) const {
  return segment(maps::stateView(grid), grid.geometry().resolution_m());
}

RoomSegmentation RoomSegmenter::segment(const cv::Mat& states, double resolution_m) const {
  if (states.type() != CV_8U) throw InvalidArgument("RoomSegmenter: states must be CV_8U");
  if (!(resolution_m > 0.0)) throw InvalidArgument("RoomSegmenter: resolution must be > 0");
  RoomSegmentation result;
  result.labels = cv::Mat::zeros(states.size(), CV_32S);
  if (states.empty()) return result;
  // Work on the known part only (a partial map is mostly unknown).
  const cv::Rect known = maps::knownBounds(states, 2);
  if (known.empty()) return result;
  cv::Mat labels = result.labels(known);
  result.room_count = segmentKnown(options_, states(known), resolution_m, labels);
  return result;
}

}  // namespace roomscout
