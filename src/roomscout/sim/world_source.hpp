#pragma once
// Resolves what a user passes as --world: a built-in name, a world file or a map_server map.

#include <filesystem>
#include <optional>
#include <string>

#include "roomscout/sim/world.hpp"

namespace roomscout::sim {

/// Loads a world from `spec`: the name of a built-in world, a world YAML file
/// (docs/world_format.md), or a map_server YAML (recognised by its `image` key), the last with
/// an optional room-label image. Throws InputError naming `spec` when it is none of these.
sim::World loadWorld(const std::string& spec,
                     const std::optional<std::filesystem::path>& room_labels_png = std::nullopt);

}  // namespace roomscout::sim
