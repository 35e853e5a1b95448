#pragma once
// A robot's explorer configuration file: the Explorer's own groups ("costmap", "planner",
// "explorer", "maps", "segmentation", "topology"), the point cloud map's ("pointcloud",
// "keyframes") and one group per exploration method, as roomscout_explore_node reads it. It
// names no simulator option: the simulator's groups are ignored with a warning, and the
// former names of the Explorer's options are read with one.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/explorer/explorer.hpp"
#include "roomscout/mapping/keyframe_selector.hpp"
#include "roomscout/mapping/point_cloud_map.hpp"

namespace roomscout::io {

/// Everything a robot's explorer is configured with. Not copyable (owns the strategy).
struct ExplorerConfig {
  std::unique_ptr<ExplorationStrategy> strategy;
  ExplorerOptions explorer;
  PointCloudMapOptions cloud_map;  ///< group "pointcloud"
  KeyframeOptions keyframes;       ///< group "keyframes"
  /// One per option the file gives under a former name or from the simulator.
  std::vector<std::string> warnings;

  /// Every group the file may set, pointing into this config; the groups of methods other
  /// than the strategy's point into default strategies appended to `others`, which must
  /// outlive the groups.
  std::vector<ParameterGroup> groups(std::string_view method, std::uint64_t seed,
                                     std::vector<std::unique_ptr<ExplorationStrategy>>& others);
  /// The former and simulator names a robot's config file may still use (for one release).
  static std::vector<RenamedOption> renamedOptions();
};

/// Creates the strategy `method` for `seed` and applies `file` (none when empty). Throws
/// OptionError for an unknown method or an option out of range, InputError for an unreadable
/// or malformed file (both naming the file).
ExplorerConfig loadExplorerConfig(std::string_view method, std::uint64_t seed,
                                  const std::filesystem::path& file);

}  // namespace roomscout::io
