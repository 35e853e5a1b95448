#include "roomscout/maps/topological_map.hpp"

namespace roomscout {

std::string_view toString(TopoNodeKind kind) {
  switch (kind) {
    case TopoNodeKind::kJunction:
      return "junction";
    case TopoNodeKind::kEndpoint:
      return "endpoint";
    case TopoNodeKind::kFrontier:
      return "frontier";
  }
  return "endpoint";
}

int TopologicalMap::degree(int node_id) const {
  int d = 0;
  for (const TopoEdge& e : edges_) d += (e.u == node_id) + (e.v == node_id);
  return d;
}

}  // namespace roomscout
