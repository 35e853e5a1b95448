#include "roomscout_ros/map_markers.hpp"

#include <algorithm>
#include <cmath>

#include <geometry_msgs/Point.h>
#include <std_msgs/ColorRGBA.h>

namespace roomscout::ros1 {
namespace {

visualization_msgs::Marker makeMarker(const std::string& frame, const ros::Time& stamp,
                                      const std::string& ns, int id, int type) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  return m;
}

visualization_msgs::Marker deleteAll(const std::string& frame, const ros::Time& stamp) {
  visualization_msgs::Marker m = makeMarker(frame, stamp, "", 0, visualization_msgs::Marker::CUBE);
  m.action = visualization_msgs::Marker::DELETEALL;
  return m;
}

std_msgs::ColorRGBA colour(const std::array<std::uint8_t, 3>& rgb, float alpha) {
  std_msgs::ColorRGBA c;
  c.r = rgb[0] / 255.0f;
  c.g = rgb[1] / 255.0f;
  c.b = rgb[2] / 255.0f;
  c.a = alpha;
  return c;
}

geometry_msgs::Point point(const Vec2& p, double z = 0.0) {
  geometry_msgs::Point q;
  q.x = p.x();
  q.y = p.y();
  q.z = z;
  return q;
}

}  // namespace

visualization_msgs::MarkerArray roomMarkers(const SemanticMap& rooms, const std::string& frame,
                                            const ros::Time& stamp, int max_cells) {
  visualization_msgs::MarkerArray out;
  out.markers.push_back(deleteAll(frame, stamp));
  const GridGeometry& g = rooms.geometry();
  const cv::Mat& labels = rooms.labels();
  long labelled = 0;
  for (const SemanticRegion& r : rooms.regions()) labelled += r.cell_count;
  // Every k-th cell on both axes keeps the markers within max_cells.
  const int k = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(labelled) /
                                                                 std::max(1, max_cells)))));
  for (const SemanticRegion& r : rooms.regions()) {
    visualization_msgs::Marker cells =
        makeMarker(frame, stamp, "room_cells", r.id, visualization_msgs::Marker::CUBE_LIST);
    cells.scale.x = cells.scale.y = g.resolution_m() * k;
    cells.scale.z = 0.01;
    cells.color = colour(r.rgb, 0.45f);
    for (int y = 0; y < labels.rows; y += k) {
      const int* row = labels.ptr<int>(y);
      for (int x = 0; x < labels.cols; x += k) {
        if (row[x] == r.id) cells.points.push_back(point(g.centerOf(Cell{x, y})));
      }
    }
    if (!cells.points.empty()) out.markers.push_back(std::move(cells));

    if (r.polygon_m.size() >= 3) {
      visualization_msgs::Marker outline =
          makeMarker(frame, stamp, "room_outline", r.id, visualization_msgs::Marker::LINE_STRIP);
      outline.scale.x = 0.04;
      outline.color = colour(r.rgb, 1.0f);
      for (const Vec2& p : r.polygon_m) outline.points.push_back(point(p, 0.02));
      outline.points.push_back(point(r.polygon_m.front(), 0.02));
      out.markers.push_back(std::move(outline));
    }

    visualization_msgs::Marker label =
        makeMarker(frame, stamp, "room_label", r.id, visualization_msgs::Marker::TEXT_VIEW_FACING);
    label.pose.position = point(r.centroid_m, 0.5);
    label.scale.z = 0.4;
    label.color = colour(r.rgb, 1.0f);
    label.text = r.label + " " + std::to_string(r.id);
    out.markers.push_back(std::move(label));
  }
  return out;
}

visualization_msgs::MarkerArray skeletonMarkers(const TopologicalMap& graph,
                                                const std::string& frame, const ros::Time& stamp) {
  visualization_msgs::MarkerArray out;
  out.markers.push_back(deleteAll(frame, stamp));
  visualization_msgs::Marker edges =
      makeMarker(frame, stamp, "skeleton_edges", 0, visualization_msgs::Marker::LINE_LIST);
  edges.scale.x = 0.03;
  edges.color = colour({40, 40, 40}, 0.9f);
  for (const TopoEdge& e : graph.edges()) {
    for (std::size_t i = 1; i < e.polyline_m.size(); ++i) {
      edges.points.push_back(point(e.polyline_m[i - 1], 0.05));
      edges.points.push_back(point(e.polyline_m[i], 0.05));
    }
  }
  if (!edges.points.empty()) out.markers.push_back(std::move(edges));
  visualization_msgs::Marker nodes =
      makeMarker(frame, stamp, "skeleton_nodes", 0, visualization_msgs::Marker::SPHERE_LIST);
  nodes.scale.x = nodes.scale.y = nodes.scale.z = 0.15;
  for (const TopoNode& n : graph.nodes()) {
    nodes.points.push_back(point(n.position_m, 0.05));
    switch (n.kind) {
      case TopoNodeKind::kJunction:
        nodes.colors.push_back(colour({30, 90, 220}, 1.0f));
        break;
      case TopoNodeKind::kEndpoint:
        nodes.colors.push_back(colour({120, 120, 120}, 1.0f));
        break;
      case TopoNodeKind::kFrontier:
        nodes.colors.push_back(colour({240, 140, 20}, 1.0f));
        break;
    }
  }
  if (!nodes.points.empty()) out.markers.push_back(std::move(nodes));
  return out;
}

visualization_msgs::Marker pointsMarker(const std::vector<Vec2>& points_m, const std::string& ns,
                                        const std::array<float, 4>& rgba, double diameter_m,
                                        const std::string& frame, const ros::Time& stamp) {
  visualization_msgs::Marker m =
      makeMarker(frame, stamp, ns, 0, visualization_msgs::Marker::SPHERE_LIST);
  if (points_m.empty()) {
    m.action = visualization_msgs::Marker::DELETE;
    return m;
  }
  m.scale.x = m.scale.y = m.scale.z = diameter_m;
  m.color.r = rgba[0];
  m.color.g = rgba[1];
  m.color.b = rgba[2];
  m.color.a = rgba[3];
  for (const Vec2& p : points_m) m.points.push_back(point(p, 0.1));
  return m;
}

}  // namespace roomscout::ros1
