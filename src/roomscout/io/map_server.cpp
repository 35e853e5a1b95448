#include "roomscout/io/map_server.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/core/grid_limits.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/detail/image_file.hpp"
#include "roomscout/io/yaml_support.hpp"

namespace roomscout::io {
namespace {

constexpr std::uint8_t kPgmFree = 254;
constexpr std::uint8_t kPgmOccupied = 0;
constexpr std::uint8_t kPgmUnknown = 205;

/// Reads and decodes an image file unchanged (bit depth and channels as stored).
cv::Mat readImage(const std::filesystem::path& path) {
  cv::Mat image = readImageFile(path, cv::IMREAD_UNCHANGED);
  if (image.depth() != CV_8U && image.depth() != CV_16U) {
    throw InputError(path.string(), "unsupported pixel type (need 8- or 16-bit channels)");
  }
  if (image.channels() > 4) {
    throw InputError(path.string(), "unsupported image: " + std::to_string(image.channels()) +
                                        " channels (need 1 to 4)");
  }
  return image;
}

/// An image's width and height from the first bytes of its file (imageHeaderSize); nullopt
/// for formats without a size in their header or an unreadable file.
std::optional<cv::Size> headerSize(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(64 * 1024, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
  return imageHeaderSize(head);
}

template <typename T>
void classifyPixels(const cv::Mat& image, const MapServerMetadata& m, cv::Mat& out) {
  const int channels = image.channels();
  // Grey + alpha and colour + alpha: the alpha channel is ignored.
  const int colour_channels = (channels == 2 || channels == 4) ? channels - 1 : channels;
  const double to_8bit = 255.0 / static_cast<double>(std::numeric_limits<T>::max());
  for (int row = 0; row < image.rows; ++row) {
    const T* pixel = image.ptr<T>(row);
    std::uint8_t* state = out.ptr<std::uint8_t>(row);
    for (int col = 0; col < image.cols; ++col, pixel += channels) {
      double sum = 0.0;
      for (int k = 0; k < colour_channels; ++k) sum += static_cast<double>(pixel[k]);
      double value = sum / colour_channels * to_8bit;
      if (m.negate) value = 255.0 - value;
      const double p = (255.0 - value) / 255.0;
      CellState s = CellState::kUnknown;
      if (p > m.occupied_thresh) {
        s = CellState::kOccupied;
      } else if (p < m.free_thresh) {
        s = CellState::kFree;
      }
      state[col] = static_cast<std::uint8_t>(s);
    }
  }
}

/// A room label image turned into ids (CV_32S) and the ids present, in id order.
template <typename T>
cv::Mat labelRooms(const cv::Mat& image, std::vector<int>& ids) {
  cv::Mat labels(image.rows, image.cols, CV_32S, cv::Scalar(0));
  const int channels = image.channels();
  if (channels <= 2) {  // greyscale (alpha ignored): the value is the room id
    std::set<int> present;
    for (int row = 0; row < image.rows; ++row) {
      const T* pixel = image.ptr<T>(row);
      int* label = labels.ptr<int>(row);
      for (int col = 0; col < image.cols; ++col) {
        label[col] = static_cast<int>(pixel[col * channels]);
        if (label[col] != 0) present.insert(label[col]);
      }
    }
    ids.assign(present.begin(), present.end());
    return labels;
  }
  // Colour: every distinct colour but black and white is one room, numbered by first sight.
  constexpr std::uint64_t kMax = std::numeric_limits<T>::max();
  const std::uint64_t white = (kMax << 32) | (kMax << 16) | kMax;
  std::map<std::uint64_t, int> id_of_colour;
  for (int row = 0; row < image.rows; ++row) {
    const T* pixel = image.ptr<T>(row);
    int* label = labels.ptr<int>(row);
    for (int col = 0; col < image.cols; ++col, pixel += channels) {
      const std::uint64_t colour = (std::uint64_t{pixel[0]} << 32) |
                                   (std::uint64_t{pixel[1]} << 16) | std::uint64_t{pixel[2]};
      if (colour == 0 || colour == white) continue;
      const auto [it, added] =
          id_of_colour.emplace(colour, static_cast<int>(id_of_colour.size()) + 1);
      if (added) ids.push_back(it->second);
      label[col] = it->second;
    }
  }
  return labels;
}

}  // namespace

MapServerMetadata loadMapServerYaml(const std::filesystem::path& yaml_path) {
  const std::string source = yaml_path.string();
  const YAML::Node root = parseYaml(readFile(yaml_path), source);
  const auto fail = [&](const std::string& problem) -> void { throw InputError(source, problem); };
  if (!root.IsMap()) fail("expected a map_server map description (a YAML map)");

  const auto required = [&](const char* key) {
    const YAML::Node node = root[key];
    if (!node.IsDefined()) fail(std::string("missing required key '") + key + "'");
    return node;
  };
  const auto number = [&](const YAML::Node& node, const std::string& where) {
    const std::optional<double> value = yamlDouble(node);
    if (!value) fail(where + ": expected a finite number, got " + describeYamlNode(node));
    return *value;
  };

  MapServerMetadata m;
  const YAML::Node image = required("image");
  if (!image.IsScalar() || image.Scalar().empty()) {
    fail("image: expected a file name, got " + describeYamlNode(image));
  }
  m.image = image.Scalar();
  if (m.image.is_relative()) m.image = yaml_path.parent_path() / m.image;

  m.resolution_m = number(required("resolution"), "resolution");
  if (!(m.resolution_m > 0.0)) fail("resolution: must be > 0, got " + formatDouble(m.resolution_m));

  const YAML::Node origin = required("origin");
  if (!origin.IsSequence() || (origin.size() != 2 && origin.size() != 3)) {
    fail("origin: expected [x, y, yaw], got " + describeYamlNode(origin));
  }
  m.origin_m = {number(origin[0], "origin[0]"), number(origin[1], "origin[1]")};
  if (origin.size() == 3) m.origin_yaw_rad = number(origin[2], "origin[2]");
  if (m.origin_yaw_rad != 0.0) {
    fail("origin: rotated origins are not supported (yaw " + formatDouble(m.origin_yaw_rad) +
         " rad; rotate the image instead)");
  }

  if (const YAML::Node negate = root["negate"]; negate.IsDefined()) {
    const std::optional<int> as_int = yamlInt(negate);
    const std::optional<bool> as_bool = yamlBool(negate);
    if (as_int && (*as_int == 0 || *as_int == 1)) {
      m.negate = *as_int == 1;
    } else if (as_bool) {
      m.negate = *as_bool;
    } else {
      fail("negate: expected 0 or 1, got " + describeYamlNode(negate));
    }
  }
  for (const auto& [key, value] : {std::pair{"occupied_thresh", &m.occupied_thresh},
                                   std::pair{"free_thresh", &m.free_thresh}}) {
    const YAML::Node node = root[key];
    if (!node.IsDefined()) continue;
    *value = number(node, key);
    if (*value < 0.0 || *value > 1.0) {
      fail(std::string(key) + ": must be in [0, 1], got " + formatDouble(*value));
    }
  }
  if (!(m.free_thresh < m.occupied_thresh)) {
    fail("free_thresh (" + formatDouble(m.free_thresh) + ") must be below occupied_thresh (" +
         formatDouble(m.occupied_thresh) + ")");
  }
  if (const YAML::Node mode = root["mode"]; mode.IsDefined()) {
    if (!mode.IsScalar()) fail("mode: expected trinary or scale, got " + describeYamlNode(mode));
    m.mode = mode.Scalar();
    if (m.mode == "raw") fail("mode: 'raw' is not supported (use trinary or scale)");
    if (m.mode != "trinary" && m.mode != "scale") {
      fail("mode: unknown mode '" + m.mode + "' (known: trinary, scale)");
    }
  }

  std::error_code ec;
  if (!std::filesystem::is_regular_file(m.image, ec)) {
    fail("image file not found: " + m.image.string());
  }
  return m;
}

cv::Mat classifyMapImage(const cv::Mat& image, const MapServerMetadata& metadata) {
  if (image.empty() || image.channels() > 4 ||
      (image.depth() != CV_8U && image.depth() != CV_16U)) {
    throw InvalidArgument("classifyMapImage: need a non-empty 8- or 16-bit image, 1-4 channels");
  }
  cv::Mat states(image.rows, image.cols, CV_8U);
  if (image.depth() == CV_8U) {
    classifyPixels<std::uint8_t>(image, metadata, states);
  } else {
    classifyPixels<std::uint16_t>(image, metadata, states);
  }
  return states;
}

cv::Mat readMapImage(const std::filesystem::path& yaml_path, const MapServerMetadata& m) {
  const auto check = [&](cv::Size size) {
    checkGridSize(yaml_path.string(), "map", size.width, size.height, m.resolution_m);
  };
  if (const std::optional<cv::Size> size = headerSize(m.image)) check(*size);
  cv::Mat image = readImage(m.image);
  check(image.size());
  return image;
}

RoomLabelImage readRoomLabelImage(const std::filesystem::path& path, cv::Size map_size) {
  const auto check_size = [&](cv::Size size) {
    if (size != map_size) {
      throw InputError(path.string(),
                       "room label image is " + std::to_string(size.width) + "x" +
                           std::to_string(size.height) + " pixels but the map image is " +
                           std::to_string(map_size.width) + "x" + std::to_string(map_size.height));
    }
  };
  if (const std::optional<cv::Size> size = headerSize(path)) check_size(*size);
  const cv::Mat image = readImage(path);
  check_size(image.size());
  RoomLabelImage out;
  out.labels = image.depth() == CV_8U ? labelRooms<std::uint8_t>(image, out.ids)
                                      : labelRooms<std::uint16_t>(image, out.ids);
  return out;
}

OccupancyGrid loadOccupancyMap(const std::filesystem::path& yaml_path) {
  const MapServerMetadata m = loadMapServerYaml(yaml_path);
  const cv::Mat states = classifyMapImage(readMapImage(yaml_path, m), m);
  OccupancyGridOptions options;
  options.resolution_m = m.resolution_m;
  OccupancyGrid grid(GridGeometry(m.origin_m, m.resolution_m, states.cols, states.rows), options);
  const GridGeometry& g = grid.geometry();
  for (int y = 0; y < g.height(); ++y) {
    const std::uint8_t* state = states.ptr<std::uint8_t>(g.height() - 1 - y);
    for (int x = 0; x < g.width(); ++x) {
      grid.setState(g.index({x, y}), static_cast<CellState>(state[x]));
    }
  }
  return grid;
}

void saveOccupancyMap(const OccupancyGrid& grid, const std::filesystem::path& yaml_path) {
  const GridGeometry& g = grid.geometry();
  if (g.width() <= 0 || g.height() <= 0) {
    throw InvalidArgument("saveOccupancyMap: the grid is empty");
  }
  const std::string name = yaml_path.stem().string();
  if (name.empty())
    throw InvalidArgument("saveOccupancyMap: no file name in " + yaml_path.string());
  const std::string image_name = name + ".pgm";

  std::string pgm =
      "P5\n" + std::to_string(g.width()) + " " + std::to_string(g.height()) + "\n255\n";
  const std::size_t header_size = pgm.size();
  pgm.resize(header_size + g.cellCount());
  for (int row = 0; row < g.height(); ++row) {
    const int y = g.height() - 1 - row;
    for (int x = 0; x < g.width(); ++x) {
      std::uint8_t value = kPgmUnknown;
      switch (grid.state(g.index({x, y}))) {
        case CellState::kFree:
          value = kPgmFree;
          break;
        case CellState::kOccupied:
          value = kPgmOccupied;
          break;
        case CellState::kUnknown:
          value = kPgmUnknown;
          break;
      }
      pgm[header_size + static_cast<std::size_t>(row) * g.width() + x] = static_cast<char>(value);
    }
  }

  YAML::Emitter image_scalar;
  image_scalar << image_name;
  const std::string yaml = std::string("image: ") + image_scalar.c_str() +
                           "\nresolution: " + formatDouble(g.resolution_m()) + "\norigin: [" +
                           formatDouble(g.origin_m().x()) + ", " + formatDouble(g.origin_m().y()) +
                           ", 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"
                           "mode: trinary\n";
  writeFileAtomic(yaml_path.parent_path() / image_name, pgm);
  writeFileAtomic(yaml_path, yaml);
}

}  // namespace roomscout::io
