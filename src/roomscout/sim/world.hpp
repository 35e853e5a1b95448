#pragma once
// Ground truth of a simulated building: walls with door openings, furniture with heights,
// labelled rooms and a start pose. Either described geometrically (built-in world files) or
// as an occupancy image (map_server worlds); the simulator rasterises both the same way.

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/geometry.hpp"

namespace roomscout::sim {

/// A straight wall piece: a rectangle of `thickness_m` centred on segment a-b, solid between
/// z_min_m and z_max_m. Door openings are already cut out (a lintel is a piece with z_min_m > 0).
struct Wall {
  Vec2 a_m = Vec2::Zero();
  Vec2 b_m = Vec2::Zero();
  double thickness_m = 0.15;
  double z_min_m = 0.0;
  double z_max_m = 2.5;
};

/// A door opening, kept for reference and drawing (the walls already have the gap).
struct Door {
  Vec2 center_m = Vec2::Zero();
  double width_m = 0.9;
};

/// One solid piece of furniture: a prism over `footprint_m` between z_min_m and z_max_m.
/// A table is a top piece over leg pieces, so the space under it is free.
struct FurniturePiece {
  std::string name;
  Polygon footprint_m;
  double z_min_m = 0.0;
  double z_max_m = 0.75;
};

/// A labelled ground-truth room. `id` is 1-based and unique within a world.
struct Room {
  int id = 0;
  std::string name;
  Polygon polygon_m;  ///< empty for image worlds, whose rooms come from a label image
};

/// An occupancy-image world: every pixel the thresholds do not call free is solid at every
/// height. Pixel (col, row) with row 0 at the top, as in the image file.
struct ImageWorld {
  cv::Mat solid;        ///< CV_8U, 255 = solid, 0 = free
  cv::Mat room_labels;  ///< CV_32S, 0 = no room, k = room id; empty if none given
  double resolution_m = 0.05;
  Vec2 origin_m = Vec2::Zero();  ///< map frame position of the image's lower-left corner
};

/// A whole world. Geometric worlds fill walls/furniture/rooms; image worlds fill `image`.
struct World {
  std::string name;
  std::string source;  ///< where it came from: "builtin:NAME" or a file path
  std::string description;
  Pose2 start;
  bool start_given = false;  ///< false for image worlds until a start pose is chosen
  double wall_height_m = 2.5;
  std::vector<Wall> walls;
  std::vector<Door> doors;
  std::vector<FurniturePiece> furniture;
  std::vector<Room> rooms;
  std::optional<ImageWorld> image;

  /// Axis-aligned bounds of everything in the world [m]: (min corner, max corner).
  std::pair<Vec2, Vec2> bounds() const;
};

}  // namespace roomscout::sim
