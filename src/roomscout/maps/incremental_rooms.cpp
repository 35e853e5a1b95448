#include "roomscout/maps/incremental_rooms.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/maps/grid_image.hpp"

namespace roomscout {

void IncrementalRoomsOptions::validate() const {
  if (!(margin_m >= 0.0)) throw OptionError("maps.rooms_margin_m must be >= 0");
  if (!(reach_m >= margin_m)) throw OptionError("maps.rooms_reach_m must be >= rooms_margin_m");
  if (!(min_overlap_m2 >= 0.0)) throw OptionError("maps.rooms_min_overlap_m2 must be >= 0");
  if (full_interval < 0) throw OptionError("maps.rooms_full_interval must be >= 0");
  if (!(full_share >= 0.0 && full_share <= 1.0))
    throw OptionError("maps.rooms_full_share must be in [0, 1]");
}

IncrementalRoomSegmenter::IncrementalRoomSegmenter(const RoomSegmenterOptions& segmentation,
                                                   const IncrementalRoomsOptions& options)
    : segmenter_(segmentation), options_(options) {
  options_.validate();
}

const RoomSegmentation& IncrementalRoomSegmenter::segmentAll(const cv::Mat& states,
                                                             double resolution_m) {
  result_ = segmenter_.segment(states, resolution_m);
  states.copyTo(states_);
  renumber();
  ++full_updates_;
  updates_since_full_ = 0;
  return result_;
}

bool IncrementalRoomSegmenter::alignTo(const GridGeometry& geometry) {
  if (result_.labels.empty()) return false;
  if (geometry == geometry_) return true;
  const std::optional<cv::Point> offset = maps::cellOffset(geometry_, geometry);
  if (!offset) return false;
  const cv::Size size(geometry.width(), geometry.height());
  states_ =
      maps::shifted(states_, *offset, size, cv::Scalar(static_cast<int>(CellState::kUnknown)));
  result_.labels = maps::shifted(result_.labels, *offset, size, cv::Scalar(0));
  geometry_ = geometry;
  return true;
}

void IncrementalRoomSegmenter::renumber() {
  std::vector<int> id_of;  // [old label] -> new label
  boxes_.assign(1, cv::Rect());
  int next = 0;
  cv::Mat& labels = result_.labels;
  for (int y = 0; y < labels.rows; ++y) {
    int* row = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x) {
      const int l = row[x];
      if (l <= 0) continue;
      if (static_cast<std::size_t>(l) >= id_of.size()) id_of.resize(l + 1, 0);
      if (!id_of[l]) {
        id_of[l] = ++next;
        boxes_.emplace_back(x, y, 1, 1);
      }
      const int id = id_of[l];
      row[x] = id;
      cv::Rect& b = boxes_[id];
      if (x < b.x) {
        b.width += b.x - x;
        b.x = x;
      }
      b.width = std::max(b.width, x - b.x + 1);
      b.height = y - b.y + 1;
    }
  }
  result_.room_count = next;
}

const RoomSegmentation& IncrementalRoomSegmenter::update(const cv::Mat& states,
                                                         const GridGeometry& geometry) {
  if (states.type() != CV_8U || states.rows != geometry.height() ||
      states.cols != geometry.width()) {
    throw InvalidArgument("IncrementalRoomSegmenter: states must be CV_8U of the geometry's size");
  }
  const double res = geometry.resolution_m();
  const bool aligned = alignTo(geometry);
  geometry_ = geometry;
  if (!aligned) return segmentAll(states, res);

  const cv::Rect diff = maps::changedBounds(states_, states);
  if (diff.empty()) return result_;
  const int margin = static_cast<int>(std::ceil(options_.margin_m / res));
  const cv::Size size = states.size();
  const cv::Rect near = maps::grown(diff, margin, size);

  // The rooms near a change, whole when they lie within reach_m of it, and the window that
  // holds them with a margin.
  cv::Mat& labels = result_.labels;
  std::vector<char> touched(result_.room_count + 1, 0);
  cv::Rect rooms_box = near;
  for (int y = near.y; y < near.y + near.height; ++y) {
    const int* row = labels.ptr<int>(y);
    for (int x = near.x; x < near.x + near.width; ++x) {
      const int l = row[x];
      if (l > 0 && !touched[l]) {
        touched[l] = 1;
        rooms_box |= boxes_[l];
      }
    }
  }
  rooms_box &= maps::grown(diff, static_cast<int>(std::ceil(options_.reach_m / res)), size);
  // The window decides every room that lies in it with a margin, touched or not: a change can
  // merge a room with one beyond the margin (a door's neck compared with both rooms' cores).
  for (int l = 1; l <= result_.room_count; ++l) {
    if ((boxes_[l] & rooms_box) == boxes_[l]) touched[l] = 1;
  }
  const cv::Rect window = maps::grown(rooms_box, margin, size);
  const cv::Rect known = maps::knownBounds(states, 0);
  if (static_cast<double>(window.area()) > options_.full_share * known.area())
    return segmentAll(states, res);

  const RoomSegmentation local = segmenter_.segment(states(window), res);
  // Cells whose label the window decides: near a change, or in a touched room and at least
  // a margin inside the window. A room reaching farther keeps its label beyond.
  auto decides = [&](int x, int y, int old) {
    return near.contains(cv::Point(x, y)) || (touched[old] && rooms_box.contains(cv::Point(x, y)));
  };
  // Each window segment takes the label of the touched room it overlaps most (greedy, largest
  // overlap first); the others get new labels.
  const int old_count = result_.room_count;
  std::vector<int> overlap(static_cast<std::size_t>(local.room_count + 1) * (old_count + 1), 0);
  for (int y = window.y; y < window.y + window.height; ++y) {
    const int* row = labels.ptr<int>(y);
    const int* lrow = local.labels.ptr<int>(y - window.y) - window.x;
    for (int x = window.x; x < window.x + window.width; ++x) {
      const int old = row[x];
      if (lrow[x] > 0 && old > 0 && decides(x, y, old))
        ++overlap[static_cast<std::size_t>(lrow[x]) * (old_count + 1) + old];
    }
  }
  std::vector<std::tuple<int, int, int>> pairs;  // (cells, window segment, old label)
  for (int s = 1; s <= local.room_count; ++s) {
    for (int old = 1; old <= old_count; ++old) {
      const int cells = overlap[static_cast<std::size_t>(s) * (old_count + 1) + old];
      if (cells > 0) pairs.emplace_back(cells, s, old);
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) > std::get<0>(b) : a < b;
  });
  std::vector<int> label_of(local.room_count + 1, 0);
  std::vector<char> taken(old_count + 1, 0);
  for (const auto& [cells, s, old] : pairs) {
    if (label_of[s] || taken[old]) continue;
    label_of[s] = old;
    taken[old] = 1;
  }
  int next = old_count;
  for (int s = 1; s <= local.room_count; ++s) {
    if (!label_of[s]) label_of[s] = ++next;
  }
  // A room the window cuts (it reaches beyond the window's trusted part) cannot change its
  // cells beyond the window. When a window segment joins it to another room, the two merge
  // everywhere. A new room split off it is one when it lies in the trusted part; one that
  // reaches the window's edge may be due to that edge (a corridor cut short ends in a room of
  // its own): the whole map is segmented then, at most every full_interval updates, and in
  // between the piece stays with the room.
  const int min_cells = std::max(1, static_cast<int>(options_.min_overlap_m2 / (res * res)));
  std::vector<char> inside(local.room_count + 1, 1);  // [segment]: all its cells are trusted
  for (int y = window.y; y < window.y + window.height; ++y) {
    const int* lrow = local.labels.ptr<int>(y - window.y) - window.x;
    for (int x = window.x; x < window.x + window.width; ++x) {
      if (lrow[x] > 0 && !rooms_box.contains(cv::Point(x, y))) inside[lrow[x]] = 0;
    }
  }
  std::vector<int> merged_into(old_count + 1, 0);  // [old label]: the segment it joins
  bool unsettled = false;
  for (const auto& [cells, s, old] : pairs) {
    const bool cut = (boxes_[old] & rooms_box) != boxes_[old];
    if (label_of[s] == old || !cut || cells < min_cells) continue;
    if (!taken[old]) {
      merged_into[old] = s;
      taken[old] = 1;
    } else if (label_of[s] > old_count && !inside[s]) {
      // A piece split off the cut room that reaches the window's edge: it stays with the room
      // unless the whole map is segmented.
      unsettled = true;
      label_of[s] = old;
    }
  }
  if (unsettled && updates_since_full_ >= options_.full_interval) return segmentAll(states, res);
  ++window_updates_;
  ++updates_since_full_;
  for (int y = window.y; y < window.y + window.height; ++y) {
    int* row = labels.ptr<int>(y);
    const int* lrow = local.labels.ptr<int>(y - window.y) - window.x;
    for (int x = window.x; x < window.x + window.width; ++x) {
      if (decides(x, y, row[x] > 0 ? row[x] : 0)) row[x] = lrow[x] > 0 ? label_of[lrow[x]] : 0;
    }
  }
  for (int old = 1; old <= old_count; ++old) {
    if (!merged_into[old]) continue;
    int into = label_of[merged_into[old]];
    for (int hops = 0; into <= old_count && merged_into[into] && hops < old_count; ++hops)
      into = label_of[merged_into[into]];
    const cv::Rect& b = boxes_[old];
    for (int y = b.y; y < b.y + b.height; ++y) {
      int* row = labels.ptr<int>(y);
      for (int x = b.x; x < b.x + b.width; ++x) {
        if (row[x] == old) row[x] = into;
      }
    }
  }
  states(window).copyTo(states_(window));
  // Changes outside the window cannot exist: the window holds every changed cell.
  renumber();
  return result_;
}

}  // namespace roomscout
