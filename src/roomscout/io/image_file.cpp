#include "roomscout/io/detail/image_file.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"

namespace roomscout::io {
namespace {

std::uint32_t bigEndian32(std::string_view b, std::size_t at) {
  return (std::uint32_t{static_cast<unsigned char>(b[at])} << 24) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 1])} << 16) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 2])} << 8) |
         std::uint32_t{static_cast<unsigned char>(b[at + 3])};
}

std::uint32_t littleEndian32(std::string_view b, std::size_t at) {
  return (std::uint32_t{static_cast<unsigned char>(b[at + 3])} << 24) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 2])} << 16) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 1])} << 8) |
         std::uint32_t{static_cast<unsigned char>(b[at])};
}

cv::Size clampedSize(std::uint64_t width, std::uint64_t height) {
  // Anything above INT_MAX is as far beyond kMaxImagePixels as INT_MAX itself.
  constexpr std::uint64_t kCap = 0x7fffffff;
  return {static_cast<int>(std::min(width, kCap)), static_cast<int>(std::min(height, kCap))};
}

/// PNM: "P1".."P6", then width and height as decimal text, with comments (# to end of line).
std::optional<cv::Size> pnmSize(std::string_view b) {
  std::size_t at = 2;
  std::uint64_t values[2] = {0, 0};
  for (std::uint64_t& value : values) {
    while (at < b.size()) {
      if (std::isspace(static_cast<unsigned char>(b[at]))) {
        ++at;
      } else if (b[at] == '#') {
        while (at < b.size() && b[at] != '\n' && b[at] != '\r') ++at;
      } else {
        break;
      }
    }
    if (at >= b.size() || !std::isdigit(static_cast<unsigned char>(b[at]))) return std::nullopt;
    for (; at < b.size() && std::isdigit(static_cast<unsigned char>(b[at])); ++at) {
      value = std::min<std::uint64_t>(value * 10 + static_cast<std::uint64_t>(b[at] - '0'),
                                      std::uint64_t{1} << 40);
    }
  }
  return clampedSize(values[0], values[1]);
}

/// JPEG: the frame header (SOF0..SOF15 but DHT, JPG and DAC) holds height, then width.
std::optional<cv::Size> jpegSize(std::string_view b) {
  std::size_t at = 2;
  while (at + 4 <= b.size()) {
    if (static_cast<unsigned char>(b[at]) != 0xff) return std::nullopt;
    const unsigned char marker = static_cast<unsigned char>(b[at + 1]);
    if (marker == 0xff) {  // fill byte
      ++at;
      continue;
    }
    const std::size_t length = (std::size_t{static_cast<unsigned char>(b[at + 2])} << 8) |
                               static_cast<unsigned char>(b[at + 3]);
    if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc) {
      if (at + 9 > b.size()) return std::nullopt;
      const std::uint64_t height = (std::uint64_t{static_cast<unsigned char>(b[at + 5])} << 8) |
                                   static_cast<unsigned char>(b[at + 6]);
      const std::uint64_t width = (std::uint64_t{static_cast<unsigned char>(b[at + 7])} << 8) |
                                  static_cast<unsigned char>(b[at + 8]);
      return clampedSize(width, height);
    }
    if (length < 2) return std::nullopt;
    at += 2 + length;
  }
  return std::nullopt;
}

}  // namespace

std::optional<cv::Size> imageHeaderSize(std::string_view b) {
  if (b.size() >= 24 && b.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8) &&
      b.substr(12, 4) == "IHDR") {
    return clampedSize(bigEndian32(b, 16), bigEndian32(b, 20));
  }
  if (b.size() >= 3 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6') return pnmSize(b);
  if (b.size() >= 26 && b[0] == 'B' && b[1] == 'M') {
    // BITMAPINFOHEADER and later: signed 32-bit width and height (negative: top-down rows).
    const auto width = static_cast<std::int32_t>(littleEndian32(b, 18));
    const auto height = static_cast<std::int32_t>(littleEndian32(b, 22));
    const auto magnitude = [](std::int32_t v) {
      return v < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(static_cast<std::int64_t>(v))
                   : static_cast<std::uint64_t>(v);
    };
    return clampedSize(magnitude(width), magnitude(height));
  }
  if (b.size() >= 4 && static_cast<unsigned char>(b[0]) == 0xff &&
      static_cast<unsigned char>(b[1]) == 0xd8) {
    return jpegSize(b);
  }
  return std::nullopt;
}

cv::Mat readImageFile(const std::filesystem::path& path, int flags) {
  const std::string bytes = readFile(path);
  if (bytes.empty()) throw InputError(path.string(), "cannot decode image: the file is empty");
  if (const std::optional<cv::Size> size = imageHeaderSize(bytes)) {
    const auto pixels =
        static_cast<std::uint64_t>(size->width) * static_cast<std::uint64_t>(size->height);
    if (pixels == 0 || pixels > kMaxImagePixels) {
      throw InputError(path.string(), "image header gives " + std::to_string(size->width) + "x" +
                                          std::to_string(size->height) + " pixels (need 1 to " +
                                          std::to_string(kMaxImagePixels) + " pixels)");
    }
  }
  cv::Mat image;
  try {
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      throw InputError(path.string(), "image file too large (over 2 GB)");
    }
    const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8U, const_cast<char*>(bytes.data()));
    image = cv::imdecode(buffer, flags);
  } catch (const cv::Exception&) {
    image.release();
  }
  if (image.empty()) {
    throw InputError(path.string(), "cannot decode image (corrupt or unsupported format)");
  }
  if (image.total() > kMaxImagePixels) {
    throw InputError(path.string(), "image is " + std::to_string(image.cols) + "x" +
                                        std::to_string(image.rows) + " pixels (at most " +
                                        std::to_string(kMaxImagePixels) + " pixels)");
  }
  return image;
}

}  // namespace roomscout::io
