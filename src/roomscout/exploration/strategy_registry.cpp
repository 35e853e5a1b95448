#include "roomscout/exploration/strategy_registry.hpp"

#include "roomscout/core/errors.hpp"
#include "roomscout/exploration/detail/improved_rrt.hpp"
#include "roomscout/exploration/detail/mmpf.hpp"
#include "roomscout/exploration/detail/nearest_frontier.hpp"
#include "roomscout/exploration/detail/rrt_exploration.hpp"
#include "roomscout/exploration/detail/semantic_explorer.hpp"
#include "roomscout/exploration/detail/topo_exploration.hpp"

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
      {"topo",
       "MR-TopoMap's topological exploration: a vertex every 2.5 m, frontier directions of a 12 m "
       "window, farthest from the centre of the map first, backtracking to the nearest vertex",
       [](std::uint64_t /*seed*/) { return std::make_unique<TopoExploration>(); }},
      {"semantic",
       "the paper's semantic-region-aware RRT exploration (samples drawn from the current room's "
       "frontier with probability kt/(1+kt), score = w_g*G - w_c*C +/- A) plus our additions: "
       "geodesic C, slivers, label search, hubs, next-room cost and frontier mass, heading and "
       "segment terms, leaf rooms, end phase (docs/semantic_method.md)",
       [](std::uint64_t seed) { return std::make_unique<SemanticExplorer>(seed); }},
      {"semantic_paper",
       "the paper's method as the paper states it: samples drawn from the current room's frontier "
       "with probability kt/(1+kt), else uniform over the known box; score = w_g*G - w_c*C +/- A "
       "with Euclidean C; improved_rrt's tree; none of semantic's additions",
       [](std::uint64_t seed) {
         return std::make_unique<SemanticExplorer>(seed, SemanticExplorerOptions::paper(),
                                                   "semantic_paper");
       }},
      {"semantic_sampling_only",
       "ablation of semantic_paper: room-biased sampling, plain score (A = 0)",
       [](std::uint64_t seed) {
         SemanticExplorerOptions o = SemanticExplorerOptions::paper();
         o.score.room_reward = 0.0;
         return std::make_unique<SemanticExplorer>(seed, o, "semantic_sampling_only");
       }},
      {"semantic_score_only",
       "ablation of semantic_paper: uniform sampling (k = 0), room-aware score",
       [](std::uint64_t seed) {
         SemanticExplorerOptions o = SemanticExplorerOptions::paper();
         o.tree.k = 0.0;
         return std::make_unique<SemanticExplorer>(seed, o, "semantic_score_only");
       }},
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
