#include "roomscout/exploration/strategy_registry.hpp"

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/nearest_frontier.hpp"

namespace roomscout {

const std::vector<StrategyEntry>& strategyRegistry() {
  static const std::vector<StrategyEntry> entries = {
      {"nearest_frontier",
       "explore_lite's greedy frontier exploration (cost = potential_scale*distance - "
       "gain_scale*size)",
       [](std::uint64_t /*seed*/) { return std::make_unique<NearestFrontier>(); }},
  };
  return entries;
}

std::vector<std::string> strategyNames() {
  std::vector<std::string> names;
  for (const StrategyEntry& e : strategyRegistry()) names.push_back(e.name);
  return names;
}

std::unique_ptr<ExplorationStrategy> createStrategy(std::string_view name, std::uint64_t seed) {
  for (const StrategyEntry& e : strategyRegistry()) {
    if (e.name == name) return e.create(seed);
  }
  std::string known;
  for (const std::string& n : strategyNames()) known += (known.empty() ? "" : ", ") + n;
  throw OptionError("unknown method '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace roomscout
