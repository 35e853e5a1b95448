// Maps larger than kMaxGridCells are refused before they are loaded, with an error naming
// the file, the size and the limit; a map at the limit loads.

#include <cstdint>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/core/grid_limits.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/image_world.hpp"

namespace roomscout::io {
namespace {

using test::Contains;
using test::TempDir;

std::string inputErrorOf(const auto& fn) { return test::messageOf<InputError>(fn); }

std::filesystem::path writeYaml(const TempDir& dir, const std::string& image,
                                const std::string& resolution = "0.05") {
  return dir.write("big.yaml",
                   "image: " + image + "\nresolution: " + resolution + "\norigin: [0, 0, 0]\n");
}

/// A binary PGM header claiming `width` x `height` pixels, followed by one row of data only:
/// a loader that trusted it would allocate the whole image.
void writePgmHeader(const TempDir& dir, const std::string& name, int width, int height) {
  dir.write(name, "P5\n# made by a test\n" + std::to_string(width) + " " + std::to_string(height) +
                      "\n255\n" + std::string(static_cast<std::size_t>(width), '\xfe'));
}

/// The signature and IHDR chunk of a PNG of `width` x `height` 8-bit grey pixels, no data.
void writePngHeader(const TempDir& dir, const std::string& name, std::uint32_t width,
                    std::uint32_t height) {
  std::string png("\x89PNG\r\n\x1a\n", 8);
  png += std::string("\0\0\0\x0dIHDR", 8);
  for (const std::uint32_t v : {width, height}) {
    for (int shift = 24; shift >= 0; shift -= 8) png += static_cast<char>((v >> shift) & 0xff);
  }
  png += std::string("\x08\x00\x00\x00\x00", 5);  // depth 8, grey, no interlace
  png += std::string("\0\0\0\0", 4);              // CRC (not checked before the size)
  dir.write(name, png);
}

TEST(MapSizeLimit, PgmHeaderOfAHugeMapIsRefusedBeforeLoading) {
  const TempDir dir;
  writePgmHeader(dir, "big.pgm", 10000, 10000);
  const auto yaml = writeYaml(dir, "big.pgm");
  const std::string expected =
      yaml.string() +
      ": map is 10000 x 10000 cells (100000000) at 0.05 m; roomscout handles at most 25000000 "
      "cells (about 62500 m^2 at this resolution)";
  EXPECT_EQ(inputErrorOf([&] { (void)loadOccupancyMap(yaml); }), expected);
  EXPECT_EQ(inputErrorOf([&] { (void)sim::loadImageWorld(yaml, std::nullopt); }), expected);
}

TEST(MapSizeLimit, PngHeaderOfAHugeMapIsRefusedBeforeLoading) {
  const TempDir dir;
  writePngHeader(dir, "big.png", 60000, 50000);
  const auto yaml = writeYaml(dir, "big.png", "0.1");
  EXPECT_TRUE(Contains(inputErrorOf([&] { (void)loadOccupancyMap(yaml); }),
                       yaml.string() + ": map is 60000 x 50000 cells (3000000000) at 0.1 m; "
                                       "roomscout handles at most 25000000 cells (about 250000 "
                                       "m^2 at this resolution)"));
}

TEST(MapSizeLimit, OneRowOverTheLimitIsRefusedAndTheLimitItselfLoads) {
  const int side = 5000;
  ASSERT_EQ(std::int64_t{side} * side, kMaxGridCells);  // the limit this test is sized for
  const TempDir dir;
  writePgmHeader(dir, "over.pgm", side, side + 1);
  EXPECT_TRUE(Contains(inputErrorOf([&] { (void)loadOccupancyMap(writeYaml(dir, "over.pgm")); }),
                       "map is 5000 x 5001 cells (25005000)"));

  // A whole map of exactly kMaxGridCells: free between two walls.
  cv::Mat image(side, side, CV_8U, cv::Scalar(254));
  image.rowRange(0, 2).setTo(0);  // a wall along the top and the bottom
  image.rowRange(side - 2, side).setTo(0);
  ASSERT_TRUE(cv::imwrite((dir / "limit.pgm").string(), image));
  const OccupancyGrid grid = loadOccupancyMap(writeYaml(dir, "limit.pgm"));
  EXPECT_EQ(grid.geometry().cellCount(), static_cast<std::size_t>(kMaxGridCells));
  EXPECT_EQ(grid.state(Cell{side / 2, side / 2}), CellState::kFree);
  EXPECT_EQ(grid.state(Cell{0, 0}), CellState::kOccupied);
}

TEST(MapSizeLimit, ImagesWithoutAReadableHeaderAreCheckedAfterDecoding) {
  // A small BMP (no header parsing for it) loads; the decoded size is checked as well.
  const TempDir dir;
  cv::Mat image(20, 30, CV_8U, cv::Scalar(254));
  ASSERT_TRUE(cv::imwrite((dir / "small.bmp").string(), image));
  const OccupancyGrid grid = loadOccupancyMap(writeYaml(dir, "small.bmp"));
  EXPECT_EQ(grid.geometry().width(), 30);
  EXPECT_EQ(grid.geometry().height(), 20);
}

TEST(MapSizeLimit, RoomLabelsOfAnotherSizeAreRefusedFromTheirHeader) {
  const TempDir dir;
  cv::Mat image(20, 30, CV_8U, cv::Scalar(254));
  ASSERT_TRUE(cv::imwrite((dir / "map.pgm").string(), image));
  writePngHeader(dir, "labels.png", 40000, 40000);
  EXPECT_TRUE(Contains(inputErrorOf([&] {
                         (void)sim::loadImageWorld(writeYaml(dir, "map.pgm"), dir / "labels.png");
                       }),
                       "room label image is 40000x40000 pixels but the map image is 30x20"));
}

TEST(CheckGridSize, NamesTheSettingAndSurvivesAbsurdSizes) {
  EXPECT_NO_THROW(checkGridSize("w.yaml", "map", 5000, 5000, 0.05));
  const std::string message = test::messageOf<InputError>(
      [] { checkGridSize("w.yaml", "explored map", 2e6, 2e6, 0.05, "mapping.resolution_m"); });
  EXPECT_EQ(message,
            "w.yaml: explored map is 2000000 x 2000000 cells (4000000000000) at 0.05 m "
            "(mapping.resolution_m); roomscout handles at most 25000000 cells (about 62500 m^2 at "
            "this resolution)");
  EXPECT_THROW(checkGridSize("w.yaml", "map", 1e300, 1e300, 1e-300), InputError);
}

}  // namespace
}  // namespace roomscout::io
