#pragma once
// A ROS map_server map (a YAML file next to a PGM/PNG image) read as a simulator world.

#include <filesystem>
#include <optional>

#include "roomscout/sim/world.hpp"

namespace roomscout::sim {

/// Loads a map_server map as a simulator world: ImageWorld.solid is 255 wherever the map is
/// not free (io::classifyMapImage). The world's name is the YAML's stem, its source the YAML's
/// path; no start pose. `room_labels_png`, when given, labels rooms (io::readRoomLabelImage).
/// Throws InputError naming the file for what io::loadMapServerYaml, io::readMapImage and
/// io::readRoomLabelImage refuse, and for a map with no free pixel.
World loadImageWorld(const std::filesystem::path& yaml_path,
                     const std::optional<std::filesystem::path>& room_labels_png);

}  // namespace roomscout::sim
