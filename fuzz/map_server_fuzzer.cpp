// Fuzz target: a map_server map (YAML + image) and its room-label image, as `--world MAP.yaml
// --room-labels LABELS.png` and `roomscout maps --map` read them. The input is the YAML text,
// then after a line "#IMAGE" the image bytes (written as map.pgm, which the seeds' YAML
// names), then optionally after a line "#LABELS" the label image bytes (labels.png).
// Loaded both as an occupancy grid and as a world; the only accepted failure is InputError.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/image_world.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const auto parts = fuzz::splitInput(fuzz::asText(data, size), "\n#IMAGE\n", 2);
  const auto images = fuzz::splitInput(parts.size() > 1 ? parts[1] : "", "\n#LABELS\n", 2);
  const std::filesystem::path& dir = fuzz::scratchDir();
  fuzz::writeFile(dir / "map.yaml", parts[0]);
  fuzz::writeFile(dir / "map.pgm", images[0]);
  std::optional<std::filesystem::path> labels;
  if (images.size() > 1) {
    labels = dir / "labels.png";
    fuzz::writeFile(*labels, images[1]);
  }
  try {
    const OccupancyGrid grid = io::loadOccupancyMap(dir / "map.yaml");
    (void)grid;
  } catch (const InputError&) {
  }
  try {
    const sim::World world = sim::loadImageWorld(dir / "map.yaml", labels);
    (void)world;
  } catch (const InputError&) {
  }
  return 0;
}
