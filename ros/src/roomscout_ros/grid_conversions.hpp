#pragma once
// Conversions between ROS 1 messages and the library's types: nav_msgs/OccupancyGrid and
// OccupancyGrid, geometry_msgs poses and Pose2. The nodes stay thin adapters over these.

#include <optional>
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
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

/// Reads a map message as map_server classifies an image: -1 unknown, a value of at least
/// `occupied_percent` occupied, at most `free_percent` free, anything between unknown. The
/// float resolution is read as the decimal it was written from (0.05f as 0.05).
/// `previous` (may be null) is the grid of the last message, for the changed cells.
/// Throws InvalidArgument naming the problem for a map the library cannot use: a rotated
/// origin, a resolution <= 0 or not finite, a data size that is not width x height.
ReceivedGrid fromMsg(const nav_msgs::OccupancyGrid& msg, const OccupancyGrid* previous = nullptr,
                     int occupied_percent = 65, int free_percent = 19);

/// The grid as a map message (free 0, occupied 100, unknown -1), header left to the caller.
void toMsg(const OccupancyGrid& grid, nav_msgs::OccupancyGrid& msg);

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
