#include "roomscout_ros/map_saver.hpp"

#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/io/pcd_io.hpp"
#include "roomscout/io/point_cloud_render.hpp"
#include "roomscout/io/semantic_io.hpp"
#include "roomscout/io/topology_io.hpp"

namespace roomscout::ros1 {

void saveMaps(const std::filesystem::path& directory, const OccupancyGrid& grid,
              const AnalysisMap& rooms, const AnalysisMap& skeleton,
              const std::vector<Eigen::Vector3f>& cloud_points, double cloud_top_m) {
  io::ensureWritableDirectory(directory);
  io::saveOccupancyMap(grid, directory / "occupancy.yaml");
  io::writePcdAtomic(directory / "pointcloud.pcd", cloud_points, io::PcdFormat::kBinaryCompressed,
                     "roomscout point cloud map, map frame of occupancy.yaml", 0.005);
  io::writeImageAtomic(directory / "pointcloud.png",
                       io::renderPointCloud(cloud_points, cloud_top_m));
  io::writeTopologicalMap(directory, skeleton.topologicalMap(), grid);
  io::writeSemanticMap(directory, *rooms.semanticMap(), grid);
}

}  // namespace roomscout::ros1
