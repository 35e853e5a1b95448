#pragma once
// The semantic map of the paper (rooms): a label grid on the occupancy grid's geometry and
// one record per room. Exploration strategies ask it which room the robot is in.
//
// Room ids are stable across updates: each new segment takes the id of the old room it
// overlaps most (greedy over overlaps, largest first), so a room keeps its id and colour
// while the map grows around it.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/grid_geometry.hpp"

namespace roomscout {

/// One room of a SemanticMap.
struct SemanticRegion {
  int id = 0;                         ///< >= 1, stable across updates
  std::array<std::uint8_t, 3> rgb{};  ///< display colour, a function of the id
  std::string label;                  ///< "room" or "corridor" (by shape)
  int cell_count = 0;
  double area_m2 = 0.0;
  Vec2 centroid_m = Vec2::Zero();
  Polygon polygon_m;            ///< outer boundary of its largest part [m]
  bool open = false;            ///< touches unknown space: not fully seen yet
  std::vector<int> neighbours;  ///< ids of rooms it shares a border (a door) with
};

/// Rooms on a grid. Not thread-safe for concurrent update() and reads. A copy is cheap (it
/// shares the label image) and stays as it was: update() gives the map a new label image.
class SemanticMap {
 public:
  SemanticMap() = default;

  /// Replaces the rooms with a new segmentation of the same geometry's grid.
  /// @param segment_labels CV_32S, geometry's height x width, row y = grid row y; 0 = no room
  /// @param states CV_8U CellState per cell, same layout (for the open flag); may be empty
  /// A geometry that differs from the last one (grown grid) is matched by map position.
  void update(const GridGeometry& geometry, const cv::Mat& segment_labels, const cv::Mat& states);

  const GridGeometry& geometry() const { return geometry_; }
  /// Room id of every cell (CV_32S, row y = grid row y), 0 = no room.
  const cv::Mat& labels() const { return labels_; }
  const std::vector<SemanticRegion>& regions() const { return regions_; }
  /// The region with this id, or nullptr.
  const SemanticRegion* region(int id) const;

  /// Room id at a point of the map frame, 0 outside every room. O(1).
  int roomAt(const Vec2& p_m) const {
    const Cell c = geometry_.cellOf(p_m);
    return geometry_.contains(c) ? labels_.ptr<int>(c.y)[c.x] : 0;
  }
  int roomAt(Cell c) const { return geometry_.contains(c) ? labels_.ptr<int>(c.y)[c.x] : 0; }

  /// Number of updates so far.
  int updateCount() const { return update_count_; }

  /// A room is open when its cells next to unknown space form a frontier this long [m].
  static constexpr double kMinFrontier_m = 0.4;

  /// The display colour of a room id (distinct hues, deterministic).
  static std::array<std::uint8_t, 3> colourOf(int id);

 private:
  GridGeometry geometry_;
  cv::Mat labels_ = cv::Mat(0, 0, CV_32S);
  std::vector<SemanticRegion> regions_;
  int next_id_ = 1;
  int update_count_ = 0;
};

}  // namespace roomscout
