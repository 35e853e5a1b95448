#pragma once
// Builds the topological map (paper: "thinning the free space") from an occupancy grid:
// binarise, fill enclosed furniture blobs, morphological opening, Zhang-Suen thinning
// (the skeleton of cv::ximgproc::thinning, computed faster by maps/thinning.hpp), then a graph of
// junction and end nodes joined by edges along the skeleton, with spurs pruned.

#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/maps/topological_map.hpp"

namespace roomscout {

class SemanticMap;

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct TopologyBuilderOptions {
  double opening_radius_m = 0.1;
  double furniture_max_area_m2 = 1.0;
  double furniture_max_extent_m = 2.0;
  double min_free_area_m2 = 0.25;
  double spur_min_length_m = 0.4;
  double spur_disc_factor = 1.5;
  double simplify_tolerance_m = 0.05;

  /// Throws OptionError when a value is out of range.
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Stateless builder; thread-safe (const).
class TopologyBuilder final {
 public:
  explicit TopologyBuilder(const TopologyBuilderOptions& options = {});
  const TopologyBuilderOptions& options() const { return options_; }

  /// @param states CV_8U CellState per cell, row y = grid row y, geometry's size
  /// @param semantic rooms for the nodes' region ids; may be null (ids 0)
  TopologicalMap build(const cv::Mat& states, const GridGeometry& geometry,
                       const SemanticMap* semantic) const;
  TopologicalMap build(const OccupancyGrid& grid, const SemanticMap* semantic = nullptr) const;

  /// build() in two steps, so that a caller can keep the images and redo parts of them
  /// (IncrementalTopologyBuilder). Images of one map, or of a window of one.
  struct Skeleton {
    cv::Mat filled;     ///< CV_8U, the states' size: free space with furniture filled (255)
    cv::Mat skel;       ///< CV_8U, one cell larger on every side: 255 on the skeleton
    cv::Mat clearance;  ///< CV_32F, as skel: distance to the nearest non-space cell [cells]
  };
  /// Step 1: the free space's skeleton and clearance (states: CV_8U CellState values).
  Skeleton skeleton(const cv::Mat& states, double resolution_m) const;
  /// Step 2: the graph along a skeleton of these states, on their geometry.
  TopologicalMap graph(const Skeleton& skeleton, const cv::Mat& states,
                       const GridGeometry& geometry, const SemanticMap* semantic) const;

 private:
  TopologyBuilderOptions options_;
};

}  // namespace roomscout
