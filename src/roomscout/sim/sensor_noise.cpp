#include "roomscout/sim/sensor_noise.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout::sim {
namespace {

bool finiteNonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

/// The tb3 profile; see the header comment for the sources.
NoiseProfile turtlebot3() {
  NoiseProfile p;
  p.laser = {
      .sd_near_m = 0.0075, .near_limit_m = 0.5, .sd_fraction = 0.025, .dropout_probability = 0.01};
  p.lidar = {
      .sd_near_m = 0.015, .near_limit_m = 0.5, .sd_fraction = 0.0, .dropout_probability = 0.0};
  p.odometry = {
      .translation_sd_per_m = 0.02, .rotation_sd_per_rad = 0.03, .rotation_sd_per_m = 0.01};
  return p;
}

/// tb3 with every standard deviation times 2.5 and more dropouts.
NoiseProfile harsh() {
  constexpr double kScale = 2.5;
  NoiseProfile p = turtlebot3();
  for (RangeNoise* r : {&p.laser, &p.lidar}) {
    r->sd_near_m *= kScale;
    r->sd_fraction *= kScale;
  }
  p.laser.dropout_probability = 0.03;
  p.lidar.dropout_probability = 0.01;
  p.odometry.translation_sd_per_m *= kScale;
  p.odometry.rotation_sd_per_rad *= kScale;
  p.odometry.rotation_sd_per_m *= kScale;
  return p;
}

}  // namespace

bool RangeNoise::none() const {
  return sd_near_m == 0.0 && sd_fraction == 0.0 && dropout_probability == 0.0;
}

double RangeNoise::sd_m(double range_m) const {
  if (range_m < near_limit_m) return sd_near_m;
  return std::max(sd_near_m, sd_fraction * range_m);
}

void RangeNoise::validate() const {
  if (!(finiteNonNegative(sd_near_m) && finiteNonNegative(sd_fraction))) {
    throw InvalidArgument("range noise: sd_near_m and sd_fraction must be finite and >= 0");
  }
  if (!(near_limit_m >= 0.0)) throw InvalidArgument("range noise: near_limit_m must be >= 0");
  if (!(dropout_probability >= 0.0 && dropout_probability <= 1.0)) {
    throw InvalidArgument("range noise: dropout_probability must be in [0, 1]");
  }
}

bool OdometryNoise::none() const {
  return translation_sd_per_m == 0.0 && rotation_sd_per_rad == 0.0 && rotation_sd_per_m == 0.0;
}

void OdometryNoise::validate() const {
  if (!(finiteNonNegative(translation_sd_per_m) && finiteNonNegative(rotation_sd_per_rad) &&
        finiteNonNegative(rotation_sd_per_m))) {
    throw InvalidArgument("odometry noise: every standard deviation must be finite and >= 0");
  }
}

NoiseProfile NoiseProfile::named(std::string_view name) {
  if (name == "none") return {};
  if (name == "tb3") return turtlebot3();
  if (name == "harsh") return harsh();
  throw OptionError("noise.profile must be \"none\", \"tb3\" or \"harsh\", not \"" +
                    std::string(name) + "\"");
}

void NoiseOptions::validate() const { NoiseProfile::named(profile); }

std::vector<ParameterRef> NoiseOptions::parameters() {
  return {
      {"profile", &profile,
       "sensor and odometry noise: none, tb3 (TurtleBot3 Burger: LDS-01 laser, VLP-16 lidar, "
       "wheel odometry) or harsh (2.5 x tb3's standard deviations, more dropouts)"},
  };
}

NoiseProfile NoiseOptions::resolved() const { return NoiseProfile::named(profile); }

OdometrySimulator::OdometrySimulator(const OdometryNoise& noise, const Pose2& start,
                                     std::uint64_t seed)
    : noise_(noise), pose_(start), rng_(seed) {
  noise_.validate();
}

void OdometrySimulator::step(const Pose2& before, const Pose2& after) {
  // The true increment in the robot frame at `before`.
  const double cb = std::cos(before.yaw_rad), sb = std::sin(before.yaw_rad);
  const double dx = after.x_m - before.x_m, dy = after.y_m - before.y_m;
  double forward_m = cb * dx + sb * dy;
  const double lateral_m = -sb * dx + cb * dy;
  double dtheta_rad = wrapAngle(after.yaw_rad - before.yaw_rad);
  if (!noise_.none()) {
    // Variances linear in |d| and |dtheta|: the sum over steps does not depend on their size.
    const double d = std::abs(forward_m);
    const double sd_forward_m = noise_.translation_sd_per_m * std::sqrt(d);
    const double sd_heading_rad =
        std::sqrt(noise_.rotation_sd_per_rad * noise_.rotation_sd_per_rad * std::abs(dtheta_rad) +
                  noise_.rotation_sd_per_m * noise_.rotation_sd_per_m * d);
    if (sd_forward_m > 0.0) forward_m += sd_forward_m * gauss_(rng_);
    if (sd_heading_rad > 0.0) dtheta_rad += sd_heading_rad * gauss_(rng_);
  }
  // Exact SE(2) composition: the translation in the odometry frame at the step's start, then
  // the rotation; without noise this reproduces the true pose up to round-off.
  const double co = std::cos(pose_.yaw_rad), so = std::sin(pose_.yaw_rad);
  pose_.x_m += co * forward_m - so * lateral_m;
  pose_.y_m += so * forward_m + co * lateral_m;
  pose_.yaw_rad = wrapAngle(pose_.yaw_rad + dtheta_rad);
}

}  // namespace roomscout::sim
