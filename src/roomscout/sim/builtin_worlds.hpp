#pragma once
// Worlds compiled into the library from worlds/*.yaml, so the tools run from any directory.

#include <string>
#include <string_view>
#include <vector>

#include "roomscout/sim/world.hpp"

namespace roomscout::sim {

/// One embedded world file: its stem and its YAML text.
struct EmbeddedWorld {
  const char* name;
  const char* yaml;
};

/// Every embedded world, sorted by name. Defined in the build's generated
/// builtin_worlds_data.cpp (cmake/embed_worlds.cmake).
const std::vector<EmbeddedWorld>& embeddedWorlds();

/// Names of the built-in worlds, sorted.
std::vector<std::string> builtinWorldNames();

/// True when `name` is a built-in world.
bool isBuiltinWorld(std::string_view name);

/// Parses a built-in world; its source is "builtin:NAME". Throws InputError listing the known
/// names when `name` is not built in.
sim::World loadBuiltinWorld(std::string_view name);

}  // namespace roomscout::sim
