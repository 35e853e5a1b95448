#pragma once
// The room segmentation benchmark of Bormann et al. (ICRA 2016) as laid out in
// ../shared/data/room_segmentation/: NAME.png, NAME_furnitures.png, NAME_gt_segmentation.png.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace roomscout::io {

/// One map of the benchmark. `furnished_png` may be absent.
struct SegmentationDatasetMap {
  std::string name;
  std::filesystem::path plain_png;
  std::optional<std::filesystem::path> furnished_png;
  std::filesystem::path ground_truth_png;
};

/// The maps of a benchmark folder, sorted by name: every NAME.png that has a
/// NAME_gt_segmentation.png beside it. Throws InputError when the folder does not exist or
/// holds no such map.
std::vector<SegmentationDatasetMap> listSegmentationDataset(const std::filesystem::path& directory);

/// A benchmark image as greyscale (CV_8U, row 0 at the top; colour channels averaged as
/// cv::imread's greyscale mode does). Throws InputError when it cannot be read.
cv::Mat readGreyImage(const std::filesystem::path& png);

/// The benchmark's binarisation as CellState values (CV_8U): grey >= 250 free, else occupied.
cv::Mat benchmarkStates(const cv::Mat& grey);

}  // namespace roomscout::io
