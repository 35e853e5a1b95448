#pragma once
// Simulated 2D laser scanner (TurtleBot3's LDS-01 profile): ray casting against the world's
// laser-plane raster, with optional range noise and dropouts (RangeNoise).

#include <cstdint>
#include <random>

#include "roomscout/core/laser_scan.hpp"
#include "roomscout/core/parameters.hpp"
#include "roomscout/sim/sensor_noise.hpp"
#include "roomscout/sim/world_model.hpp"

namespace roomscout::sim {

/// Its fields are documented in parameters() and printed by `roomscout options`.
struct LaserOptions {
  int num_beams = 360;
  double range_min_m = 0.12;
  double range_max_m = 3.5;
  double rate_hz = 5.0;
  void validate() const;
  std::vector<ParameterRef> parameters();
};

/// Casts one scan at a time. Deterministic for a given seed and call sequence; with
/// noise.none() it draws nothing from its generator. Not thread-safe.
class LaserSimulator {
 public:
  /// `world` must outlive the simulator. Throws OptionError for bad options and
  /// InvalidArgument for a noise that fails RangeNoise::validate().
  LaserSimulator(const WorldModel& world, const LaserOptions& options, std::uint64_t seed,
                 const RangeNoise& noise = {});

  const LaserOptions& options() const { return options_; }
  const RangeNoise& noise() const { return noise_; }

  /// A full scan from the sensor pose. Beams with no obstacle within range_max_m return +inf;
  /// returns closer than range_min_m and lost returns (noise dropouts) read 0, as on the LDS-01;
  /// an obstacle within range that noise puts beyond range_max_m reads as measured.
  LaserScan scan(const Pose2& T_map_sensor);

  /// Exact distance along a ray to the first laser-solid raster cell, or +inf beyond max_m.
  double castRay(const Vec2& origin_m, double angle_rad, double max_m) const;

 private:
  const WorldModel& world_;
  LaserOptions options_;
  RangeNoise noise_;
  std::mt19937_64 rng_;
};

}  // namespace roomscout::sim
