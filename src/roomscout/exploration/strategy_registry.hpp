#pragma once
// Strategies chosen by name: an explicit list of every strategy the library knows.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "roomscout/exploration/exploration_strategy.hpp"

namespace roomscout {

/// One registered strategy: its name, a one-line description and a factory taking the seed.
struct StrategyEntry {
  std::string name;
  std::string description;
  std::function<std::unique_ptr<ExplorationStrategy>(std::uint64_t seed)> create;
};

/// Every known strategy, in a fixed order.
const std::vector<StrategyEntry>& strategyRegistry();

/// Names of every registered strategy.
std::vector<std::string> strategyNames();

/// Creates the strategy called `name` with default options; throws OptionError listing the
/// known names when there is none.
std::unique_ptr<ExplorationStrategy> createStrategy(std::string_view name, std::uint64_t seed);

}  // namespace roomscout
