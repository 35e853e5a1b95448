#include "roomscout/maps/incremental_topology.hpp"

#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/maps/grid_image.hpp"

namespace roomscout {

void IncrementalTopologyOptions::validate() const {
  if (!(margin_m >= 0.0)) throw OptionError("maps.skeleton_margin_m must be >= 0");
  if (!(full_share >= 0.0 && full_share <= 1.0))
    throw OptionError("maps.skeleton_full_share must be in [0, 1]");
}

IncrementalTopologyBuilder::IncrementalTopologyBuilder(const TopologyBuilderOptions& topology,
                                                       const IncrementalTopologyOptions& options)
    : builder_(topology), options_(options) {
  options_.validate();
}

bool IncrementalTopologyBuilder::alignTo(const GridGeometry& geometry) {
  if (states_.empty()) return false;
  if (geometry == geometry_) return true;
  const std::optional<cv::Point> offset = maps::cellOffset(geometry_, geometry);
  if (!offset) return false;
  const cv::Size size(geometry.width(), geometry.height());
  const cv::Size framed(size.width + 2, size.height + 2);
  states_ =
      maps::shifted(states_, *offset, size, cv::Scalar(static_cast<int>(CellState::kUnknown)));
  skeleton_.filled = maps::shifted(skeleton_.filled, *offset, size, cv::Scalar(0));
  skeleton_.skel = maps::shifted(skeleton_.skel, *offset, framed, cv::Scalar(0));
  skeleton_.clearance = maps::shifted(skeleton_.clearance, *offset, framed, cv::Scalar(0));
  geometry_ = geometry;
  return true;
}

TopologicalMap IncrementalTopologyBuilder::update(const cv::Mat& states,
                                                  const GridGeometry& geometry,
                                                  const SemanticMap* semantic) {
  if (states.type() != CV_8U || states.rows != geometry.height() ||
      states.cols != geometry.width()) {
    throw InvalidArgument(
        "IncrementalTopologyBuilder: states must be CV_8U of the geometry's size");
  }
  const double res = geometry.resolution_m();
  const bool aligned = alignTo(geometry);
  geometry_ = geometry;
  // The known part of the map: the share a window may take of it, and where the graph is traced.
  const cv::Rect known_cells = maps::knownBounds(states, 0);
  bool all = !aligned;
  if (aligned) {
    const cv::Rect diff = maps::changedBounds(states_, states);
    // Free space wider than twice the margin takes a wider one: the window grows until its
    // widest free space fits (its clearance, seen from inside the window, is below the margin).
    for (int margin = static_cast<int>(std::ceil(options_.margin_m / res)); !diff.empty();) {
      const cv::Rect keep = maps::grown(diff, margin, states.size());
      const cv::Rect window = maps::grown(diff, 2 * margin, states.size());
      if (static_cast<double>(window.area()) > options_.full_share * known_cells.area()) {
        all = true;
        break;
      }
      TopologyBuilder::Skeleton local = builder_.skeleton(states(window), res);
      double widest = 0.0;
      cv::minMaxLoc(local.clearance, nullptr, &widest);
      if (widest > margin) {
        margin = static_cast<int>(std::ceil(widest)) + 1;
        continue;
      }
      const cv::Rect in_window = keep - window.tl();
      const cv::Point frame(1, 1);
      local.filled(in_window).copyTo(skeleton_.filled(keep));
      local.skel(in_window + frame).copyTo(skeleton_.skel(keep + frame));
      local.clearance(in_window + frame).copyTo(skeleton_.clearance(keep + frame));
      states(diff).copyTo(states_(diff));
      ++window_updates_;
      break;
    }
  }
  if (all) {
    skeleton_ = builder_.skeleton(states, res);
    states.copyTo(states_);
    ++full_updates_;
  }

  // The graph, traced on the known part of the map (with TopologyBuilder::build's margin).
  if (known_cells.empty()) return TopologicalMap(geometry, {}, {});
  const cv::Rect known = maps::grown(known_cells, 2, states.size());
  const TopologyBuilder::Skeleton view{
      skeleton_.filled(known),
      skeleton_.skel(cv::Rect(known.x, known.y, known.width + 2, known.height + 2)),
      skeleton_.clearance(cv::Rect(known.x, known.y, known.width + 2, known.height + 2))};
  const TopologicalMap crop =
      builder_.graph(view, states(known),
                     GridGeometry(geometry.origin_m() + Vec2(known.x, known.y) * res, res,
                                  known.width, known.height),
                     semantic);
  return TopologicalMap(geometry, crop.nodes(), crop.edges());
}

}  // namespace roomscout
