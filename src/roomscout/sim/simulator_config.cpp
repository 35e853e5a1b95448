#include "roomscout/sim/simulator_config.hpp"

#include <memory>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/options_yaml.hpp"

namespace roomscout::sim {

SimulatorConfig loadSimulatorConfig(const std::filesystem::path& file) {
  SimulatorConfig config;
  std::vector<ParameterGroup> groups = config.episode.groups();
  for (ParameterGroup& g : config.cloud.groups()) groups.push_back(std::move(g));
  // Every method's group, read into default strategies that are then dropped (the seed only
  // seeds their random numbers, which nothing draws).
  std::vector<std::unique_ptr<ExplorationStrategy>> methods;
  for (const StrategyEntry& e : strategyRegistry()) {
    methods.push_back(e.create(1));
    groups.push_back({e.name, methods.back()->parameters()});
  }
  if (!file.empty()) {
    config.warnings = io::applyConfigFile(file, groups, EpisodeConfig::renamedOptions());
  }
  try {
    config.cloud.validate();
    config.episode.resolve();
    config.episode.validate();
    config.cloud.lidar_noise = config.episode.noise.resolved().lidar;
  } catch (const OptionError& e) {
    if (file.empty()) throw;
    throw OptionError(file.string() + ": " + e.what());
  }
  return config;
}

}  // namespace roomscout::sim
