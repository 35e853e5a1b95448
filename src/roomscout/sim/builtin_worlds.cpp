#include "roomscout/sim/builtin_worlds.hpp"

#include "roomscout/core/errors.hpp"
#include "roomscout/io/yaml_support.hpp"
#include "roomscout/sim/world_file.hpp"

namespace roomscout::sim {

using io::joinNames;

std::vector<std::string> builtinWorldNames() {
  std::vector<std::string> names;
  for (const EmbeddedWorld& world : embeddedWorlds()) names.emplace_back(world.name);
  return names;
}

bool isBuiltinWorld(std::string_view name) {
  for (const EmbeddedWorld& world : embeddedWorlds()) {
    if (name == world.name) return true;
  }
  return false;
}

sim::World loadBuiltinWorld(std::string_view name) {
  const std::string source = "builtin:" + std::string(name);
  for (const EmbeddedWorld& world : embeddedWorlds()) {
    if (name == world.name) return parseWorldYaml(world.yaml, source);
  }
  throw InputError(source,
                   "no such built-in world (known: " + joinNames(builtinWorldNames()) + ")");
}

}  // namespace roomscout::sim
