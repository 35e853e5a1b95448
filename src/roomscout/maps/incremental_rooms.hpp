#pragma once
// Rooms kept up to date while a map grows, at a cost that follows what changed instead of the
// whole map (a robot's map changes only where its sensor looks).
//
// An update compares the new cell states with those of the last update. The rooms within
// `margin_m` of a changed cell are touched. A window holding the changed cells and the touched
// rooms, whole as far as they lie within `reach_m` of a changed cell, widened by margin_m, is
// segmented on its own: the RoomSegmenter treats the window's edge as unknown space, as it
// treats the edge of any partial map. Its labels replace the old ones on the changed cells and
// on the touched rooms within reach only; every other room keeps its cells, and a room that
// reaches farther (a long corridor) keeps its label beyond. A window segment takes the label of
// the touched room it overlaps most, so rooms keep their labels (and a SemanticMap fed with
// them keeps its ids) while the map grows. Every room that lies in the window with a margin is
// decided by it too.
//
// A room the window cuts keeps its cells beyond the window: a window segment that joins it to
// another room (`min_overlap_m2` of each) merges the two everywhere, and a new segment split
// off it that reaches the window's edge leaves the map unsettled (that edge may be the cause: a
// corridor cut short ends in a room of its own). The whole map is segmented then, though not
// within `full_interval` updates of the last time; until then the piece stays with the room.
// When the window would cover more than `full_share` of the known map, or the grid moved by a
// fraction of a cell, the whole map is segmented, as RoomSegmenter::segment does.

#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/maps/room_segmenter.hpp"

namespace roomscout {

/// How far updates reach; the "maps" option group holds them (AnalysisMapsOptions).
struct IncrementalRoomsOptions {
  double margin_m = 2.5;        ///< see the class comment [m]
  double reach_m = 12.0;        ///< see the class comment [m]
  double full_share = 0.5;      ///< see the class comment; 0: always the whole map
  double min_overlap_m2 = 0.5;  ///< see the class comment [m^2]
  int full_interval = 20;       ///< see the class comment [updates]
  /// Throws OptionError when a value is out of range.
  void validate() const;
};

class IncrementalRoomSegmenter {
 public:
  explicit IncrementalRoomSegmenter(const RoomSegmenterOptions& segmentation = {},
                                    const IncrementalRoomsOptions& options = {});

  /// The rooms of `states` (CV_8U CellState values, row y = grid row y, on `geometry`),
  /// numbered 1..room_count. Valid until the next update. A geometry of another size or
  /// origin (a map that grew) is matched by map position.
  const RoomSegmentation& update(const cv::Mat& states, const GridGeometry& geometry);

  /// Updates so far that segmented the whole map (the first one among them).
  int fullUpdates() const { return full_updates_; }
  /// Updates so far that segmented a window only.
  int windowUpdates() const { return window_updates_; }

 private:
  /// Segments the whole map, as the last update's.
  const RoomSegmentation& segmentAll(const cv::Mat& states, double resolution_m);
  /// Puts the last update's states and labels into `geometry`'s frame; false when it cannot
  /// (no last update, another resolution, a shift by a fraction of a cell).
  bool alignTo(const GridGeometry& geometry);
  /// Numbers the labels 1..n in row-major order of first appearance and records each room's
  /// bounding box.
  void renumber();

  RoomSegmenter segmenter_;
  IncrementalRoomsOptions options_;
  GridGeometry geometry_;
  cv::Mat states_;               ///< cell states at the last update
  RoomSegmentation result_;      ///< labels at the last update
  std::vector<cv::Rect> boxes_;  ///< [label]: bounding box of the room's cells
  int full_updates_ = 0;
  int window_updates_ = 0;
  int updates_since_full_ = 0;
};

}  // namespace roomscout
