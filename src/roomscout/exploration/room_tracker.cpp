#include "roomscout/exploration/detail/room_tracker.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/semantic_map.hpp"

namespace roomscout {

void RoomTrackerOptions::validate() const {
  auto finiteAtLeast = [](double v, double lo) { return std::isfinite(v) && v >= lo; };
  if (!finiteAtLeast(label_search_m, 0.0))
    throw OptionError("semantic.label_search_m must be >= 0");
  if (hub_min_neighbours < 0) throw OptionError("semantic.hub_min_neighbours must be >= 0");
  if (!finiteAtLeast(hub_sample_radius_m, 0.0))
    throw OptionError("semantic.hub_sample_radius_m must be >= 0");
}

int RoomTracker::roomOf(const ExplorationInput& input, const Vec2& p) const {
  if (input.semantic == nullptr) return 0;
  const SemanticMap& map = *input.semantic;
  const int id = map.roomAt(p);
  if (id != 0) return id;
  // A cell seen since the segmentation's last update has no label yet: it belongs to the room
  // of the nearest labelled cell reached through known-free cells within label_search_m (a
  // breadth-first search, nearest first; unknown space is in no room). Through free cells, not
  // the straight line: the fresh end of a corridor belongs to the corridor's room, not to the
  // room behind its wall.
  const GridGeometry& g = input.grid.geometry();
  const Cell c = g.cellOf(p);
  if (!g.contains(c) || !input.grid.isFree(g.index(c))) return 0;
  const int r = static_cast<int>(std::ceil(options_.label_search_m / g.resolution_m()));
  label_seen_.begin(g.cellCount());
  label_queue_.clear();
  label_queue_.push_back({c, 0});
  label_seen_.mark(g.index(c));
  for (std::size_t head = 0; head < label_queue_.size(); ++head) {
    const auto [q, steps] = label_queue_[head];
    if (head > 0) {
      if (const int label = map.roomAt(g.centerOf(q)); label != 0) return label;
    }
    if (steps >= r) continue;
    for (const Cell n :
         {Cell{q.x + 1, q.y}, Cell{q.x - 1, q.y}, Cell{q.x, q.y + 1}, Cell{q.x, q.y - 1}}) {
      if (!g.contains(n)) continue;
      const std::size_t i = g.index(n);
      if (label_seen_.marked(i) || !input.grid.isFree(i)) continue;
      label_seen_.mark(i);
      label_queue_.push_back({n, steps + 1});
    }
  }
  return 0;
}

void RoomTracker::update(const ExplorationInput& input) {
  const int room = roomOf(input, input.robot.position());
  if (room != 0 && room != room_) {
    room_ = room;
    room_since_s_ = input.time_s;
  }
  time_in_room_s_ = room_ != 0 ? input.time_s - room_since_s_ : 0.0;
  const SemanticRegion* region =
      room_ != 0 && input.semantic != nullptr ? input.semantic->region(room_) : nullptr;
  hub_ = region != nullptr && options_.hub_min_neighbours > 0 &&
         static_cast<int>(region->neighbours.size()) >= options_.hub_min_neighbours;
  // Leaves: rooms that open onto the current room alone, while the current room has another way
  // out (in a world of two rooms neither is a leaf of the other).
  leaves_.clear();
  if (options_.leaf_rooms && region != nullptr && region->neighbours.size() >= 2) {
    for (const int n : region->neighbours) {
      const SemanticRegion* other = input.semantic->region(n);
      if (other != nullptr && other->neighbours.size() == 1 && other->neighbours.front() == room_) {
        leaves_.push_back(n);
      }
    }
  }
}

bool RoomTracker::inCurrentRoom(int room) const {
  return room != 0 &&
         (room == room_ || std::find(leaves_.begin(), leaves_.end(), room) != leaves_.end());
}

void RoomTracker::collectSampleCells(const ExplorationInput& input, double half_side_m,
                                     double min_unknown_m2) {
  sample_cells_.clear();
  const GridGeometry& g = input.grid.geometry();
  if (room_ == 0 || input.semantic == nullptr) return;
  // In a hub, P_sem is any frontier cell near the robot, whatever its room.
  const bool local = hub_;
  if (local && options_.hub_sample_radius_m <= 0.0) return;
  Vec2 lo, hi;
  if (local) {
    const Vec2 r(options_.hub_sample_radius_m, options_.hub_sample_radius_m);
    lo = input.robot.position() - r;
    hi = input.robot.position() + r;
  } else {
    const SemanticRegion* region = input.semantic->region(room_);
    if (region == nullptr || region->polygon_m.empty()) return;
    lo = region->polygon_m.front();
    hi = lo;
    for (const Vec2& v : region->polygon_m) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    // The room's leaves (see leaf_rooms) are part of it.
    for (const int n : leaves_) {
      for (const Vec2& v : input.semantic->region(n)->polygon_m) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
    }
  }
  // Cells labelled by the search for a label lie up to label_search_m outside the room's box.
  const double pad = (local ? 0.0 : options_.label_search_m) + g.resolution_m();
  const Cell a = g.cellOf(lo - Vec2(pad, pad));
  const Cell b = g.cellOf(hi + Vec2(pad, pad));
  const int w = g.width();
  const int x0 = std::max(1, a.x), x1 = std::min(w - 2, b.x);
  const int y0 = std::max(1, a.y), y1 = std::min(g.height() - 2, b.y);
  if (x0 > x1 || y0 > y1) return;
  // Unknown cells counted over the box grown by the square, so that a frontier cell whose
  // square holds less than min_unknown_m2 of unknown space (a sliver) is no sample.
  const int r = static_cast<int>(std::lround(half_side_m / g.resolution_m()));
  counts_.build(std::max(0, x0 - r), std::max(0, y0 - r), std::min(w - 1, x1 + r),
                std::min(g.height() - 1, y1 + r), [&](int x, int y) {
                  return input.grid.isUnknown(static_cast<std::size_t>(y) * w + x);
                });
  const double cell_m2 = g.resolution_m() * g.resolution_m();
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!freeBesideUnknown(input.grid, x, y) || input.costmap.isLethal(i)) continue;
      if (counts_.square(x, y, r) * cell_m2 < min_unknown_m2) continue;
      const Vec2 p = g.centerOf(Cell{x, y});
      if (local || inCurrentRoom(roomOf(input, p))) sample_cells_.push_back(p);
    }
  }
}

}  // namespace roomscout
