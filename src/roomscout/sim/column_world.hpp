#pragma once
// The 3D ground truth of a world as a 2.5D column representation: for every raster cell of
// the WorldModel, the sorted, disjoint z-intervals that are solid there, plus a floor plane at
// z = 0 and a ceiling plane at the world's wall height over the whole raster. Walls are
// extruded between their z range (a door leaves a gap under its lintel), furniture pieces
// between theirs (a table is a top over four legs, free underneath), and every solid pixel
// of an image world from the floor to the default wall height.

#include <cstdint>
#if __cplusplus >= 202002L
#include <span>
#endif
#include <vector>

#include <Eigen/Core>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {

/// A solid span of one column [m], z_min_m < z_max_m.
struct ZInterval {
  float z_min_m = 0.0f;
  float z_max_m = 0.0f;
};

/// Immutable after construction; safe to share between threads.
class ColumnWorld {
 public:
  /// Builds the columns on `world`'s raster (same geometry as its 2D rasters).
  explicit ColumnWorld(const WorldModel& world);

  const GridGeometry& geometry() const { return geometry_; }
  /// Height of the floor plane [m] (always 0).
  double floor_m() const { return 0.0; }
  /// Height of the ceiling plane [m]: the world's default wall height.
  double ceiling_m() const { return ceiling_m_; }

  /// Solid intervals of a cell inside geometry(), sorted by z and disjoint.
#if __cplusplus >= 202002L  // the ROS 1 nodes include this header as C++17
  std::span<const ZInterval> intervals(std::size_t cell_index) const {
    return {intervals_.data() + offsets_[cell_index], intervals_.data() + offsets_[cell_index + 1]};
  }
#endif
  bool columnEmpty(std::size_t cell_index) const {
    return offsets_[cell_index] == offsets_[cell_index + 1];
  }

  /// True when the point p_map [m] is inside a solid interval, below the floor or above the
  /// ceiling. Points outside the raster are not solid.
  bool solidAt(const Eigen::Vector3d& p_map) const;

  /// True when a surface (floor, ceiling or the boundary of a solid column interval) lies
  /// within `tolerance_m` of p_map (checked over the raster cells within that radius and by
  /// interval bounds grown by the tolerance; conservative by up to one raster cell).
  bool nearSurface(const Eigen::Vector3d& p_map, double tolerance_m) const;

  /// Number of solid intervals over all columns, and bytes held by the representation.
  std::size_t intervalCount() const { return intervals_.size(); }
  std::size_t memoryBytes() const {
    return offsets_.size() * sizeof(std::uint32_t) + intervals_.size() * sizeof(ZInterval);
  }

 private:
  GridGeometry geometry_;
  double ceiling_m_ = 2.5;
  std::vector<std::uint32_t> offsets_;  ///< cellCount() + 1 entries into intervals_
  std::vector<ZInterval> intervals_;
};

}  // namespace roomscout::sim
