#pragma once
// The topological map of the paper: a graph along the skeleton of the free space, with
// junction and end nodes and edges that follow the skeleton. Positions in the map frame [m].

#include <string_view>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/grid_geometry.hpp"

namespace roomscout {

enum class TopoNodeKind { kJunction, kEndpoint, kFrontier };

/// "junction", "endpoint" or "frontier".
std::string_view toString(TopoNodeKind kind);

struct TopoNode {
  int id = 0;
  Vec2 position_m = Vec2::Zero();
  TopoNodeKind kind = TopoNodeKind::kEndpoint;
  int region_id = 0;         ///< room the node stands in (SemanticMap id), 0 = none
  double clearance_m = 0.0;  ///< distance to the nearest obstacle or unknown cell [m]
};

struct TopoEdge {
  int id = 0;
  int u = 0, v = 0;              ///< node ids
  double length_m = 0.0;         ///< along the skeleton [m]
  double min_clearance_m = 0.0;  ///< narrowest place along the edge [m]
  std::vector<Vec2> polyline_m;  ///< simplified skeleton path from u to v [m]
};

/// A skeleton graph on a grid's geometry. Node and edge ids are their indices.
class TopologicalMap {
 public:
  TopologicalMap() = default;
  TopologicalMap(const GridGeometry& geometry, std::vector<TopoNode> nodes,
                 std::vector<TopoEdge> edges)
      : geometry_(geometry), nodes_(std::move(nodes)), edges_(std::move(edges)) {}

  const GridGeometry& geometry() const { return geometry_; }
  const std::vector<TopoNode>& nodes() const { return nodes_; }
  const std::vector<TopoEdge>& edges() const { return edges_; }
  /// Number of edges incident to a node (a self-loop counts twice).
  int degree(int node_id) const;

 private:
  GridGeometry geometry_;
  std::vector<TopoNode> nodes_;
  std::vector<TopoEdge> edges_;
};

}  // namespace roomscout
