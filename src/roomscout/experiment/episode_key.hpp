#pragma once
// What identifies one bench episode: world, method and seed. Records with the same key are
// the same experiment (a resumed bench skips them; a report keeps one of them).

#include <compare>
#include <cstdint>
#include <string>

namespace roomscout::experiment {

struct EpisodeKey {
  std::string world;   ///< world name: a built-in name or a world file's stem
  std::string method;  ///< registered strategy name
  std::uint64_t seed = 0;
  auto operator<=>(const EpisodeKey&) const = default;
  /// "world/method/seed N", for messages.
  std::string text() const { return world + "/" + method + "/seed " + std::to_string(seed); }
};

}  // namespace roomscout::experiment
