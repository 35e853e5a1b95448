// Fuzz target: a world YAML file as `--world FILE` reads it (sim::loadWorld: map_server
// detection, then the world-file parser). The only accepted failure is InputError.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/sim/world_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const std::filesystem::path path = fuzz::scratchDir() / "world.yaml";
  fuzz::writeFile(path, fuzz::asText(data, size));
  try {
    const sim::World world = sim::loadWorld(path.string());
    (void)world;
  } catch (const InputError&) {
  }
  return 0;
}
