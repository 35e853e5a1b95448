#pragma once
// rviz markers of the library's maps: rooms in their stable colours with labels, the
// skeleton graph, and points such as frontier candidates or the current goal.

#include <array>
#include <string>
#include <vector>

#include <ros/time.h>
#include <visualization_msgs/Marker.h>
#include <visualization_msgs/MarkerArray.h>

#include "roomscout/core/geometry.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "roomscout/maps/topological_map.hpp"

namespace roomscout::ros1 {

/// Rooms: a DELETEALL first (rooms come and go as the map grows), then per room its cells
/// (namespace "room_cells", a flat CUBE_LIST at most `max_cells` cells in all, thinned evenly),
/// its outline ("room_outline", LINE_STRIP) and its label ("room_label", TEXT, e.g.
/// "room 3"), all in SemanticMap::colourOf(id). Marker ids are room ids.
visualization_msgs::MarkerArray roomMarkers(const SemanticMap& rooms, const std::string& frame,
                                            const ros::Time& stamp, int max_cells = 40000);

/// The skeleton graph: a DELETEALL, then its edges as one LINE_LIST along their polylines
/// ("skeleton_edges") and its nodes as one SPHERE_LIST ("skeleton_nodes": junctions blue,
/// endpoints grey, frontier nodes orange).
visualization_msgs::MarkerArray skeletonMarkers(const TopologicalMap& graph,
                                                const std::string& frame, const ros::Time& stamp);

/// Points as one SPHERE_LIST (or, with none, a DELETE of that marker), in `ns` with id 0.
visualization_msgs::Marker pointsMarker(const std::vector<Vec2>& points_m, const std::string& ns,
                                        const std::array<float, 4>& rgba, double diameter_m,
                                        const std::string& frame, const ros::Time& stamp);

}  // namespace roomscout::ros1
