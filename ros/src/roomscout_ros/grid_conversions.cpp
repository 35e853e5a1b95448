#include "roomscout_ros/grid_conversions.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

#include "roomscout/core/errors.hpp"

namespace roomscout::ros1 {
namespace {

double yawOf(double x, double y, double z, double w) {
  return std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
}

/// The decimal a float resolution was written from (0.05f is 0.0500000007; the map is 0.05):
/// the shortest text that reads back as the same float, read as a double.
double decimalOf(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text - 1, value).ptr;
  *end = '\0';
  return std::strtod(text, nullptr);
}

}  // namespace

MapConvention MapConvention::named(const std::string& source) {
  // map_server: its free_thresh and occupied_thresh defaults (map_server's YAML).
  if (source == "map_server") return {19.6, 65.0};
  // Cartographer publishes each cell's probability of being occupied x 100; a cell seen free
  // once holds its miss probability 0.49, one hit once its hit probability 0.55
  // (trajectory_builder_2d's defaults), and -1 only where nothing was seen.
  if (source == "cartographer") return {49.0, 55.0};
  // slam_toolbox (Karto's grid) and gmapping publish 0, 100 and -1 only: the split at 50 reads
  // them exactly and tolerates a grid that was averaged or scaled.
  if (source == "slam_toolbox" || source == "gmapping") return {49.0, 50.0};
  // A costmap_2d costmap: 100 lethal, 99 inscribed (within the robot's radius of a wall, so
  // free floor), 1-98 the inflation's fall-off, 0 free. As costmap_2d's static layer reads a map
  // (trinary_costmap, lethal_cost_threshold 100), everything below lethal is free.
  if (source == "costmap") return {99.0, 100.0};
  std::string known;
  for (const std::string& n : names()) known += (known.empty() ? "" : ", ") + n;
  throw OptionError("~map_source: unknown source '" + source + "' (known: " + known + ")");
}

std::vector<std::string> MapConvention::names() {
  return {"map_server", "cartographer", "slam_toolbox", "gmapping", "costmap"};
}

void MapConvention::validate() const {
  if (!(std::isfinite(free_max) && std::isfinite(occupied_min) && free_max >= 0.0 &&
        free_max < occupied_min && occupied_min <= 100.0)) {
    throw OptionError(
        "~free_threshold and ~occupied_threshold must satisfy 0 <= free < "
        "occupied <= 100, not " +
        std::to_string(free_max) + " and " + std::to_string(occupied_min));
  }
}

ReceivedGrid fromMsg(const nav_msgs::OccupancyGrid& msg, const OccupancyGrid* previous,
                     const MapConvention& convention) {
  const auto& info = msg.info;
  const auto& q = info.origin.orientation;
  const auto& o = info.origin.position;
  if (!(std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z) && std::isfinite(q.x) &&
        std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w))) {
    throw InvalidArgument("map message: the origin is not finite (" + std::to_string(o.x) + ", " +
                          std::to_string(o.y) + ")");
  }
  if (!(std::isfinite(info.resolution) && info.resolution > 0.0f)) {
    throw InvalidArgument("map message: resolution " + std::to_string(info.resolution) +
                          " is not > 0");
  }
  if (info.width == 0 || info.height == 0)
    throw InvalidArgument("map message: the map is empty (0 cells)");
  if (msg.data.size() != static_cast<std::size_t>(info.width) * info.height) {
    throw InvalidArgument("map message: " + std::to_string(msg.data.size()) +
                          " cells of data for a " + std::to_string(info.width) + " x " +
                          std::to_string(info.height) + " map");
  }
  const double yaw = yawOf(q.x, q.y, q.z, q.w);
  if (std::abs(yaw) > 1e-6 || std::abs(q.x) > 1e-6 || std::abs(q.y) > 1e-6) {
    throw InvalidArgument("map message: the origin is rotated (yaw " + std::to_string(yaw) +
                          " rad); only maps aligned with their frame are supported");
  }
  const GridGeometry geometry(Vec2(info.origin.position.x, info.origin.position.y),
                              decimalOf(info.resolution), static_cast<int>(info.width),
                              static_cast<int>(info.height));
  ReceivedGrid out{OccupancyGrid(geometry), std::nullopt};
  const std::size_t n = msg.data.size();
  for (std::size_t i = 0; i < n; ++i) {
    const int v = msg.data[i];
    if (v < 0) continue;  // unknown, as constructed
    if (v >= convention.occupied_min) {
      out.grid.setState(i, CellState::kOccupied);
    } else if (v <= convention.free_max) {
      out.grid.setState(i, CellState::kFree);
    }
  }
  if (previous != nullptr && previous->geometry() == geometry) {
    CellRect changed;
    const std::uint8_t* a = previous->stateBytes();
    const std::uint8_t* b = out.grid.stateBytes();
    const int w = geometry.width();
    for (int y = 0; y < geometry.height(); ++y) {
      const std::size_t row = static_cast<std::size_t>(y) * w;
      for (int x = 0; x < w; ++x) {
        if (a[row + x] != b[row + x]) changed.expandToInclude(Cell{x, y});
      }
    }
    out.changed = changed;
  }
  return out;
}

void applyUpdate(nav_msgs::OccupancyGrid& map, const map_msgs::OccupancyGridUpdate& update) {
  const std::uint64_t x = static_cast<std::uint32_t>(update.x);
  const std::uint64_t y = static_cast<std::uint32_t>(update.y);
  if (update.x < 0 || update.y < 0 || x + update.width > map.info.width ||
      y + update.height > map.info.height) {
    throw InvalidArgument("map update: the patch " + std::to_string(update.width) + " x " +
                          std::to_string(update.height) + " at (" + std::to_string(update.x) +
                          ", " + std::to_string(update.y) + ") lies outside the " +
                          std::to_string(map.info.width) + " x " + std::to_string(map.info.height) +
                          " map");
  }
  if (update.data.size() != static_cast<std::size_t>(update.width) * update.height) {
    throw InvalidArgument("map update: " + std::to_string(update.data.size()) +
                          " cells of data for a " + std::to_string(update.width) + " x " +
                          std::to_string(update.height) + " patch");
  }
  if (map.data.size() != static_cast<std::size_t>(map.info.width) * map.info.height)
    throw InvalidArgument("map update: the map it patches has the wrong data size");
  for (std::uint32_t row = 0; row < update.height; ++row) {
    const auto from = update.data.begin() + static_cast<std::ptrdiff_t>(row) * update.width;
    std::copy(from, from + update.width,
              map.data.begin() + static_cast<std::ptrdiff_t>((y + row) * map.info.width + x));
  }
}

void toMsg(const OccupancyGrid& grid, nav_msgs::OccupancyGrid& msg) {
  const GridGeometry& g = grid.geometry();
  msg.info.resolution = static_cast<float>(g.resolution_m());  // read back by decimalOf()
  msg.info.width = static_cast<std::uint32_t>(g.width());
  msg.info.height = static_cast<std::uint32_t>(g.height());
  msg.info.origin = toPoseMsg(Pose2{g.origin_m().x(), g.origin_m().y(), 0.0});
  const std::size_t n = static_cast<std::size_t>(g.width()) * g.height();
  msg.data.resize(n);
  static constexpr std::int8_t kValue[3] = {-1, 0, 100};  // by CellState
  const std::uint8_t* states = grid.stateBytes();
  for (std::size_t i = 0; i < n; ++i) msg.data[i] = kValue[states[i]];
}

void toProbabilityMsg(const OccupancyGrid& grid, nav_msgs::OccupancyGrid& msg) {
  toMsg(grid, msg);
  const std::size_t n = msg.data.size();
  for (std::size_t i = 0; i < n; ++i) {
    const float l = grid.logOdds(i);
    if (l == 0.0f) continue;  // never observed: as toMsg has it
    const double p = 1.0 / (1.0 + std::exp(-static_cast<double>(l)));
    msg.data[i] = static_cast<std::int8_t>(std::lround(100.0 * p));
  }
}

void labelsToMsg(const cv::Mat& labels, const GridGeometry& geometry,
                 nav_msgs::OccupancyGrid& msg) {
  if (labels.type() != CV_32S || labels.rows != geometry.height() ||
      labels.cols != geometry.width()) {
    throw InvalidArgument("room labels: expected a CV_32S image of " +
                          std::to_string(geometry.width()) + " x " +
                          std::to_string(geometry.height()) + " cells");
  }
  msg.info.resolution = static_cast<float>(geometry.resolution_m());
  msg.info.width = static_cast<std::uint32_t>(geometry.width());
  msg.info.height = static_cast<std::uint32_t>(geometry.height());
  msg.info.origin = toPoseMsg(Pose2{geometry.origin_m().x(), geometry.origin_m().y(), 0.0});
  msg.data.resize(static_cast<std::size_t>(geometry.width()) * geometry.height());
  std::size_t i = 0;
  for (int y = 0; y < labels.rows; ++y) {
    const int* row = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x, ++i) {
      msg.data[i] =
          row[x] <= 0 ? std::int8_t{-1} : static_cast<std::int8_t>((row[x] - 1) % 100 + 1);
    }
  }
}

Pose2 toPose2(const geometry_msgs::Pose& pose) {
  const auto& q = pose.orientation;
  return Pose2{pose.position.x, pose.position.y, yawOf(q.x, q.y, q.z, q.w)};
}

Pose2 toPose2(const geometry_msgs::Transform& transform) {
  const auto& q = transform.rotation;
  return Pose2{transform.translation.x, transform.translation.y, yawOf(q.x, q.y, q.z, q.w)};
}

geometry_msgs::Pose toPoseMsg(const Pose2& pose) {
  geometry_msgs::Pose p;
  p.position.x = pose.x_m;
  p.position.y = pose.y_m;
  p.position.z = 0.0;
  p.orientation.x = 0.0;
  p.orientation.y = 0.0;
  p.orientation.z = std::sin(0.5 * pose.yaw_rad);
  p.orientation.w = std::cos(0.5 * pose.yaw_rad);
  return p;
}

}  // namespace roomscout::ros1
