#include "roomscout/exploration/strategy_registry.hpp"

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/improved_rrt.hpp"
#include "roomscout/exploration/mmpf.hpp"
#include "roomscout/exploration/nearest_frontier.hpp"
#include "roomscout/exploration/rrt_exploration.hpp"

namespace roomscout {

const std::vector<StrategyEntry>& strategyRegistry() {
  static const std::vector<StrategyEntry> entries = {
      {"nearest_frontier",
       "explore_lite's greedy frontier exploration (cost = potential_scale*distance - "
       "gain_scale*size)",
       [](std::uint64_t /*seed*/) { return std::make_unique<NearestFrontier>(); }},
      {"rrt",
       "Umari & Mukhopadhyay's RRT exploration (global + local trees, mean-shift filter, "
       "revenue = 3*IG - distance)",
       [](std::uint64_t seed) { return std::make_unique<RrtExploration>(seed); }},
      {"improved_rrt",
       "SMMR-Explore's rrt node: one tree over the map box, score = 3*(unknown - occupied) - "
       "distance",
       [](std::uint64_t seed) { return std::make_unique<ImprovedRrt>(seed); }},
      {"mmpf",
       "SMMR-Explore's multi-target potential field: frontier clusters, BFS distances, "
       "gradient descent with a river term",
       [](std::uint64_t /*seed*/) { return std::make_unique<Mmpf>(); }},
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
