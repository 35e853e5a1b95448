#pragma once
// Writes the four maps of an exploration into a folder, in the files `roomscout explore`
// writes: occupancy.pgm/.yaml (map_server), pointcloud.pcd/.png, topology.json/.png and
// semantic.json/.png/_labels.png, each atomically (a failed save leaves the previous files
// whole). Knows no ROS, so that any robot interface can save the same way.

#include <filesystem>
#include <vector>

#include <Eigen/Core>

#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/explorer/analysis_maps.hpp"

namespace roomscout::ros1 {

/// Writes the maps into `directory` (created if needed). `cloud_top_m` clips the point cloud's
/// picture from above (e.g. just under the ceiling). Throws InputError naming the folder or
/// file that could not be written.
void saveMaps(const std::filesystem::path& directory, const OccupancyGrid& grid,
              const AnalysisMap& rooms, const AnalysisMap& skeleton,
              const std::vector<Eigen::Vector3f>& cloud_points, double cloud_top_m);

}  // namespace roomscout::ros1
