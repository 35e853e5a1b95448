#include "roomscout/sim/world_source.hpp"

#include <yaml-cpp/yaml.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/builtin_worlds.hpp"
#include "roomscout/sim/image_world.hpp"
#include "roomscout/sim/world_file.hpp"

namespace roomscout::sim {

using io::readFile;

sim::World loadWorld(const std::string& spec,
                     const std::optional<std::filesystem::path>& room_labels_png) {
  if (isBuiltinWorld(spec)) {
    if (room_labels_png) throw InputError(spec, "--room-labels applies only to map_server worlds");
    return loadBuiltinWorld(spec);
  }
  const std::filesystem::path path(spec);
  if (!std::filesystem::exists(path)) {
    std::string known;
    for (const std::string& n : builtinWorldNames()) known += (known.empty() ? "" : ", ") + n;
    throw InputError(spec, "no such file, and not a built-in world (built-in: " + known + ")");
  }
  const std::string text = readFile(path);
  bool is_map_server = false;
  try {
    const YAML::Node root = YAML::Load(text);
    is_map_server = root.IsMap() && root["image"] && !root["walls"];
  } catch (const YAML::Exception&) {
    // Not YAML at all: let the world-file reader report the syntax error with its line.
  }
  if (is_map_server) return sim::loadImageWorld(path, room_labels_png);
  if (room_labels_png) throw InputError(spec, "--room-labels applies only to map_server worlds");
  return parseWorldYaml(text, path.string());
}

}  // namespace roomscout::sim
