#include "roomscout/io/map_server.hpp"
#include "roomscout/sim/image_world.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "../support/temp_dir.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"

namespace roomscout::io {
namespace {

using test::Contains;
using test::Names;
using test::TempDir;

constexpr CellState kFree = CellState::kFree;
constexpr CellState kOcc = CellState::kOccupied;
constexpr CellState kUnk = CellState::kUnknown;

const std::string kYamlHead = "resolution: 0.1\norigin: [-1.0, 2.0, 0.0]\n";

/// Writes `image` as `image_name` and a map YAML `map.yaml` pointing at it.
std::filesystem::path writeMap(const TempDir& dir, const cv::Mat& image,
                               const std::string& extra_yaml = "",
                               const std::string& image_name = "map.png") {
  EXPECT_TRUE(cv::imwrite((dir / image_name).string(), image));
  return dir.write("map.yaml", "image: " + image_name + "\n" + kYamlHead + extra_yaml);
}

cv::Mat greyRow(std::vector<std::uint8_t> values) {
  cv::Mat image(1, static_cast<int>(values.size()), CV_8UC1);
  for (std::size_t i = 0; i < values.size(); ++i) image.at<std::uint8_t>(0, i) = values[i];
  return image;
}

/// States of a one-row map, left to right.
std::vector<CellState> rowStates(const OccupancyGrid& grid) {
  std::vector<CellState> out;
  for (int x = 0; x < grid.geometry().width(); ++x) out.push_back(grid.state(Cell{x, 0}));
  return out;
}

std::string inputErrorOf(const auto& fn) { return test::messageOf<InputError>(fn); }

TEST(LoadOccupancyMap, ClassifiesWithDefaultThresholds) {
  const TempDir dir;
  const auto yaml = writeMap(dir, greyRow({0, 100, 254, 205, 255, 51, 50}));
  const OccupancyGrid grid = loadOccupancyMap(yaml);
  // p = (255 - v) / 255: 0 -> 1.0, 100 -> 0.61, 254 -> 0.004, 205 -> 0.196078 (not < 0.196),
  // 51 -> 0.8; v = 50 gives 0.804 as well: all above 0.65.
  EXPECT_EQ(rowStates(grid), (std::vector<CellState>{kOcc, kUnk, kFree, kUnk, kFree, kOcc, kOcc}));
  EXPECT_EQ(grid.geometry(), GridGeometry(Vec2(-1.0, 2.0), 0.1, 7, 1));
}

TEST(LoadOccupancyMap, UsesGivenThresholds) {
  const TempDir dir;
  const auto yaml = writeMap(dir, greyRow({100, 150, 140}),
                             "occupied_thresh: 0.5\nfree_thresh: 0.42\nmode: scale\n");
  // 100 -> 0.608 > 0.5; 150 -> 0.412 < 0.42; 140 -> 0.451 between.
  EXPECT_EQ(rowStates(loadOccupancyMap(yaml)), (std::vector<CellState>{kOcc, kFree, kUnk}));
}

TEST(LoadOccupancyMap, NegateSwapsBlackAndWhite) {
  const TempDir dir;
  const auto yaml = writeMap(dir, greyRow({0, 254, 100, 205}), "negate: 1\n");
  // p = v / 255: 0 -> 0, 254 -> 0.996, 100 -> 0.39, 205 -> 0.80.
  EXPECT_EQ(rowStates(loadOccupancyMap(yaml)), (std::vector<CellState>{kFree, kOcc, kUnk, kOcc}));
}

TEST(LoadOccupancyMap, AveragesColourChannelsAndIgnoresAlpha) {
  const TempDir dir;
  cv::Mat bgr(1, 4, CV_8UC3);
  bgr.at<cv::Vec3b>(0, 0) = {0, 0, 255};      // mean 85 -> p 0.667: occupied
  bgr.at<cv::Vec3b>(0, 1) = {255, 255, 0};    // mean 170 -> p 0.333: unknown
  bgr.at<cv::Vec3b>(0, 2) = {250, 250, 250};  // free
  bgr.at<cv::Vec3b>(0, 3) = {255, 250, 245};  // mean 250: free
  EXPECT_EQ(rowStates(loadOccupancyMap(writeMap(dir, bgr))),
            (std::vector<CellState>{kOcc, kUnk, kFree, kFree}));

  const TempDir dir2;
  cv::Mat bgra(1, 3, CV_8UC4);
  bgra.at<cv::Vec4b>(0, 0) = {255, 255, 255, 0};  // transparent white: still free
  bgra.at<cv::Vec4b>(0, 1) = {0, 0, 0, 255};
  bgra.at<cv::Vec4b>(0, 2) = {0, 0, 0, 0};
  EXPECT_EQ(rowStates(loadOccupancyMap(writeMap(dir2, bgra))),
            (std::vector<CellState>{kFree, kOcc, kOcc}));
}

TEST(LoadOccupancyMap, ReadsSixteenBitImages) {
  const TempDir dir;
  cv::Mat image(1, 3, CV_16UC1);
  image.at<std::uint16_t>(0, 0) = 65535;
  image.at<std::uint16_t>(0, 1) = 0;
  image.at<std::uint16_t>(0, 2) = 100 * 257;  // 100 in 8 bits
  EXPECT_EQ(rowStates(loadOccupancyMap(writeMap(dir, image))),
            (std::vector<CellState>{kFree, kOcc, kUnk}));
}

TEST(LoadOccupancyMap, ImageRowZeroIsTheTopOfTheMap) {
  const TempDir dir;
  cv::Mat image(3, 2, CV_8UC1, cv::Scalar(254));
  image.at<std::uint8_t>(0, 0) = 0;  // top-left
  image.at<std::uint8_t>(2, 1) = 0;  // bottom-right
  const OccupancyGrid grid = loadOccupancyMap(writeMap(dir, image, "", "map.pgm"));
  ASSERT_EQ(grid.geometry(), GridGeometry(Vec2(-1.0, 2.0), 0.1, 2, 3));
  EXPECT_EQ(grid.state(Cell{0, 2}), kOcc);
  EXPECT_EQ(grid.state(Cell{1, 0}), kOcc);
  EXPECT_EQ(grid.state(Cell{0, 0}), kFree);
  EXPECT_EQ(grid.state(Cell{1, 2}), kFree);
  EXPECT_EQ(grid.state(Cell{0, 1}), kFree);
  // The top-left pixel is the cell holding the map point just below the top-left corner.
  EXPECT_EQ(grid.geometry().cellOf(Vec2(-0.95, 2.25)), (Cell{0, 2}));
}

TEST(LoadMapServerYaml, ReadsKeysDefaultsAndIgnoresUnknownKeys) {
  const TempDir dir;
  std::filesystem::create_directory(dir / "img");
  cv::imwrite((dir / "img" / "m.pgm").string(), greyRow({254}));
  const auto yaml = dir.write("m.yaml",
                              "image: img/m.pgm\nresolution: 0.025\norigin: [1.5, -2, 0]\n"
                              "frame_id: map\nextra: [1, 2]\n");
  const MapServerMetadata m = loadMapServerYaml(yaml);
  EXPECT_EQ(m.image, dir / "img" / "m.pgm");
  EXPECT_DOUBLE_EQ(m.resolution_m, 0.025);
  EXPECT_DOUBLE_EQ(m.origin_m.x(), 1.5);
  EXPECT_DOUBLE_EQ(m.origin_m.y(), -2.0);
  EXPECT_EQ(m.origin_yaw_rad, 0.0);
  EXPECT_FALSE(m.negate);
  EXPECT_DOUBLE_EQ(m.occupied_thresh, 0.65);
  EXPECT_DOUBLE_EQ(m.free_thresh, 0.196);
  EXPECT_EQ(m.mode, "trinary");

  const auto absolute =
      dir.write("abs.yaml", "image: " + (dir / "img" / "m.pgm").string() + "\n" + kYamlHead);
  EXPECT_EQ(loadMapServerYaml(absolute).image, dir / "img" / "m.pgm");
}

/// A bad map YAML and what its error must say.
struct BadMapYaml {
  const char* label;
  std::string yaml;
  std::string expected;
};

TEST(LoadMapServerYaml, RejectsBadValuesNamingTheFile) {
  const std::vector<BadMapYaml> cases = {
      {"missing image", "resolution: 0.1\norigin: [0, 0, 0]\n", "missing required key 'image'"},
      {"missing resolution", "image: map.png\norigin: [0, 0, 0]\n",
       "missing required key 'resolution'"},
      {"missing origin", "image: map.png\nresolution: 0.1\n", "missing required key 'origin'"},
      {"zero resolution", "image: map.png\nresolution: 0\norigin: [0, 0, 0]\n",
       "resolution: must be > 0, got 0"},
      {"negative resolution", "image: map.png\nresolution: -0.05\norigin: [0, 0, 0]\n",
       "resolution: must be > 0, got -0.05"},
      {"text resolution", "image: map.png\nresolution: fine\norigin: [0, 0, 0]\n",
       "resolution: expected a finite number, got 'fine'"},
      {"rotated", "image: map.png\nresolution: 0.1\norigin: [0, 0, 0.5]\n",
       "origin: rotated origins are not supported"},
      {"origin short", "image: map.png\nresolution: 0.1\norigin: [0]\n",
       "origin: expected [x, y, yaw]"},
      {"occupied above 1", "image: map.png\n" + kYamlHead + "occupied_thresh: 1.5\n",
       "occupied_thresh: must be in [0, 1], got 1.5"},
      {"free below 0", "image: map.png\n" + kYamlHead + "free_thresh: -0.1\n",
       "free_thresh: must be in [0, 1], got -0.1"},
      {"free above occupied", "image: map.png\n" + kYamlHead + "free_thresh: 0.7\n",
       "free_thresh (0.7) must be below occupied_thresh (0.65)"},
      {"negate 2", "image: map.png\n" + kYamlHead + "negate: 2\n", "negate: expected 0 or 1"},
      {"raw mode", "image: map.png\n" + kYamlHead + "mode: raw\n", "mode: 'raw' is not supported"},
      {"bad mode", "image: map.png\n" + kYamlHead + "mode: fancy\n", "unknown mode 'fancy'"},
      {"malformed", "image: map.png\nresolution: [0.1\n", "line "},
      {"not a map", "- map.png\n", "expected a map_server map description"},
  };
  for (const BadMapYaml& c : cases) {
    SCOPED_TRACE(c.label);
    const TempDir dir;
    cv::imwrite((dir / "map.png").string(), greyRow({254}));
    const auto yaml = dir.write("map.yaml", c.yaml);
    const std::string message = inputErrorOf([&] { loadMapServerYaml(yaml); });
    EXPECT_TRUE(Contains(message, yaml.string() + ": "));
    EXPECT_TRUE(Contains(message, c.expected));
  }
}

TEST(LoadMapServerYaml, MissingYamlOrImageFile) {
  const TempDir dir;
  EXPECT_TRUE(Contains(inputErrorOf([&] { loadMapServerYaml(dir / "none.yaml"); }),
                       (dir / "none.yaml").string() + ": file not found"));
  const auto yaml = dir.write("map.yaml", "image: gone.pgm\n" + kYamlHead);
  const std::string message = inputErrorOf([&] { sim::loadImageWorld(yaml, std::nullopt); });
  EXPECT_TRUE(Contains(message, yaml.string() + ": image file not found: "));
  EXPECT_TRUE(Contains(message, (dir / "gone.pgm").string()));
  EXPECT_TRUE(Contains(inputErrorOf([&] { loadOccupancyMap(yaml); }), "image file not found"));
}

TEST(LoadImageWorld, CorruptImageIsNamed) {
  const TempDir dir;
  const auto image = dir.write("map.png", "\x89PNG\r\n\x1a\n this is not really a png");
  const auto yaml = dir.write("map.yaml", "image: map.png\n" + kYamlHead);
  EXPECT_TRUE(Contains(inputErrorOf([&] { sim::loadImageWorld(yaml, std::nullopt); }),
                       image.string() + ": cannot decode image"));
  EXPECT_TRUE(Contains(inputErrorOf([&] { loadOccupancyMap(yaml); }),
                       image.string() + ": cannot decode image"));
  dir.write("map.png", "");
  EXPECT_TRUE(Contains(inputErrorOf([&] { sim::loadImageWorld(yaml, std::nullopt); }),
                       image.string() + ": cannot decode image"));
}

TEST(LoadImageWorld, ImageWithoutFreePixelIsRejected) {
  const TempDir dir;
  const auto yaml = writeMap(dir, cv::Mat(4, 4, CV_8UC1, cv::Scalar(100)));  // all unknown
  EXPECT_TRUE(Contains(inputErrorOf([&] { sim::loadImageWorld(yaml, std::nullopt); }),
                       (dir / "map.png").string() + ": no free pixel"));
  // As a map (not a world) it is fine: everything unknown.
  const OccupancyGrid grid = loadOccupancyMap(yaml);
  for (std::size_t i = 0; i < grid.geometry().cellCount(); ++i) EXPECT_TRUE(grid.isUnknown(i));
}

TEST(LoadImageWorld, BuildsSolidMaskNameAndSource) {
  const TempDir dir;
  cv::Mat image(2, 3, CV_8UC1, cv::Scalar(254));
  image.at<std::uint8_t>(0, 1) = 0;    // occupied
  image.at<std::uint8_t>(1, 2) = 205;  // unknown: solid too
  const auto yaml = writeMap(dir, image);
  const sim::World world = sim::loadImageWorld(yaml, std::nullopt);
  EXPECT_EQ(world.name, "map");
  EXPECT_EQ(world.source, yaml.string());
  EXPECT_FALSE(world.start_given);
  EXPECT_TRUE(world.walls.empty());
  EXPECT_TRUE(world.rooms.empty());
  ASSERT_TRUE(world.image.has_value());
  const sim::ImageWorld& w = *world.image;
  EXPECT_DOUBLE_EQ(w.resolution_m, 0.1);
  EXPECT_DOUBLE_EQ(w.origin_m.x(), -1.0);
  EXPECT_DOUBLE_EQ(w.origin_m.y(), 2.0);
  EXPECT_TRUE(w.room_labels.empty());
  ASSERT_EQ(w.solid.type(), CV_8UC1);
  ASSERT_EQ(w.solid.size(), cv::Size(3, 2));
  const std::uint8_t expected[2][3] = {{0, 255, 0}, {0, 0, 255}};
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(w.solid.at<std::uint8_t>(r, c), expected[r][c]);
  }
}

TEST(LoadImageWorld, GreyscaleRoomLabels) {
  const TempDir dir;
  const auto yaml = writeMap(dir, cv::Mat(3, 2, CV_8UC1, cv::Scalar(254)));
  cv::Mat labels(3, 2, CV_8UC1, cv::Scalar(0));
  labels.at<std::uint8_t>(0, 1) = 7;
  labels.at<std::uint8_t>(1, 0) = 3;
  labels.at<std::uint8_t>(2, 1) = 3;
  cv::imwrite((dir / "rooms.png").string(), labels);
  const sim::World world = sim::loadImageWorld(yaml, dir / "rooms.png");
  ASSERT_EQ(world.rooms.size(), 2u);
  EXPECT_EQ(world.rooms[0].id, 3);
  EXPECT_EQ(world.rooms[0].name, "room_3");
  EXPECT_EQ(world.rooms[1].id, 7);
  EXPECT_EQ(world.rooms[1].name, "room_7");
  EXPECT_TRUE(world.rooms[0].polygon_m.empty());
  const cv::Mat& ids = world.image->room_labels;
  ASSERT_EQ(ids.type(), CV_32SC1);
  EXPECT_EQ(ids.at<int>(0, 0), 0);
  EXPECT_EQ(ids.at<int>(0, 1), 7);
  EXPECT_EQ(ids.at<int>(1, 0), 3);
  EXPECT_EQ(ids.at<int>(2, 1), 3);
}

TEST(LoadImageWorld, SixteenBitRoomLabels) {
  const TempDir dir;
  const auto yaml = writeMap(dir, cv::Mat(1, 3, CV_8UC1, cv::Scalar(254)));
  cv::Mat labels(1, 3, CV_16UC1, cv::Scalar(0));
  labels.at<std::uint16_t>(0, 0) = 300;
  labels.at<std::uint16_t>(0, 2) = 5;
  cv::imwrite((dir / "rooms.png").string(), labels);
  const sim::World world = sim::loadImageWorld(yaml, dir / "rooms.png");
  ASSERT_EQ(world.rooms.size(), 2u);
  EXPECT_EQ(world.rooms[0].id, 5);
  EXPECT_EQ(world.rooms[1].id, 300);
  EXPECT_EQ(world.image->room_labels.at<int>(0, 0), 300);
}

TEST(LoadImageWorld, ColourRoomLabelsNumberedByFirstAppearance) {
  const TempDir dir;
  const auto yaml = writeMap(dir, cv::Mat(2, 3, CV_8UC1, cv::Scalar(254)));
  cv::Mat labels(2, 3, CV_8UC3, cv::Scalar(0, 0, 0));
  labels.at<cv::Vec3b>(0, 1) = {0, 0, 255};      // red: first seen -> 1
  labels.at<cv::Vec3b>(0, 2) = {255, 255, 255};  // white: no room
  labels.at<cv::Vec3b>(1, 0) = {0, 200, 0};      // green -> 2
  labels.at<cv::Vec3b>(1, 1) = {0, 0, 255};      // red again
  labels.at<cv::Vec3b>(1, 2) = {10, 20, 30};     // -> 3
  cv::imwrite((dir / "rooms.png").string(), labels);
  const sim::World world = sim::loadImageWorld(yaml, dir / "rooms.png");
  ASSERT_EQ(world.rooms.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(world.rooms[i].id, i + 1);
    EXPECT_EQ(world.rooms[i].name, "room_" + std::to_string(i + 1));
  }
  const int expected[2][3] = {{0, 1, 0}, {2, 1, 3}};
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(world.image->room_labels.at<int>(r, c), expected[r][c]) << r << "," << c;
    }
  }
}

TEST(LoadImageWorld, RoomLabelImageErrors) {
  const TempDir dir;
  const auto yaml = writeMap(dir, cv::Mat(2, 3, CV_8UC1, cv::Scalar(254)));
  cv::imwrite((dir / "small.png").string(), cv::Mat(3, 2, CV_8UC1, cv::Scalar(1)));
  const std::string message = inputErrorOf([&] { sim::loadImageWorld(yaml, dir / "small.png"); });
  EXPECT_TRUE(Contains(message, (dir / "small.png").string() + ": "));
  EXPECT_TRUE(Contains(message, "is 2x3 pixels but the map image is 3x2"));

  const auto corrupt = dir.write("corrupt.png", "not an image");
  EXPECT_TRUE(Contains(inputErrorOf([&] { sim::loadImageWorld(yaml, corrupt); }),
                       corrupt.string() + ": cannot decode image"));
  EXPECT_TRUE(Contains(inputErrorOf([&] { sim::loadImageWorld(yaml, dir / "none.png"); }),
                       (dir / "none.png").string() + ": file not found"));
}

OccupancyGrid patternGrid() {
  const GridGeometry geometry(Vec2(0.1 + 0.2, -7.35), 0.05, 7, 5);
  OccupancyGrid grid(geometry);
  for (std::size_t i = 0; i < geometry.cellCount(); ++i) {
    grid.setState(i, static_cast<CellState>((i * 7 + i / 3) % 3));
  }
  return grid;
}

TEST(SaveOccupancyMap, WritesPgmAndYamlInMapServerFormat) {
  const TempDir dir;
  OccupancyGrid grid(GridGeometry(Vec2(-3.25, 1.5), 0.05, 3, 2));
  grid.setState(grid.geometry().index({0, 1}), kOcc);  // top-left pixel
  grid.setState(grid.geometry().index({1, 1}), kFree);
  grid.setState(grid.geometry().index({2, 0}), kFree);  // bottom-right pixel
  saveOccupancyMap(grid, dir / "saved.yaml");
  EXPECT_EQ(dir.entries(), (Names{"saved.pgm", "saved.yaml"}));
  EXPECT_EQ(readFile(dir / "saved.pgm"),
            std::string("P5\n3 2\n255\n") + std::string("\x00\xfe\xcd\xcd\xcd\xfe", 6));
  EXPECT_EQ(readFile(dir / "saved.yaml"),
            "image: saved.pgm\nresolution: 0.05\norigin: [-3.25, 1.5, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n");
}

TEST(SaveOccupancyMap, RoundTripReproducesStatesAndGeometry) {
  const TempDir dir;
  const OccupancyGrid grid = patternGrid();
  saveOccupancyMap(grid, dir / "round.yaml");
  const OccupancyGrid back = loadOccupancyMap(dir / "round.yaml");
  EXPECT_EQ(back.geometry(), grid.geometry());
  EXPECT_EQ(back.states(), grid.states());

  // Overwriting keeps exactly the two files.
  OccupancyGrid changed = grid;
  changed.setState(0, kOcc);
  saveOccupancyMap(changed, dir / "round.yaml");
  EXPECT_EQ(loadOccupancyMap(dir / "round.yaml").states(), changed.states());
  EXPECT_EQ(dir.entries(), (Names{"round.pgm", "round.yaml"}));

  // The saved map also loads as a world, solid wherever it is not free.
  const sim::World world = sim::loadImageWorld(dir / "round.yaml", std::nullopt);
  const GridGeometry& g = grid.geometry();
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const bool free = changed.state(Cell{x, y}) == kFree;
      EXPECT_EQ(world.image->solid.at<std::uint8_t>(g.height() - 1 - y, x), free ? 0 : 255);
    }
  }
}

TEST(SaveOccupancyMap, RejectsEmptyGridAndUnwritablePlace) {
  const TempDir dir;
  EXPECT_THROW(
      saveOccupancyMap(OccupancyGrid(GridGeometry(Vec2::Zero(), 0.05, 0, 0)), dir / "empty.yaml"),
      InvalidArgument);
  const auto blocker = dir.write("blocker", "x");
  EXPECT_TRUE(Contains(inputErrorOf([&] { saveOccupancyMap(patternGrid(), blocker / "m.yaml"); }),
                       "cannot write"));
  EXPECT_EQ(dir.entries(), (Names{"blocker"}));
}

}  // namespace
}  // namespace roomscout::io
