#pragma once
// A World rasterised for simulation: what the laser plane hits, what the robot bumps into,
// and which room each point belongs to, on a fine grid aligned with the map grid.

#include <cstdint>
#include <vector>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/sim/world.hpp"

namespace roomscout::sim {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct WorldModelOptions {
  double raster_resolution_m = 0.025;
  double laser_height_m = 0.18;
  double robot_height_m = 0.19;
  double robot_radius_m = 0.105;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Rasterised ground truth. Immutable after construction; safe to share between threads.
class WorldModel {
 public:
  /// Throws InputError (naming world.source) when the world has no free space, its given
  /// start pose is outside the world or too close to a solid object, or its raster would
  /// have more than kMaxGridCells cells (checked before the raster is allocated).
  WorldModel(const World& world, const WorldModelOptions& options = {});

  const World& world() const { return world_; }
  const WorldModelOptions& options() const { return options_; }
  const GridGeometry& geometry() const { return geometry_; }

  /// Solid cells in the laser plane (1) and for robot motion (1), row-major over geometry().
  const std::vector<std::uint8_t>& laserSolid() const { return laser_solid_; }
  const std::vector<std::uint8_t>& robotSolid() const { return robot_solid_; }
  bool blocksLaser(Cell c) const {
    return !geometry_.contains(c) || laser_solid_[geometry_.index(c)];
  }

  /// Distance from a point to the nearest robot-solid raster cell [m] (accurate to a cell).
  double clearance_m(const Vec2& p_m) const;
  /// The same per raster cell, row-major over geometry().
  const std::vector<float>& clearanceMap_m() const { return clearance_m_; }
  /// True when the robot disc centred at p_m touches nothing solid.
  bool robotFits(const Vec2& p_m) const { return clearance_m(p_m) >= options_.robot_radius_m; }

  /// Ground-truth room id at a point (0 = none).
  int roomAt(const Vec2& p_m) const;
  /// True when the world labels at least one room (HouseExpo plans, say, label none).
  bool hasRooms() const { return has_rooms_; }

  /// The start pose: the world's own, or for worlds without one, the free cell of largest
  /// clearance in the largest free region (deterministic).
  const Pose2& start() const { return start_; }

  /// Area of the free floor in the region connected to the start [m^2].
  double freeArea_m2() const { return free_area_m2_; }

 private:
  void rasterizeGeometry();
  void rasterizeImage();
  void computeClearance();
  void chooseStart();

  World world_;
  WorldModelOptions options_;
  GridGeometry geometry_;
  std::vector<std::uint8_t> laser_solid_;
  std::vector<std::uint8_t> robot_solid_;
  std::vector<float> clearance_m_;
  std::vector<std::int32_t> room_labels_;
  bool has_rooms_ = false;
  Pose2 start_;
  double free_area_m2_ = 0.0;
};

}  // namespace roomscout::sim
