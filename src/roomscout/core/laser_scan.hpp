#pragma once
// One 2D laser scan, as a driver (or the simulator) delivers it: sensor_msgs/LaserScan's
// fields in our units.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace roomscout {

/// Ranges of one sweep, beam i at angle angle_min_rad + i * angle_increment_rad in the sensor
/// frame, read as REP 117 has it: +inf means "no return", the beam saw free space up to
/// range_max_m and no obstacle; NaN, -inf and finite ranges outside [range_min_m,
/// range_max_m] are invalid readings that carry no information.
struct LaserScan {
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double range_min_m = 0.12;
  double range_max_m = 3.5;
  std::vector<float> ranges_m;
};

/// The scan as a sensor of range `max_m` would see it: range_max_m lowered to `max_m` and the
/// returns beyond it made "no return" (+inf), since the space up to `max_m` was seen free.
inline LaserScan cappedToRange(LaserScan scan, double max_m) {
  if (!(max_m < scan.range_max_m)) return scan;
  for (float& r : scan.ranges_m)
    if (std::isfinite(r) && r > max_m && r <= scan.range_max_m)
      r = std::numeric_limits<float>::infinity();
  scan.range_max_m = max_m;
  return scan;
}

}  // namespace roomscout
