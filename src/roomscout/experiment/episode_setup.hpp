#pragma once
// The resolved options of one episode: defaults, then a config file, then the command line.
// Shared by `roomscout explore` and `roomscout bench`, so both run an episode the same way.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "roomscout/exploration/exploration_strategy.hpp"
#include "roomscout/io/pcd_io.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/point_cloud_observer.hpp"

namespace roomscout::experiment {

/// What the command line sets for every episode of a run besides world, method and seed.
struct RunSettings {
  std::filesystem::path config_file;  ///< YAML options grouped as in metrics.json; empty = none
  std::optional<double> max_time_s;   ///< overrides episode.max_time_s [s]
  bool remove_floor = false;          ///< overrides pointcloud.remove_floor_ceiling when set
  io::PcdFormat pcd_format = io::PcdFormat::kBinaryCompressed;  ///< pointcloud.pcd encoding
  double pcd_precision_m =
      0.005;                     ///< pointcloud.pcd coordinates rounded to multiples [m]; 0 = exact
  bool background_maps = false;  ///< build the maps the strategy does not read (point cloud;
                                 ///< skeleton and rooms unless it readsRooms()) on two
                                 ///< background threads; the outputs are the same either way
  /// Throws OptionError naming the command-line option that is out of range.
  void validate() const;
};

/// Every option of one episode, resolved and validated. Not copyable (owns the strategy).
struct EpisodeSetup {
  std::string method;
  std::uint64_t seed = 0;
  sim::EpisodeConfig config;
  std::unique_ptr<ExplorationStrategy> strategy;
  sim::PointCloudObserverOptions cloud;
  /// One per option the config file gives under a former name (for the user to see).
  std::vector<std::string> warnings;

  /// Every resolved option as metrics.json's `options`: {group: {name: value}}, the
  /// method's own group included (other methods' groups are not).
  nlohmann::json optionsJson();
};

/// Every group a config file may set, pointing into `setup`: the episode's groups, the point
/// cloud's, then one per registered method in the registry's order. The group of
/// setup.method points into setup.strategy; the others into default strategies (created with
/// setup.seed) appended to `others`, which must outlive the groups.
std::vector<ParameterGroup> configGroups(EpisodeSetup& setup,
                                         std::vector<std::unique_ptr<ExplorationStrategy>>& others);

/// Creates the strategy `method` for `seed` and resolves every option. Every registered method
/// has a group in the config file, so that one file serves all methods; groups of other
/// methods are checked but not used. Throws OptionError for an unknown method or an option
/// out of range (naming the config file, when one is given), InputError for an unreadable or
/// malformed config file (naming it).
EpisodeSetup makeEpisodeSetup(std::string_view method, std::uint64_t seed,
                              const RunSettings& settings);

}  // namespace roomscout::experiment
