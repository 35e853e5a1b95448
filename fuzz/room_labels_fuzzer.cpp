// Fuzz target: the room-label image of `--room-labels`, read by sim::loadImageWorld. The input
// is the label image; the harness writes a map_server map of the same size beside it (found
// by decoding the input first), so that the labels get past the size check. The only
// accepted failure is InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/image_world.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const std::filesystem::path& dir = fuzz::scratchDir();
  const std::string_view bytes = fuzz::asText(data, size);
  fuzz::writeFile(dir / "labels.png", bytes);
  // The map's size: the label image's own when it decodes, else 4 x 4.
  int cols = 4, rows = 4;
  if (size > 0) {
    try {
      const cv::Mat raw(1, static_cast<int>(size), CV_8U, const_cast<std::uint8_t*>(data));
      const cv::Mat decoded = cv::imdecode(raw, cv::IMREAD_UNCHANGED);
      // Larger maps only cost time: their labels are decoded the same way.
      if (!decoded.empty() && decoded.total() <= 4096 * 4096) {
        cols = decoded.cols;
        rows = decoded.rows;
      }
    } catch (const cv::Exception&) {
    }
  }
  std::string pgm = "P5\n" + std::to_string(cols) + " " + std::to_string(rows) + "\n255\n";
  pgm.append(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), '\xfe');
  fuzz::writeFile(dir / "map.pgm", pgm);
  fuzz::writeFile(dir / "map.yaml", "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  try {
    const sim::World world = sim::loadImageWorld(dir / "map.yaml", dir / "labels.png");
    (void)world;
  } catch (const InputError&) {
  }
  return 0;
}
