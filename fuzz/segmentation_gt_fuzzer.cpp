// Fuzz target: an image of the room segmentation benchmark as `roomscout segment-eval` reads
// it (io::readGreyImage), binarised as a map (io::benchmarkStates) and as ground-truth rooms
// (groundTruthRooms), then scored against itself. The only accepted failure is InputError.
#include <cstddef>
#include <cstdint>

#include <opencv2/core.hpp>

#include "fuzz_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/maps/segmentation_score.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roomscout;
  const std::filesystem::path path = fuzz::scratchDir() / "map_gt_segmentation.png";
  fuzz::writeFile(path, fuzz::asText(data, size));
  try {
    const cv::Mat grey = io::readGreyImage(path);
    const cv::Mat states = io::benchmarkStates(grey);
    const cv::Mat rooms = groundTruthRooms(grey);
    const SegmentationScore score = scoreSegmentation(rooms, rooms);
    (void)states;
    (void)score;
  } catch (const InputError&) {
  }
  return 0;
}
