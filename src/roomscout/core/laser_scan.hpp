#pragma once
// One 2D laser scan, as a driver (or the simulator) delivers it: sensor_msgs/LaserScan's
// fields in our units.

#include <vector>

namespace roomscout {

/// Ranges of one sweep, beam i at angle angle_min_rad + i * angle_increment_rad in the sensor
/// frame. A range outside [range_min_m, range_max_m] (including +inf) means "no return":
/// the beam saw free space up to range_max_m and no obstacle.
struct LaserScan {
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double range_min_m = 0.12;
  double range_max_m = 3.5;
  std::vector<float> ranges_m;
};

}  // namespace roomscout
