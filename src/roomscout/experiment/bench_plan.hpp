#pragma once
// The episode list of a bench: which worlds (built-in names, world or map_server files, or
// folders of them), the (world, method, seed) product in a fixed order, and shards of it.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "roomscout/experiment/episode_key.hpp"

namespace roomscout::experiment {

/// One world of a bench, as named in results and directories.
struct BenchWorld {
  std::string name;   ///< a built-in name, or the file's stem (unique within a bench)
  std::string spec;   ///< what sim::loadWorld takes: the built-in name or the file path
  std::string group;  ///< "builtin", or the name of the folder holding the file (reports
                      ///< summarise a group such as "houseexpo" in one row)
};

/// Expands --worlds items in order: a built-in name; a world or map_server YAML file; a folder,
/// which stands for its *.yaml files sorted by name. Only names and paths are checked here
/// (worlds are loaded when they run). Throws InputError naming an item that is neither a
/// built-in name nor an existing file or folder, or a folder with no .yaml file, and
/// OptionError when two worlds share a name.
std::vector<BenchWorld> expandWorlds(const std::vector<std::string>& items);

/// The I-th of N slices of an episode list (1-based I).
struct Shard {
  int index = 1;
  int count = 1;
  /// True when the episode at `position` of the sorted list belongs to this shard: the
  /// slices are position % count == index - 1, so together they hold every episode once.
  bool holds(std::size_t position) const {
    return position % static_cast<std::size_t>(count) == static_cast<std::size_t>(index - 1);
  }
};

/// Parses "I/N" (1 <= I <= N). Throws OptionError naming --shard otherwise.
Shard parseShard(std::string_view text);

/// The seeds first..last of every world x method.
struct SeedRange {
  int first = 1;
  int last = 1;
};

/// Parses "N" (seeds 1..N) or "A-B" (seeds A..B, 1 <= A <= B). Throws OptionError naming
/// --seeds otherwise.
SeedRange parseSeeds(std::string_view text);

/// Every (world, method, seed) with the seeds of `seeds`, sorted by world name, method name,
/// seed, then only the episodes that `shard` holds. Worlds and methods are deduplicated. Throws
/// OptionError when the range is empty or starts below 1, or a list is empty.
std::vector<EpisodeKey> planEpisodes(const std::vector<std::string>& worlds,
                                     const std::vector<std::string>& methods,
                                     const SeedRange& seeds, const Shard& shard = {});

/// Splits a comma-separated list, trimming blanks and dropping empty items.
std::vector<std::string> splitList(std::string_view text);

}  // namespace roomscout::experiment
