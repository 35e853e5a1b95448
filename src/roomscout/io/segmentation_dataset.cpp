#include "roomscout/io/segmentation_dataset.hpp"

#include <algorithm>

#include <opencv2/imgcodecs.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/io/detail/image_file.hpp"

namespace fs = std::filesystem;

namespace roomscout::io {

std::vector<SegmentationDatasetMap> listSegmentationDataset(const fs::path& directory) {
  if (!fs::is_directory(directory)) throw InputError(directory.string(), "not a directory");
  const std::string kGt = "_gt_segmentation", kFurnished = "_furnitures";
  std::vector<SegmentationDatasetMap> maps;
  for (const fs::directory_entry& e : fs::directory_iterator(directory)) {
    if (!e.is_regular_file() || e.path().extension() != ".png") continue;
    const std::string stem = e.path().stem().string();
    if (stem.ends_with(kGt) || stem.ends_with(kFurnished)) continue;
    const fs::path gt = directory / (stem + kGt + ".png");
    if (!fs::exists(gt)) continue;
    SegmentationDatasetMap m{stem, e.path(), std::nullopt, gt};
    const fs::path furnished = directory / (stem + kFurnished + ".png");
    if (fs::exists(furnished)) m.furnished_png = furnished;
    maps.push_back(std::move(m));
  }
  if (maps.empty()) {
    throw InputError(directory.string(),
                     "no benchmark maps (NAME.png with NAME_gt_segmentation.png beside it)");
  }
  std::sort(maps.begin(), maps.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return maps;
}

cv::Mat readGreyImage(const fs::path& png) {
  if (!fs::exists(png)) throw InputError(png.string(), "file not found");
  return readImageFile(png, cv::IMREAD_GRAYSCALE);
}

cv::Mat benchmarkStates(const cv::Mat& grey) {
  cv::Mat states(grey.size(), CV_8U, cv::Scalar(static_cast<int>(CellState::kOccupied)));
  states.setTo(static_cast<int>(CellState::kFree), grey >= 250);
  return states;
}

}  // namespace roomscout::io
