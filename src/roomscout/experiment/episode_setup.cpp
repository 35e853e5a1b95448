#include "roomscout/experiment/episode_setup.hpp"

#include <vector>

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/strategy_registry.hpp"
#include "roomscout/io/options_yaml.hpp"

namespace roomscout::experiment {

void RunSettings::validate() const {
  if (!(pcd_precision_m >= 0.0)) throw OptionError("--pcd-precision must be >= 0");
}

nlohmann::json EpisodeSetup::optionsJson() {
  nlohmann::json options = nlohmann::json::object();
  for (const ParameterGroup& g : config.groups())
    options[g.name] = io::parametersToJson(g.parameters);
  options[method] = io::parametersToJson(strategy->parameters());
  for (const ParameterGroup& g : cloud.groups())
    options[g.name] = io::parametersToJson(g.parameters);
  return options;
}

std::vector<ParameterGroup> configGroups(
    EpisodeSetup& setup, std::vector<std::unique_ptr<ExplorationStrategy>>& others) {
  std::vector<ParameterGroup> groups = setup.config.groups();
  for (ParameterGroup& g : setup.cloud.groups()) groups.push_back(std::move(g));
  // Every method has a group of its own, so that one config file serves all methods.
  for (const StrategyEntry& e : strategyRegistry()) {
    if (e.name == setup.method) {
      groups.push_back({e.name, setup.strategy->parameters()});
    } else {
      others.push_back(e.create(setup.seed));
      groups.push_back({e.name, others.back()->parameters()});
    }
  }
  return groups;
}

EpisodeSetup makeEpisodeSetup(std::string_view method, std::uint64_t seed,
                              const RunSettings& settings) {
  EpisodeSetup setup;
  setup.method = std::string(method);
  setup.seed = seed;
  setup.strategy = createStrategy(method, seed);
  std::vector<std::unique_ptr<ExplorationStrategy>> others;
  std::vector<ParameterGroup> groups = configGroups(setup, others);
  if (!settings.config_file.empty()) {
    setup.warnings =
        io::applyConfigFile(settings.config_file, groups, sim::EpisodeConfig::renamedOptions());
  }
  if (settings.max_time_s) setup.config.episode.max_time_s = *settings.max_time_s;
  if (settings.remove_floor) setup.cloud.remove_floor_ceiling = true;
  try {
    setup.cloud.validate();
    setup.config.resolve();
    setup.config.validate();
    setup.strategy->validateOptions();
    setup.cloud.lidar_noise = setup.config.noise.resolved().lidar;
  } catch (const OptionError& e) {
    // A value out of range came from the config file unless the command line set it.
    if (settings.config_file.empty()) throw;
    throw OptionError(settings.config_file.string() + ": " + e.what());
  }
  return setup;
}

}  // namespace roomscout::experiment
