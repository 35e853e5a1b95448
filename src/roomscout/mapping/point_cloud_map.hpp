#pragma once
// A 3D point cloud map in the map frame, voxel-filtered as it grows: each voxel of side
// voxel_size_m keeps the centroid of the points that fell into it (what pcl::VoxelGrid would
// give for the same points), held in an open-addressing hash so a scan is inserted in time
// proportional to its size, not the map's. Knows no sensor or file format.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "roomscout/core/parameters.hpp"

namespace roomscout {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct PointCloudMapOptions {
  double voxel_size_m = 0.05;
  int max_points = 5000000;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Not thread-safe. Voxel indices must fit in 21 bits per axis (+-1 048 576 voxels from the
/// map origin, +-52 km at 0.05 m); points beyond are rejected as out of bounds.
class PointCloudMap {
 public:
  explicit PointCloudMap(const PointCloudMapOptions& options = {});

  const PointCloudMapOptions& options() const { return options_; }

  /// Adds points given in the map frame [m]. Returns the number of new voxels. Non-finite
  /// points and points out of bounds are skipped.
  std::size_t insert(const std::vector<Eigen::Vector3f>& points_map);

  /// One point per voxel (the centroid of its points), in the order the voxels were created.
  std::vector<Eigen::Vector3f> points() const;
  std::size_t size() const { return voxels_.size(); }
  bool empty() const { return voxels_.empty(); }
  /// Axis-aligned bounds of points() [m]; both zero when empty.
  std::pair<Eigen::Vector3f, Eigen::Vector3f> bounds() const;
  /// Points that found the map full (max_points voxels) and were dropped.
  std::size_t droppedPoints() const { return dropped_; }
  /// Bytes held by the map's arrays (capacity, not size).
  std::size_t memoryBytes() const;

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  /// A hash slot: packed voxel index (kEmpty: free) and the voxel's index into voxels_. Packed
  /// into 12 bytes so that a probe touches one cache line.
#pragma pack(push, 4)
  struct Slot {
    std::uint64_t key;
    std::uint32_t voxel;
  };
#pragma pack(pop)
  /// A voxel: sum of its points relative to its centre (float precision far from the origin),
  /// and their number; one cache line per update.
  struct Voxel {
    Eigen::Vector3f sum;
    std::uint32_t count;
  };
  static_assert(sizeof(Slot) == 12 && sizeof(Voxel) == 16);
  void grow();
  std::size_t slotOf(std::uint64_t key) const;

  PointCloudMapOptions options_;
  float inv_voxel_ = 20.0f;
  std::vector<Slot> slots_;  ///< open-addressing hash, linear probing
  std::size_t mask_ = 0;
  std::vector<Voxel> voxels_;              ///< in creation order
  std::vector<std::uint64_t> voxel_keys_;  ///< per voxel: its packed index
  std::size_t dropped_ = 0;
  std::vector<std::uint64_t> scratch_keys_;  ///< insert(): voxel keys of the batch (not map data)
};

}  // namespace roomscout
