#pragma once
// ROS map_server maps (a YAML file next to a PGM/PNG image): read as occupancy grids (or as the
// classified image a simulator world is made from), and write occupancy grids in the same format.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::io {

/// The contents of a map_server YAML file.
struct MapServerMetadata {
  std::filesystem::path image;    ///< image file, already resolved against the YAML's folder
  double resolution_m = 0.05;     ///< cell side [m/pixel]
  Vec2 origin_m = Vec2::Zero();   ///< map frame position of the image's lower-left corner
  double origin_yaw_rad = 0.0;    ///< always 0: rotated origins are rejected
  bool negate = false;            ///< true: white is occupied, black is free
  double occupied_thresh = 0.65;  ///< occupancy probability above which a pixel is occupied
  double free_thresh = 0.196;     ///< occupancy probability below which a pixel is free
  std::string mode = "trinary";   ///< "trinary" or "scale" (both classify the same way here)
};

/// Reads a map_server YAML file. Required keys: image, resolution, origin; defaults: negate 0,
/// occupied_thresh 0.65, free_thresh 0.196, mode trinary; other keys are ignored, as
/// map_server does. Throws InputError for a bad value (resolution <= 0, thresholds outside
/// [0, 1] or free >= occupied, a non-zero origin yaw, mode raw), a missing key or a missing
/// image file.
MapServerMetadata loadMapServerYaml(const std::filesystem::path& yaml_path);

/// Classifies an image's pixels exactly as map_server does: with v the pixel's grey value
/// (colour channels averaged, alpha ignored) scaled to [0, 255], p = (255 - v) / 255, or
/// v / 255 when `negate`; p > occupied_thresh is occupied, p < free_thresh is free, anything
/// else unknown. Returns one CellState per pixel (CV_8U, same orientation as the image).
/// Accepts 8- or 16-bit images with 1 to 4 channels; throws InvalidArgument otherwise.
cv::Mat classifyMapImage(const cv::Mat& image, const MapServerMetadata& metadata);

/// Reads the image `metadata` names (8- or 16-bit, 1 to 4 channels, as stored). Throws
/// InputError naming the file for an unreadable or corrupt image, or naming `yaml_path` for an
/// image of more than kMaxGridCells pixels (read from a PNG or PGM header before the image is
/// decoded; core/grid_limits.hpp).
cv::Mat readMapImage(const std::filesystem::path& yaml_path, const MapServerMetadata& metadata);

/// A room label image read as room ids.
struct RoomLabelImage {
  cv::Mat labels;        ///< CV_32S, the image's size: 0 = no room, k = room k
  std::vector<int> ids;  ///< the ids present, in order of their numbering
};

/// Reads a room label image for a map of `map_size` pixels: either 8/16-bit greyscale (0 = no
/// room, k = room k) or colour (each distinct colour other than black and white is a room,
/// numbered 1, 2, ... in order of first appearance in a row-major scan). Throws InputError
/// naming the file for an unreadable or corrupt image or one of another size.
RoomLabelImage readRoomLabelImage(const std::filesystem::path& path, cv::Size map_size);

/// Loads a map_server map as an OccupancyGrid (cell states set from the classification,
/// geometry from resolution and origin). Map cell (x, y) is pixel (x, height - 1 - y).
/// Refuses images larger than kMaxGridCells as readMapImage does.
OccupancyGrid loadOccupancyMap(const std::filesystem::path& yaml_path);

/// Writes `grid` as NAME.pgm (binary P5: 254 free, 0 occupied, 205 unknown, first row = top)
/// and NAME.yaml next to it, NAME being yaml_path's stem; both written atomically, image
/// first. loadOccupancyMap reads back the same states and geometry. Throws InvalidArgument
/// for an empty grid and InputError when a file cannot be written.
void saveOccupancyMap(const OccupancyGrid& grid, const std::filesystem::path& yaml_path);

}  // namespace roomscout::io
