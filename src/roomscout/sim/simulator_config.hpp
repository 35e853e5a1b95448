#pragma once
// A simulator's configuration file, as roomscout_sim_node reads it: the file `roomscout
// explore --config` reads, of which the simulator uses the episode's groups (EpisodeConfig)
// and the point cloud's ("lidar", "pointcloud", "keyframes"). The groups of the exploration
// methods are accepted, so that one file serves the simulator and the explorer, and checked
// but not used.

#include <filesystem>
#include <string>
#include <vector>

#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/point_cloud_observer.hpp"

namespace roomscout::sim {

/// Every option of a simulated robot, resolved and validated.
struct SimulatorConfig {
  EpisodeConfig episode;
  PointCloudObserverOptions cloud;  ///< lidar_noise is noise.profile's
  /// One per option the file gives under a former name (for the user to see).
  std::vector<std::string> warnings;
};

/// Applies `file` (none when empty) over the defaults, then resolves and validates every
/// option. Throws OptionError for an option out of range or an unknown group or option,
/// InputError for an unreadable or malformed file (both naming the file).
SimulatorConfig loadSimulatorConfig(const std::filesystem::path& file);

}  // namespace roomscout::sim
