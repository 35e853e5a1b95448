#pragma once
// Splits the free space of an occupancy grid into rooms.
//
// The paper builds its semantic map with ROSE² (Luperto et al., RA-L 2022): wall directions,
// wall lines and cells merged into rooms. What we ship is the method that scored best on the
// room segmentation benchmark of Bormann et al. (ICRA 2016), measured with `segment-eval`:
// a persistence-based watershed of the distance transform. Every room has a core far from its
// walls; two cores are kept apart when the neck that joins them (a door) is narrow both in
// absolute terms and relative to the cores' own clearance. Cores grow back into the whole
// free space along decreasing clearance, so borders fall on the narrowest place between two
// rooms: the door. Small pieces merge into their neighbour across their longest border.
// Furniture blobs enclosed by free space are filled first so that they do not cut rooms.
//
// Unknown space counts as a border (neither wall nor room), so the method works on partial
// maps during exploration.

#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct RoomSegmenterOptions {
  double furniture_max_area_m2 = 1.0;
  double furniture_max_extent_m = 2.0;
  double door_cut_min_width_m = 0.5;
  double door_cut_max_width_m = 2.0;
  double wall_extension_max_m = 1.5;
  double jamb_min_length_m = 0.3;
  double wall_max_thickness_m = 0.4;
  double door_max_width_m = 1.6;
  double neck_ratio = 0.75;
  double min_core_clearance_m = 0.45;
  double min_room_area_m2 = 2.0;
  double min_isolated_area_m2 = 0.5;

  /// Throws OptionError when a value is out of range.
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// A segmentation: CV_32S labels of the input's size, 0 = no room, 1..room_count = rooms.
struct RoomSegmentation {
  cv::Mat labels;
  int room_count = 0;
};

/// Stateless room segmentation of one map; thread-safe (const). Its work buffers are kept per
/// thread between calls (about 40 bytes per cell of the largest map segmented), so that the
/// updates of an episode do not allocate them again.
class RoomSegmenter final {
 public:
  explicit RoomSegmenter(const RoomSegmenterOptions& options = {});
  const RoomSegmenterOptions& options() const { return options_; }

  /// @param states CV_8U image of CellState values (any orientation)
  /// @param resolution_m cell side [m]
  /// Only free cells get a room label.
  RoomSegmentation segment(const cv::Mat& states, double resolution_m) const;
  RoomSegmentation segment(const OccupancyGrid& grid) const;

 private:
  RoomSegmenterOptions options_;
};

}  // namespace roomscout
