#include "roomscout/sim/laser_simulator.hpp"

#include <cmath>
#include <limits>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/grid_ray.hpp"

namespace roomscout::sim {

void LaserOptions::validate() const {
  if (num_beams < 1 || num_beams > 100000)
    throw OptionError("laser.num_beams must be in [1, 100000]");
  if (!(range_min_m >= 0.0 && range_min_m < range_max_m)) {
    throw OptionError("laser: need 0 <= range_min_m < range_max_m");
  }
  if (!(rate_hz > 0.0)) throw OptionError("laser.rate_hz must be > 0");
}

std::vector<ParameterRef> LaserOptions::parameters() {
  return {
      {"num_beams", &num_beams, "beams per revolution, evenly spaced over 360 degrees"},
      {"range_min_m", &range_min_m, "minimum range: closer returns are dropped [m]"},
      {"range_max_m", &range_max_m, "maximum range: no return beyond it [m]"},
      {"rate_hz", &rate_hz, "scans per second"},
  };
}

LaserSimulator::LaserSimulator(const WorldModel& world, const LaserOptions& options,
                               std::uint64_t seed, const RangeNoise& noise)
    : world_(world), options_(options), noise_(noise), rng_(seed) {
  options_.validate();
  noise_.validate();
}

double LaserSimulator::castRay(const Vec2& origin_m, double angle_rad, double max_m) const {
  const GridGeometry& g = world_.geometry();
  const double res = g.resolution_m();
  GridRay ray((origin_m - g.origin_m()) / res, std::cos(angle_rad), std::sin(angle_rad));
  if (world_.blocksLaser({ray.x(), ray.y()})) return 0.0;
  const double t_limit = max_m / res;
  const auto& solid = world_.laserSolid();
  const int w = g.width(), h = g.height();
  while (true) {
    const double t_enter = ray.step();
    if (t_enter > t_limit) return std::numeric_limits<double>::infinity();
    const int x = ray.x(), y = ray.y();
    if (x < 0 || y < 0 || x >= w || y >= h || solid[static_cast<std::size_t>(y) * w + x]) {
      return t_enter * res;
    }
  }
}

LaserScan LaserSimulator::scan(const Pose2& T_map_sensor) {
  LaserScan scan;
  scan.angle_min_rad = -M_PI;
  scan.angle_increment_rad = 2.0 * M_PI / options_.num_beams;
  scan.range_min_m = options_.range_min_m;
  scan.range_max_m = options_.range_max_m;
  scan.ranges_m.resize(options_.num_beams);
  const bool noisy = !noise_.none();
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::bernoulli_distribution dropout(noise_.dropout_probability);
  const Vec2 origin = T_map_sensor.position();
  const float inf = std::numeric_limits<float>::infinity();
  for (int i = 0; i < options_.num_beams; ++i) {
    const double angle = T_map_sensor.yaw_rad + scan.angle_min_rad + i * scan.angle_increment_rad;
    double r = castRay(origin, angle, options_.range_max_m);
    if (std::isfinite(r) && noisy) {
      if (noise_.dropout_probability > 0.0 && dropout(rng_)) {
        scan.ranges_m[i] = 0.0f;  // a lost return: the LDS-01 reports 0 for an invalid reading
        continue;
      }
      const double sd_m = noise_.sd_m(r);
      if (sd_m > 0.0) r = std::max(0.0, r + sd_m * gauss(rng_));
    }
    if (!std::isfinite(r)) {
      scan.ranges_m[i] = inf;
    } else if (r > options_.range_max_m) {
      // A real obstacle measured beyond the range by noise: reported as read, a value outside
      // [range_min, range_max] that consumers discard (REP 117), not as "nothing within range".
      scan.ranges_m[i] = static_cast<float>(r);
    } else if (r < options_.range_min_m) {
      scan.ranges_m[i] = 0.0f;  // below range_min: reported as an invalid (too close) reading
    } else {
      scan.ranges_m[i] = static_cast<float>(r);
    }
  }
  return scan;
}

}  // namespace roomscout::sim
