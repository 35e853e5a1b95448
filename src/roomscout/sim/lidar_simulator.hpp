#pragma once
// Simulated 3D spinning lidar (Velodyne VLP-16 profile by default): rings of beams at fixed
// elevations swept over 360 degrees, cast against the ColumnWorld with a 2D DDA per azimuth
// column that all rings of that column share (they cross the same raster cells and differ
// only in the height at which they cross them). The DDA jumps across squares of empty
// columns, reads the spans of the common kinds of column (a wall, a table) from a small
// table instead of the column, and skips cells and rings whose heights cannot meet a solid
// span, with the same arithmetic as a cell-by-cell walk, so the hits are bit for bit those
// of the plain walk. Optional range noise and dropouts (RangeNoise).

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/sim/column_world.hpp"
#include "roomscout/sim/sensor_noise.hpp"

namespace roomscout::sim {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct LidarOptions {
  int num_rings = 16;
  double elevation_min_deg = -15.0;
  double elevation_max_deg = 15.0;
  double azimuth_step_deg = 0.2;
  double range_min_m = 0.5;
  double range_max_m = 100.0;
  double rate_hz = 10.0;
  double mount_height_m = 0.5;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// What a beam hit.
enum class LidarSurface : std::uint8_t { kObject = 0, kFloor = 1, kCeiling = 2 };

/// One revolution. Points are in the sensor frame (x forward, z up), one per return.
struct LidarScan {
  Eigen::Isometry3d T_map_sensor = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3f> points_sensor;
  std::vector<LidarSurface> surfaces;  ///< per point; lets a map drop the floor and ceiling
};

/// One beam's return: range along the beam [m] and the surface it hit.
struct LidarHit {
  double range_m = 0.0;
  LidarSurface surface = LidarSurface::kObject;
};

/// Casts one revolution at a time, ignoring motion during the revolution. Deterministic for a
/// given seed and call sequence; with noise.none() it draws nothing from its generator. Not
/// thread-safe (the noise generator has state).
class LidarSimulator {
 public:
  /// `world` must outlive the simulator. Throws OptionError for bad options and
  /// InvalidArgument for a noise that fails RangeNoise::validate().
  LidarSimulator(const ColumnWorld& world, const LidarOptions& options, std::uint64_t seed,
                 const RangeNoise& noise = {});

  const LidarOptions& options() const { return options_; }
  const RangeNoise& noise() const { return noise_; }
  int columns() const { return static_cast<int>(cos_azimuth_.size()); }

  /// The sensor pose of a robot pose: mount_height_m above it, same heading.
  Eigen::Isometry3d sensorPose(const Pose2& T_map_robot) const;

  /// A full revolution from the robot pose. Beams without a return within range and lost
  /// returns (noise dropouts) are omitted; noise moves a point along its beam.
  LidarScan scan(const Pose2& T_map_robot);

  /// The first surface along one beam from origin_map [m] with the given map-frame azimuth
  /// and elevation [rad], or nothing within max_range_m. Noise-free.
  std::optional<LidarHit> castRay(const Eigen::Vector3d& origin_map, double azimuth_rad,
                                  double elevation_rad, double max_range_m) const;

 private:
  struct Ring {
    double slope;  ///< dz per horizontal metre
    double cos_elev;
    double limit_m;  ///< horizontal distance where it meets a plane or its range ends
    LidarSurface plane_surface;
    bool plane_hit;  ///< limit_m is a floor/ceiling hit (else the range ends there)
  };
  /// Rings for a sensor at height z_m with the given max range, sorted by limit_m.
  std::vector<Ring> makeRings(const std::vector<double>& elevations_rad, double z_m,
                              double max_range_m, std::vector<int>& order) const;
  /// Casts every ring of one azimuth column. hit_t_m[k] < 0 means no return for ring k, else
  /// it is the horizontal distance to the hit and hit_dz_m[k] the hit's height above the
  /// sensor, exact for horizontal faces (so floor points lie exactly at z = 0).
  void castColumn(const Eigen::Vector2d& origin_m, double z_m, double cos_az, double sin_az,
                  const std::vector<Ring>& rings, const std::vector<int>& order, double* hit_t_m,
                  double* hit_dz_m, LidarSurface* hit_surface) const;

  const ColumnWorld& world_;
  LidarOptions options_;
  RangeNoise noise_;
  std::vector<double> elevations_rad_;
  std::vector<double> cos_azimuth_, sin_azimuth_;  ///< per column, sensor frame
  /// Per raster cell: the kind of a non-empty column (an index into kind_offsets_, or
  /// kReadColumn for a column of no listed kind), or kClearBase - 1 plus the chessboard
  /// distance to the nearest non-empty column, capped at 255. The DDA reads a solid column's
  /// spans from its kind without touching the column, and jumps across empty squares.
  std::vector<std::uint8_t> clear_cells_;
  static constexpr int kKinds = 32;  ///< codes 0 .. kKinds - 2: kinds; kKinds - 1: kReadColumn
  static constexpr std::uint8_t kReadColumn = kKinds - 1, kClearBase = kKinds;
  std::vector<ZInterval> kind_spans_;        ///< the kinds' span lists, one after another
  std::vector<std::uint32_t> kind_offsets_;  ///< kind k: kind_spans_[offsets[k] .. offsets[k + 1])
  std::mt19937_64 rng_;
};

}  // namespace roomscout::sim
