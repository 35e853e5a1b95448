#include "roomscout/experiment/oracle_references.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>
#include <variant>

#include <nlohmann/json.hpp>

#include "roomscout/experiment/oracle_tour.hpp"
#include "roomscout/sim/episode.hpp"
#include "roomscout/sim/world_model.hpp"
#include "roomscout/sim/world_source.hpp"

namespace roomscout::experiment {
namespace {

/// Sets the parameters of `groups` that `options` ({group: {name: value}}) holds with a value
/// of the parameter's type; anything else keeps its default.
void applyOptions(std::vector<ParameterGroup> groups, const nlohmann::json& options) {
  for (ParameterGroup& g : groups) {
    if (!options.contains(g.name) || !options[g.name].is_object()) continue;
    const nlohmann::json& values = options[g.name];
    for (ParameterRef& p : g.parameters) {
      const std::string name(p.name);
      if (!values.contains(name)) continue;
      const nlohmann::json& v = values[name];
      std::visit(
          [&](auto* target) {
            using T = std::remove_pointer_t<decltype(target)>;
            if constexpr (std::is_same_v<T, bool>) {
              if (v.is_boolean()) *target = v.get<bool>();
            } else if constexpr (std::is_same_v<T, std::string>) {
              if (v.is_string()) *target = v.get<std::string>();
            } else if constexpr (std::is_same_v<T, int>) {
              if (v.is_number_integer()) *target = v.get<int>();
            } else {
              if (v.is_number()) *target = v.get<double>();
            }
          },
          p.value);
    }
  }
}

OracleReference planFor(const std::string& spec, const std::string& setup) {
  sim::EpisodeConfig config;
  if (!setup.empty()) applyOptions(config.groups(), nlohmann::json::parse(setup));
  config.resolve();
  config.validate();
  sim::World world = sim::loadWorld(spec);
  if (!setup.empty()) {
    // A bench with random starts records each episode's start (see readWorldAndOptions).
    const nlohmann::json parsed = nlohmann::json::parse(setup);
    if (parsed.contains("start")) {
      const nlohmann::json& start = parsed["start"];
      world.start = Pose2{start[0].get<double>(), start[1].get<double>(), start[2].get<double>()};
      world.start_given = true;
    }
  }
  const sim::WorldModel model(world, config.world);
  const experiment::OracleTour tour =
      experiment::planOracleTour(model, experiment::oracleTourOptionsFor(config));
  return {tour.length_m, tour.coverage, tour.viewpointCount()};
}

}  // namespace

OracleSummary attachOracleTours(ResultSet& results, const OracleSettings& settings) {
  using Key = std::pair<std::string, std::string>;  // (world_spec, world_setup)
  std::map<Key, std::size_t> index;
  std::vector<Key> keys;
  for (const EpisodeSummary& e : results.episodes) {
    if (e.world_spec.empty()) continue;
    const Key key{e.world_spec, e.world_setup};
    if (index.emplace(key, keys.size()).second) keys.push_back(key);
  }
  struct Outcome {
    std::optional<OracleReference> oracle;
    std::string error;
  };
  std::vector<Outcome> outcomes(keys.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&]() {
    for (std::size_t i = next.fetch_add(1); i < keys.size(); i = next.fetch_add(1)) {
      try {
        outcomes[i].oracle = planFor(keys[i].first, keys[i].second);
      } catch (const std::exception& e) {
        outcomes[i].error = e.what();
      }
    }
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads =
      std::min<std::size_t>(settings.threads ? settings.threads : cores, keys.size());
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
  }

  OracleSummary summary;
  summary.planned = keys.size();
  std::map<std::string, std::string> failed;  // world spec -> first error
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!outcomes[i].oracle) failed.emplace(keys[i].first, outcomes[i].error);
  }
  for (const auto& [spec, error] : failed) {
    summary.notes.push_back("oracle: no reference tour for world '" + spec + "': " + error);
  }
  for (EpisodeSummary& e : results.episodes) {
    if (e.world_spec.empty()) continue;
    e.oracle = outcomes[index.at({e.world_spec, e.world_setup})].oracle;
  }
  return summary;
}

}  // namespace roomscout::experiment
