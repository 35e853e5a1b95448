#pragma once
// The room bookkeeping of SemanticExplorer: which room the robot is in and since when, whether
// that room is a hub (a hallway) and which rooms are its leaves, the room of any point, and
// the room's frontier cells that the tree draws P_sem from. Rooms come from the semantic map
// (ExplorationInput::semantic); without one the robot is in no room and no point is in one.

#include <utility>
#include <vector>

#include "roomscout/core/visit_marks.hpp"
#include "roomscout/exploration/detail/cell_counts.hpp"
#include "roomscout/exploration/detail/slivers.hpp"
#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// The room options (documented in SemanticExplorerOptions::parameters()); each has a value
/// that switches it off.
struct RoomTrackerOptions {
  double label_search_m = 3.5;
  int hub_min_neighbours = 4;
  double hub_sample_radius_m = 4.5;
  bool leaf_rooms = true;

  void validate() const;
};

class RoomTracker {
 public:
  explicit RoomTracker(const RoomTrackerOptions& options) : options_(options) {}

  /// The robot's room, hub and leaves now. In a doorway or an unlabelled patch the robot stays
  /// in the room it was in.
  void update(const ExplorationInput& input);
  /// The room of a point: its label, or for a free cell the segmentation has not labelled yet
  /// the label of the nearest labelled cell within label_search_m through free cells (0: none).
  int roomOf(const ExplorationInput& input, const Vec2& p) const;
  /// Whether a point whose room is `room` counts as in the current room: `room` is the current
  /// room or one of its leaves (leaf_rooms). False outside every room.
  bool inCurrentRoom(int room) const;
  /// Collects sampleCells(): the frontier cells (freeBesideUnknown, not lethal) of the current
  /// room and its leaves, or in a hub those within hub_sample_radius_m of the robot, leaving
  /// out those whose square of half-side `half_side_m` holds less than `min_unknown_m2` of
  /// unknown space.
  void collectSampleCells(const ExplorationInput& input, double half_side_m, double min_unknown_m2);

  int room() const { return room_; }
  bool inHub() const { return hub_; }
  double timeInRoom_s() const { return time_in_room_s_; }
  const std::vector<Vec2>& sampleCells() const { return sample_cells_; }

 private:
  RoomTrackerOptions options_;
  int room_ = 0;
  bool hub_ = false;
  std::vector<int> leaves_;  ///< the current room's leaves (see leaf_rooms), as of update()
  double room_since_s_ = 0.0;
  double time_in_room_s_ = 0.0;
  std::vector<Vec2> sample_cells_;
  CellCounts counts_;  ///< scratch of collectSampleCells()
  // roomOf()'s search for a label: the cells it reached, and its queue of cells with their
  // distance in steps.
  mutable VisitMarks label_seen_;
  mutable std::vector<std::pair<Cell, int>> label_queue_;
};

}  // namespace roomscout
