#include "roomscout/sim/world_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/core/grid_limits.hpp"
#include "roomscout/sim/detail/polygon_raster.hpp"

namespace roomscout::sim {

void WorldModelOptions::validate() const {
  if (!(raster_resolution_m > 0.0)) throw OptionError("world.raster_resolution_m must be > 0");
  if (!(laser_height_m > 0.0)) throw OptionError("world.laser_height_m must be > 0");
  if (!(robot_height_m > 0.0)) throw OptionError("world.robot_height_m must be > 0");
  if (!(robot_radius_m > 0.0)) throw OptionError("world.robot_radius_m must be > 0");
}

std::vector<ParameterRef> WorldModelOptions::parameters() {
  return {
      {"raster_resolution_m", &raster_resolution_m,
       "ground-truth raster cell of geometric worlds [m] (image worlds use their own pixel size)"},
      {"laser_height_m", &laser_height_m, "height of the 2D laser plane above the floor [m]"},
      {"robot_height_m", &robot_height_m, "objects whose bottom is below this block the robot [m]"},
      {"robot_radius_m", &robot_radius_m,
       "robot footprint radius, for clearance queries and the start pose choice [m]"},
  };
}

namespace {

bool spans(double z_min, double z_max, double z) { return z_min <= z && z <= z_max; }

}  // namespace

WorldModel::WorldModel(const World& world, const WorldModelOptions& options)
    : world_(world), options_(options) {
  options_.validate();
  if (world_.image) {
    rasterizeImage();
  } else {
    rasterizeGeometry();
  }
  has_rooms_ = std::any_of(room_labels_.begin(), room_labels_.end(),
                           [](std::int32_t id) { return id != 0; });
  computeClearance();
  chooseStart();
}

void WorldModel::rasterizeGeometry() {
  if (world_.walls.empty()) throw InputError(world_.source, "the world has no walls");
  const double res = options_.raster_resolution_m;
  auto [lo, hi] = world_.bounds();
  constexpr double kPad_m = 0.5;
  // Origin on a multiple of 0.05 m so that map grids of 0.05/0.1 m align with the raster.
  const Vec2 origin(std::floor((lo.x() - kPad_m) / 0.05) * 0.05,
                    std::floor((lo.y() - kPad_m) / 0.05) * 0.05);
  const double width_cells = std::ceil((hi.x() + kPad_m - origin.x()) / res);
  const double height_cells = std::ceil((hi.y() + kPad_m - origin.y()) / res);
  checkGridSize(world_.source, "world raster", width_cells, height_cells, res,
                "world.raster_resolution_m");
  const int width = static_cast<int>(width_cells);
  const int height = static_cast<int>(height_cells);
  geometry_ = GridGeometry(origin, res, width, height);

  cv::Mat laser = cv::Mat::zeros(height, width, CV_8U);
  cv::Mat robot = cv::Mat::zeros(height, width, CV_8U);
  auto add = [&](const Polygon& poly, double z_min, double z_max) {
    if (spans(z_min, z_max, options_.laser_height_m))
      fillPolygon<std::uint8_t>(laser, geometry_, poly, 1);
    if (z_min < options_.robot_height_m) fillPolygon<std::uint8_t>(robot, geometry_, poly, 1);
  };
  for (const Wall& w : world_.walls) add(wallRectangle(w), w.z_min_m, w.z_max_m);
  for (const FurniturePiece& f : world_.furniture) add(f.footprint_m, f.z_min_m, f.z_max_m);

  cv::Mat rooms = cv::Mat::zeros(height, width, CV_32S);
  for (const Room& r : world_.rooms) fillPolygon<std::int32_t>(rooms, geometry_, r.polygon_m, r.id);

  laser_solid_.assign(laser.datastart, laser.dataend);
  robot_solid_.assign(robot.datastart, robot.dataend);
  room_labels_.assign(reinterpret_cast<const std::int32_t*>(rooms.datastart),
                      reinterpret_cast<const std::int32_t*>(rooms.dataend));
}

void WorldModel::rasterizeImage() {
  const ImageWorld& img = *world_.image;
  if (img.solid.empty() || img.solid.type() != CV_8U) {
    throw InputError(world_.source, "the world image is empty");
  }
  checkGridSize(world_.source, "world image", img.solid.cols, img.solid.rows, img.resolution_m);
  geometry_ = GridGeometry(img.origin_m, img.resolution_m, img.solid.cols, img.solid.rows);
  cv::Mat solid;
  cv::flip(img.solid, solid, 0);  // image row 0 is the top; grid row 0 is the bottom
  cv::threshold(solid, solid, 0, 1, cv::THRESH_BINARY);
  laser_solid_.assign(solid.datastart, solid.dataend);
  robot_solid_ = laser_solid_;
  room_labels_.assign(geometry_.cellCount(), 0);
  if (!img.room_labels.empty()) {
    cv::Mat labels;
    cv::flip(img.room_labels, labels, 0);
    room_labels_.assign(reinterpret_cast<const std::int32_t*>(labels.datastart),
                        reinterpret_cast<const std::int32_t*>(labels.dataend));
  }
}

void WorldModel::computeClearance() {
  cv::Mat free_mask(geometry_.height(), geometry_.width(), CV_8U);
  for (std::size_t i = 0; i < robot_solid_.size(); ++i) {
    free_mask.data[i] = robot_solid_[i] ? 0 : 255;
  }
  // The border counts as solid so the robot never leaves the raster.
  cv::rectangle(free_mask, cv::Rect(0, 0, free_mask.cols, free_mask.rows), cv::Scalar(0), 1);
  cv::Mat dist;
  cv::distanceTransform(free_mask, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const float res = static_cast<float>(geometry_.resolution_m());
  clearance_m_.resize(geometry_.cellCount());
  const float* d = dist.ptr<float>();
  for (std::size_t i = 0; i < clearance_m_.size(); ++i) {
    clearance_m_[i] = d[i] > 0.0f ? (d[i] - 0.5f) * res : 0.0f;
  }
}

double WorldModel::clearance_m(const Vec2& p_m) const {
  const Cell c = geometry_.cellOf(p_m);
  return geometry_.contains(c) ? clearance_m_[geometry_.index(c)] : 0.0;
}

int WorldModel::roomAt(const Vec2& p_m) const {
  const Cell c = geometry_.cellOf(p_m);
  return geometry_.contains(c) ? room_labels_[geometry_.index(c)] : 0;
}

void WorldModel::chooseStart() {
  const int w = geometry_.width(), h = geometry_.height();
  cv::Mat free_mask(h, w, CV_8U);
  for (std::size_t i = 0; i < robot_solid_.size(); ++i) {
    free_mask.data[i] = (robot_solid_[i] || laser_solid_[i]) ? 0 : 255;
  }
  if (cv::countNonZero(free_mask) == 0)
    throw InputError(world_.source, "the world has no free space");

  if (world_.start_given) {
    start_ = world_.start;
    const Vec2 p = start_.position();
    if (!geometry_.contains(p)) {
      throw InputError(world_.source, "start pose " + formatPoint(p) + " is outside the map");
    }
    if (!robotFits(p)) {
      throw InputError(world_.source, "start pose " + formatPoint(p) +
                                          " is inside or too close to a wall or furniture");
    }
  } else {
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(free_mask, labels, stats, centroids, 8, CV_32S);
    int largest = 1;
    for (int k = 2; k < n; ++k) {
      if (stats.at<int>(k, cv::CC_STAT_AREA) > stats.at<int>(largest, cv::CC_STAT_AREA))
        largest = k;
    }
    std::size_t best = 0;
    float best_clearance = -1.0f;
    const int* lab = labels.ptr<int>();
    for (std::size_t i = 0; i < clearance_m_.size(); ++i) {
      if (lab[i] == largest && clearance_m_[i] > best_clearance) {
        best_clearance = clearance_m_[i];
        best = i;
      }
    }
    if (best_clearance < options_.robot_radius_m) {
      throw InputError(world_.source, "no free place is wide enough for the robot (radius " +
                                          std::to_string(options_.robot_radius_m) + " m)");
    }
    const Vec2 p = geometry_.centerOf(geometry_.cellAt(best));
    start_ = Pose2{p.x(), p.y(), 0.0};
  }

  // Free floor connected to the start (4-neighbours).
  cv::Mat mask = cv::Mat::zeros(h + 2, w + 2, CV_8U);
  const Cell s = geometry_.cellOf(start_.position());
  const int filled = cv::floodFill(free_mask, mask, cv::Point(s.x, s.y), cv::Scalar(128), nullptr,
                                   cv::Scalar(0), cv::Scalar(0), 4 | cv::FLOODFILL_MASK_ONLY);
  free_area_m2_ = filled * geometry_.resolution_m() * geometry_.resolution_m();
}

}  // namespace roomscout::sim
