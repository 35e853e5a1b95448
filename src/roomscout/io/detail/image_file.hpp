#pragma once
// Decoding of image files a user supplies (map_server maps, room labels, the segmentation
// benchmark): the size in the header is checked before anything is allocated for the pixels.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string_view>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/grid_limits.hpp"

namespace roomscout::io {

/// Largest image the readers decode: the largest grid roomscout builds (kMaxGridCells).
inline constexpr std::size_t kMaxImagePixels = kMaxGridCells;

/// Width and height stored in the header of a PNG, PNM (PBM/PGM/PPM), BMP or JPEG file;
/// nullopt for other formats and for headers too short or malformed to hold them.
std::optional<cv::Size> imageHeaderSize(std::string_view bytes);

/// Reads and decodes an image file with cv::imdecode `flags` (cv::IMREAD_UNCHANGED,
/// cv::IMREAD_GRAYSCALE, ...). Throws InputError(path, problem) when the file is missing or
/// unreadable, when its header gives a size of zero or more than kMaxImagePixels pixels, or
/// when it does not decode (corrupt or unsupported format).
cv::Mat readImageFile(const std::filesystem::path& path, int flags);

}  // namespace roomscout::io
