#include "roomscout/slam/map_consistency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout::slam {

MapConsistency mapConsistency(const OccupancyGrid& map, const std::vector<LaserScan>& scans,
                              const std::vector<Pose2>& T_map_sensor, double max_range_m) {
  if (scans.size() != T_map_sensor.size()) {
    throw InvalidArgument("mapConsistency: " + std::to_string(scans.size()) + " scans but " +
                          std::to_string(T_map_sensor.size()) + " poses");
  }
  if (!(max_range_m > 0.0)) throw InvalidArgument("mapConsistency: max_range_m must be > 0");
  MapConsistency result;
  const GridGeometry& g = map.geometry();
  if (g.cellCount() == 0) return result;

  // Distance of every cell to the nearest occupied one [cells]: zero pixels are the occupied.
  cv::Mat not_occupied(g.height(), g.width(), CV_8U);
  bool any_occupied = false;
  for (int y = 0; y < g.height(); ++y) {
    auto* row = not_occupied.ptr<std::uint8_t>(y);
    for (int x = 0; x < g.width(); ++x) {
      const bool occupied = map.isOccupied(g.index(Cell{x, y}));
      row[x] = occupied ? 0 : 255;
      any_occupied = any_occupied || occupied;
    }
  }
  if (!any_occupied) return result;
  cv::Mat distance_cells;
  cv::distanceTransform(not_occupied, distance_cells, cv::DIST_L2, cv::DIST_MASK_PRECISE);

  double sum_cells = 0.0;
  for (std::size_t s = 0; s < scans.size(); ++s) {
    const LaserScan& scan = scans[s];
    const Pose2& pose = T_map_sensor[s];
    const double far_m = std::min(scan.range_max_m, max_range_m);
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
      const double r = scan.ranges_m[i];
      if (!std::isfinite(r) || r < scan.range_min_m || r > far_m) continue;
      const double angle =
          pose.yaw_rad + scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
      const Cell c = g.cellOf(pose.position() + r * Vec2(std::cos(angle), std::sin(angle)));
      if (!g.contains(c)) {
        ++result.outside_points;
        continue;
      }
      sum_cells += distance_cells.at<float>(c.y, c.x);
      ++result.points;
    }
  }
  if (result.points > 0) {
    result.mean_distance_m = sum_cells / static_cast<double>(result.points) * g.resolution_m();
  }
  return result;
}

}  // namespace roomscout::slam
