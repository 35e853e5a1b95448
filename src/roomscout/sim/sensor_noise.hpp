#pragma once
// Noise models of the simulated sensors and wheel odometry, and the named profiles that set
// them. The profile values and their sources:
// - tb3, LDS-01 2D laser (ROBOTIS e-Manual, TurtleBot3 LDS-01 specification): accuracy
//   +-15 mm for 0.12-0.5 m and +-5 % for 0.5-3.5 m, taken as 2 sd: 7.5 mm below 0.5 m, 2.5 %
//   of the range beyond; 1 % of returns lost.
// - tb3, VLP-16 3D lidar (Velodyne VLP-16 datasheet): range accuracy up to +-3 cm typical,
//   taken as 2 sd: a constant 15 mm; no returns lost.
// - tb3, wheel odometry (TurtleBot3 Burger, Dynamixel XL430 wheel encoders): gmapping's and
//   AMCL's default odometry error parameters (0.1-0.2) are deliberately pessimistic; a tenth
//   to a fifth of them: 0.02 m per m driven, 0.03 rad per rad turned, 0.01 rad per m driven.
// - harsh: 2.5 x every tb3 standard deviation; 3 % of laser and 1 % of lidar returns lost.
// - none: no noise; the simulators then draw nothing from their generators.

#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/core/parameters.hpp"

namespace roomscout::sim {

/// Range noise of one range sensor: Gaussian with a standard deviation that is a fixed
/// distance below near_limit_m and a fraction of the range beyond (never less than the fixed
/// distance, so sd_fraction 0 gives a constant sd), plus random dropouts.
struct RangeNoise {
  double sd_near_m = 0.0;             ///< sd below near_limit_m [m]
  double near_limit_m = 0.5;          ///< [m]
  double sd_fraction = 0.0;           ///< sd as a fraction of the true range beyond near_limit_m
  double dropout_probability = 0.0;   ///< a return lost (reported as no reading) [0, 1]
  bool none() const;                  ///< no sd and no dropouts
  double sd_m(double range_m) const;  ///< the sd at that true range [m]
  /// Throws InvalidArgument unless every figure is finite and >= 0 and the probability <= 1.
  void validate() const;
};

/// Wheel-odometry error as a random walk: over a motion the error's variance grows linearly
/// with the distance driven and the angle turned, so the figures are the standard deviations
/// after 1 m driven / 1 rad turned, whatever the simulation step.
struct OdometryNoise {
  double translation_sd_per_m = 0.0;  ///< sd of the along-track distance error after 1 m [m]
  double rotation_sd_per_rad = 0.0;   ///< sd of the heading error after turning 1 rad [rad]
  double rotation_sd_per_m = 0.0;     ///< sd of the heading error after driving 1 m [rad]
  bool none() const;                  ///< all zero
  /// Throws InvalidArgument unless every figure is finite and >= 0.
  void validate() const;
};

/// The noise of all simulated sensors, by name.
struct NoiseProfile {
  OdometryNoise odometry;
  RangeNoise laser;  ///< LDS-01 2D laser
  RangeNoise lidar;  ///< VLP-16 3D lidar
  /// "none", "tb3" or "harsh" (values and sources in this file's header comment); throws
  /// OptionError naming the key noise.profile and the valid names for anything else.
  static NoiseProfile named(std::string_view name);
};

/// The config group "noise": one key, profile (default "none").
/// Its fields are documented in parameters() and printed by `roomscout options`.
struct NoiseOptions {
  std::string profile = "none";
  void validate() const;  ///< NoiseProfile::named(profile)
  std::vector<ParameterRef> parameters();
  NoiseProfile resolved() const;
};

/// Wheel odometry of the simulated robot: fed the true pose after every motion step, it
/// integrates the true increment (in the robot frame) with the noise added, like encoders.
/// Per step, with d the forward distance and dtheta the heading change of the true increment:
/// forward d + N(0, translation_sd_per_m^2 |d|), lateral exact, dtheta
/// + N(0, rotation_sd_per_rad^2 |dtheta| + rotation_sd_per_m^2 |d|) (variances). With
/// noise.none() the odometry pose is the true pose up to round-off and nothing is drawn.
/// Deterministic for a given seed and call sequence. Not thread-safe.
class OdometrySimulator {
 public:
  /// Throws InvalidArgument for a noise that fails OdometryNoise::validate().
  OdometrySimulator(const OdometryNoise& noise, const Pose2& start, std::uint64_t seed);

  /// The robot moved from `before` to `after` (true poses) in one step.
  void step(const Pose2& before, const Pose2& after);

  /// The odometry pose: `start`, then the noisy increments; heading wrapped to (-pi, pi].
  const Pose2& pose() const { return pose_; }

 private:
  OdometryNoise noise_;
  Pose2 pose_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> gauss_{0.0, 1.0};
};

}  // namespace roomscout::sim
