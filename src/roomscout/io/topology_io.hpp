#pragma once
// Files of the topological map: topology.json and topology.png (graph over the map).

#include <filesystem>

#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/maps/topological_map.hpp"

namespace roomscout::io {

/// {frame, resolution, origin, nodes: [{id, x, y, kind, region_id, clearance}],
///  edges: [{id, u, v, length, min_clearance, polyline: [[x, y], ...]}]}; metres, map frame.
nlohmann::json topologyJson(const TopologicalMap& map);

/// The graph drawn over the occupancy grid: edges blue, junctions red, ends green, frontier
/// ends orange; row 0 at the top, scaled up so small maps stay legible.
cv::Mat renderTopology(const TopologicalMap& map, const OccupancyGrid& grid);

/// Writes topology.json and topology.png into `directory`, atomically.
void writeTopologicalMap(const std::filesystem::path& directory, const TopologicalMap& map,
                         const OccupancyGrid& grid);

}  // namespace roomscout::io
