// Image files a user supplies: header sizes, and inputs that crashed the fuzz targets kept as
// regressions (a header announcing a huge image must be an InputError naming the file, before
// any pixel memory is allocated and without OpenCV's own exceptions escaping).
#include "roomscout/io/detail/image_file.hpp"

#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/io/segmentation_dataset.hpp"
#include "roomscout/sim/image_world.hpp"

namespace roomscout::io {
namespace {

using test::Contains;
using test::TempDir;

std::string inputErrorOf(const auto& fn) { return test::messageOf<InputError>(fn); }

std::string encoded(const cv::Mat& image, const std::string& extension) {
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(extension, image, bytes));
  return {bytes.begin(), bytes.end()};
}

TEST(ImageHeaderSize, ReadsPngPnmBmpAndJpegHeaders) {
  const cv::Mat image(7, 13, CV_8UC3, cv::Scalar(10, 200, 30));
  for (const char* extension : {".png", ".pgm", ".ppm", ".bmp", ".jpg"}) {
    const cv::Mat written =
        std::string(extension) == ".pgm" ? cv::Mat(7, 13, CV_8UC1, cv::Scalar(200)) : image;
    const std::optional<cv::Size> size = imageHeaderSize(encoded(written, extension));
    ASSERT_TRUE(size.has_value()) << extension;
    EXPECT_EQ(*size, cv::Size(13, 7)) << extension;
  }
  EXPECT_EQ(imageHeaderSize("P2\n# a comment\n 4 # another\n3\n255\n"), cv::Size(4, 3));
  EXPECT_FALSE(imageHeaderSize("P5\n12").has_value());
  EXPECT_FALSE(imageHeaderSize("GIF89a").has_value());
  EXPECT_FALSE(imageHeaderSize("").has_value());
}

TEST(ReadImageFile, DecodesAndNamesTheFileOnEveryError) {
  const TempDir dir;
  const auto png = dir.write("ok.png", encoded(cv::Mat(3, 5, CV_8UC1, cv::Scalar(9)), ".png"));
  const cv::Mat image = readImageFile(png, cv::IMREAD_UNCHANGED);
  EXPECT_EQ(image.size(), cv::Size(5, 3));
  EXPECT_TRUE(Contains(inputErrorOf([&] { readImageFile(dir / "none.png", 0); }),
                       (dir / "none.png").string() + ": file not found"));
  const auto empty = dir.write("empty.png", "");
  EXPECT_TRUE(Contains(inputErrorOf([&] { readImageFile(empty, 0); }),
                       empty.string() + ": cannot decode image"));
  const auto zero = dir.write("zero.pgm", "P5\n0 4\n255\n");
  EXPECT_TRUE(Contains(inputErrorOf([&] { readImageFile(zero, 0); }),
                       zero.string() + ": image header gives 0x4 pixels"));
}

// Crashed the segmentation_gt fuzz target: a PGM header wider than OpenCV's limit of 2^20 columns
// made cv::imread throw cv::Exception out of readGreyImage, terminating `segment-eval`.
TEST(FuzzRegression, ReadGreyImageOfAPgmTooWideForOpenCv) {
  const TempDir dir;
  const auto pgm = dir.write("wide_gt_segmentation.png", "P5\n2000000 1\n255\nabc");
  EXPECT_TRUE(Contains(inputErrorOf([&] { readGreyImage(pgm); }),
                       pgm.string() + ": cannot decode image (corrupt or unsupported format)"));
}

// Crashed the map_server fuzz target (out of memory): a 16-bit PGM header of 30000 x 30000 pixels
// made OpenCV allocate 1.8 GB before finding that the pixels are missing (and a grey read of it
// took seconds).
TEST(FuzzRegression, MapImageHeaderOfAHugeImageIsRejectedBeforeDecoding) {
  const TempDir dir;
  const auto image = dir.write("map.pgm", "P5\n30000 30000\n65535\nabc");
  const auto yaml = dir.write("map.yaml", "image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  // The map loaders refuse it as a grid too large (grid_limits.hpp), naming the map's YAML.
  const std::string too_large = yaml.string() + ": map is 30000 x 30000 cells";
  EXPECT_TRUE(Contains(inputErrorOf([&] { loadOccupancyMap(yaml); }), too_large));
  EXPECT_TRUE(Contains(inputErrorOf([&] { sim::loadImageWorld(yaml, std::nullopt); }), too_large));
  const std::string expected = image.string() + ": image header gives 30000x30000 pixels";
  EXPECT_TRUE(Contains(inputErrorOf([&] { readGreyImage(image); }), expected));
  // The same header as a room label image of a valid map.
  dir.write("small.pgm", "P5\n2 2\n255\n\xfe\xfe\xfe\xfe");
  const auto small =
      dir.write("small.yaml", "image: small.pgm\nresolution: 0.05\norigin: [0, 0]\n");
  EXPECT_TRUE(Contains(inputErrorOf([&] { sim::loadImageWorld(small, image); }),
                       image.string() + ": room label image is 30000x30000 pixels"));
}

}  // namespace
}  // namespace roomscout::io
