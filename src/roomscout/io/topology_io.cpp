#include "roomscout/io/topology_io.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/semantic_io.hpp"

namespace roomscout::io {

nlohmann::json topologyJson(const TopologicalMap& map) {
  const GridGeometry& g = map.geometry();
  nlohmann::json nodes = nlohmann::json::array(), edges = nlohmann::json::array();
  for (const TopoNode& n : map.nodes()) {
    nodes.push_back({{"id", n.id},
                     {"x", n.position_m.x()},
                     {"y", n.position_m.y()},
                     {"kind", std::string(toString(n.kind))},
                     {"region_id", n.region_id},
                     {"clearance", n.clearance_m}});
  }
  for (const TopoEdge& e : map.edges()) {
    nlohmann::json polyline = nlohmann::json::array();
    for (const Vec2& p : e.polyline_m) polyline.push_back({p.x(), p.y()});
    edges.push_back({{"id", e.id},
                     {"u", e.u},
                     {"v", e.v},
                     {"length", e.length_m},
                     {"min_clearance", e.min_clearance_m},
                     {"polyline", polyline}});
  }
  return {{"frame", "map"},
          {"resolution", g.resolution_m()},
          {"origin", {g.origin_m().x(), g.origin_m().y(), 0.0}},
          {"units", "m"},
          {"nodes", nodes},
          {"edges", edges}};
}

cv::Mat renderTopology(const TopologicalMap& map, const OccupancyGrid& grid) {
  const GridGeometry& g = grid.geometry();
  const int scale = std::max(1, std::min(4, 1200 / std::max(1, std::max(g.width(), g.height()))));
  cv::Mat image;
  cv::cvtColor(occupancyImage(grid), image, cv::COLOR_GRAY2BGR);
  cv::resize(image, image, {}, scale, scale, cv::INTER_NEAREST);
  auto toPixel = [&](const Vec2& p) {
    return cv::Point(
        static_cast<int>((p.x() - g.origin_m().x()) / g.resolution_m() * scale),
        static_cast<int>((g.height() - (p.y() - g.origin_m().y()) / g.resolution_m()) * scale));
  };
  for (const TopoEdge& e : map.edges()) {
    std::vector<cv::Point> line;
    for (const Vec2& p : e.polyline_m) line.push_back(toPixel(p));
    cv::polylines(image, line, false, cv::Scalar(200, 90, 20), std::max(1, scale / 2), cv::LINE_AA);
  }
  for (const TopoNode& n : map.nodes()) {
    const cv::Scalar colour = n.kind == TopoNodeKind::kJunction   ? cv::Scalar(40, 40, 220)
                              : n.kind == TopoNodeKind::kFrontier ? cv::Scalar(0, 150, 255)
                                                                  : cv::Scalar(40, 170, 40);
    cv::circle(image, toPixel(n.position_m), 2 + scale, colour, cv::FILLED, cv::LINE_AA);
  }
  return image;
}

void writeTopologicalMap(const std::filesystem::path& directory, const TopologicalMap& map,
                         const OccupancyGrid& grid) {
  writeImageAtomic(directory / "topology.png", renderTopology(map, grid));
  writeFileAtomic(directory / "topology.json", topologyJson(map).dump(2) + "\n");
}

}  // namespace roomscout::io
