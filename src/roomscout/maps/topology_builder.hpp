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

struct TopologyBuilderOptions {
  double opening_radius_m = 0.1;        ///< opening of the free space; keep below half the
                                        ///< narrowest door, or doors get cut [m]
  double furniture_max_area_m2 = 1.0;   ///< enclosed obstacle blobs up to this area are filled,
                                        ///< so furniture makes no loops [m^2]
  double furniture_max_extent_m = 2.0;  ///< ... and up to this bounding-box side [m]
  double min_free_area_m2 = 0.25;       ///< smaller free patches get no skeleton [m^2]
  double spur_min_length_m = 0.4;       ///< dead-end edges shorter than this are pruned [m]
  double spur_disc_factor = 1.5;        ///< dead ends within this many times the junction's
                                        ///< clearance of it are pruned too (room corners)
  double simplify_tolerance_m = 0.05;   ///< polyline simplification (Douglas-Peucker) [m]

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

 private:
  TopologyBuilderOptions options_;
};

}  // namespace roomscout
