#pragma once
// The skeleton graph kept up to date while a map grows, at a cost that follows what changed
// instead of the whole map.
//
// The builder keeps the whole map's skeleton and clearance images. An update compares the new
// cell states with those of the last update and rebuilds the images in a window around the
// changed cells only: the window reaches 2 * margin beyond them, and its result is kept on the
// cells within the margin of a change, where neither the window's edge (which the thinning
// takes for a wall) nor anything farther away reaches. Thinning and clearance at a cell depend
// on the free space within about its half-width, so the margin starts at margin_m and grows
// to the largest clearance in the window when the free space there is wider. The graph is then
// traced along the whole skeleton. When the window would
// cover more than `full_share` of the known map, or the grid moved by a fraction of a cell,
// the whole map is rebuilt, as TopologyBuilder::build does.

#include <opencv2/core/mat.hpp>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/maps/topological_map.hpp"
#include "roomscout/maps/topology_builder.hpp"

namespace roomscout {

class SemanticMap;

/// How far updates reach; the "maps" option group holds them (AnalysisMapsOptions).
struct IncrementalTopologyOptions {
  double margin_m = 3.0;    ///< see the class comment [m]
  double full_share = 0.5;  ///< see the class comment; 0: always the whole map
  /// Throws OptionError when a value is out of range.
  void validate() const;
};

class IncrementalTopologyBuilder {
 public:
  explicit IncrementalTopologyBuilder(const TopologyBuilderOptions& topology = {},
                                      const IncrementalTopologyOptions& options = {});

  /// The skeleton graph of `states` (CV_8U CellState values, row y = grid row y, on
  /// `geometry`); `semantic` labels its nodes (may be null). A geometry of another size or
  /// origin (a map that grew) is matched by map position.
  TopologicalMap update(const cv::Mat& states, const GridGeometry& geometry,
                        const SemanticMap* semantic);

  /// Updates so far that rebuilt the whole map (the first one among them).
  int fullUpdates() const { return full_updates_; }
  /// Updates so far that rebuilt a window only.
  int windowUpdates() const { return window_updates_; }

 private:
  bool alignTo(const GridGeometry& geometry);

  TopologyBuilder builder_;
  IncrementalTopologyOptions options_;
  GridGeometry geometry_;
  cv::Mat states_;                      ///< cell states at the last update
  TopologyBuilder::Skeleton skeleton_;  ///< of the whole map at the last update
  int full_updates_ = 0;
  int window_updates_ = 0;
};

}  // namespace roomscout
