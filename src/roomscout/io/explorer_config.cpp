#include "roomscout/io/explorer_config.hpp"

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/options_yaml.hpp"

namespace roomscout::io {

std::vector<ParameterGroup> ExplorerConfig::groups(
    std::string_view method, std::uint64_t seed,
    std::vector<std::unique_ptr<ExplorationStrategy>>& others) {
  std::vector<ParameterGroup> groups = explorer.groups();
  groups.push_back({"pointcloud", cloud_map.parameters()});
  groups.push_back({"keyframes", keyframes.parameters()});
  // Every method has a group of its own, so that one file serves all methods.
  for (const StrategyEntry& e : strategyRegistry()) {
    if (e.name == method) {
      groups.push_back({e.name, strategy->parameters()});
    } else {
      others.push_back(e.create(seed));
      groups.push_back({e.name, others.back()->parameters()});
    }
  }
  return groups;
}

std::vector<RenamedOption> ExplorerConfig::renamedOptions() {
  std::vector<RenamedOption> renamed = ExplorerOptions::renamedOptions();
  // The robot's description, formerly read from the simulator's groups.
  renamed.push_back({"robot.radius_m", "costmap.robot_radius_m", ""});
  renamed.push_back({"laser.range_max_m", "explorer.sensor_range_m", ""});
  renamed.push_back({"follower.goal_tolerance_m", "explorer.arrival_tolerance_m", ""});
  renamed.push_back({"follower.lookahead_m", "explorer.progress_lookahead_m", ""});
  const std::string simulator = "a simulator option; the robot's explorer does not read it";
  renamed.push_back({"pointcloud.remove_floor_ceiling", "", simulator});
  for (const char* group :
       {"robot", "world", "laser", "lidar", "mapping", "follower", "episode", "noise", "slam"}) {
    renamed.push_back({group, "", "a simulator group; the robot's explorer does not read it"});
  }
  return renamed;
}

ExplorerConfig loadExplorerConfig(std::string_view method, std::uint64_t seed,
                                  const std::filesystem::path& file) {
  ExplorerConfig config;
  config.strategy = createStrategy(method, seed);
  std::vector<std::unique_ptr<ExplorationStrategy>> others;
  std::vector<ParameterGroup> groups = config.groups(method, seed, others);
  if (!file.empty()) config.warnings = applyConfigFile(file, groups, config.renamedOptions());
  try {
    config.explorer.validate();
    config.cloud_map.validate();
    config.keyframes.validate();
    config.strategy->validateOptions();
  } catch (const OptionError& e) {
    if (file.empty()) throw;
    throw OptionError(file.string() + ": " + e.what());
  }
  return config;
}

}  // namespace roomscout::io
