#include "roomscout/maps/incremental_topology.hpp"

#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/maps/grid_image.hpp"

namespace roomscout {
namespace {

cv::Rect inflated(const cv::Rect& r, int by, const cv::Size& size) {
  return cv::Rect(r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by) &
         cv::Rect(0, 0, size.width, size.height);
}

}  // namespace

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
  bool all = !aligned;
  if (aligned) {
    cv::Mat changed;
    cv::compare(states, states_, changed, cv::CMP_NE);
    const cv::Rect diff = cv::boundingRect(changed);
    // Free space wider than twice the margin takes a wider one: the window grows until its
    // widest free space fits (its clearance, seen from inside the window, is below the margin).
    for (int margin = static_cast<int>(std::ceil(options_.margin_m / res)); !diff.empty();) {
      const cv::Rect keep = inflated(diff, margin, states.size());
      const cv::Rect window = inflated(diff, 2 * margin, states.size());
      if (static_cast<double>(window.area()) >
          options_.full_share * maps::knownBounds(states, 0).area()) {
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

  // The graph, traced on the known part of the map.
  const cv::Rect known = maps::knownBounds(states, 2);
  if (known.empty()) return TopologicalMap(geometry, {}, {});
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
