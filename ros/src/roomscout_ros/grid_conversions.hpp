#pragma once
// Conversions between ROS 1 messages and the library's types: nav_msgs/OccupancyGrid and
// OccupancyGrid, geometry_msgs poses and Pose2. The nodes stay thin adapters over these.

#include <optional>
#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
#include <map_msgs/OccupancyGridUpdate.h>
#include <nav_msgs/OccupancyGrid.h>
#include <opencv2/core/mat.hpp>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::ros1 {

/// A map message read as a grid, with the cells that differ from the previous one.
struct ReceivedGrid {
  OccupancyGrid grid;
  /// Cells whose state differs from `previous` (empty rectangle: none), or nullopt when the
  /// geometry changed and any cell may differ.
  std::optional<CellRect> changed;
};

/// How a map's cell values (0-100, -1 unknown) read as free and occupied: a value at or below
/// `free_max` is free, at or above `occupied_min` occupied, anything between unknown.
struct MapConvention {
  double free_max = 19.6;      ///< map_server's free_thresh 0.196
  double occupied_min = 65.0;  ///< map_server's occupied_thresh 0.65

  /// The convention of the package that publishes the map, by name (names()); throws
  /// OptionError listing the known names for another. Sources in docs/ros.md.
  static MapConvention named(const std::string& source);
  static std::vector<std::string> names();
  /// Throws OptionError unless 0 <= free_max < occupied_min <= 100.
  void validate() const;
};

/// Reads a map message by `convention`. The float resolution is read as the decimal it was
/// written from (0.05f as 0.05). `previous` (may be null) is the grid of the last message, for
/// the changed cells. Throws InvalidArgument naming the problem for a map the library cannot
/// use: a rotated origin, an origin or a resolution that is not finite, a resolution <= 0, a
/// data size that is not width x height.
ReceivedGrid fromMsg(const nav_msgs::OccupancyGrid& msg, const OccupancyGrid* previous = nullptr,
                     const MapConvention& convention = {});

/// Writes `update` (a patch of cells, as costmap_2d and Cartographer's map publishers send on
/// `map_updates`) into `map`. Throws InvalidArgument naming the problem, leaving `map` as it
/// was, for a patch outside the map or whose data is not width x height.
void applyUpdate(nav_msgs::OccupancyGrid& map, const map_msgs::OccupancyGridUpdate& update);

/// The grid as a map message (free 0, occupied 100, unknown -1), header left to the caller.
void toMsg(const OccupancyGrid& grid, nav_msgs::OccupancyGrid& msg);

/// The grid as Cartographer publishes its map: each observed cell's probability of being
/// occupied x 100 (from its log-odds, rounded), -1 where nothing was observed (log-odds 0).
void toProbabilityMsg(const OccupancyGrid& grid, nav_msgs::OccupancyGrid& msg);

/// A room-id image (CV_32S, row y = grid row y, 0 = no room) on `geometry` as a map message:
/// cell value = room id, ids above 100 wrap into 1..100 (rviz's "map" colour scheme shows
/// them as distinct greys), 0 and -1 (no room) become -1. Header left to the caller.
void labelsToMsg(const cv::Mat& labels, const GridGeometry& geometry, nav_msgs::OccupancyGrid& msg);

/// Planar pose of a 3D pose (heading = yaw).
Pose2 toPose2(const geometry_msgs::Pose& pose);
Pose2 toPose2(const geometry_msgs::Transform& transform);
/// 3D pose of a planar pose (z = 0).
geometry_msgs::Pose toPoseMsg(const Pose2& pose);

}  // namespace roomscout::ros1
