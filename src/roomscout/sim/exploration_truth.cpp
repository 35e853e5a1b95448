#include "roomscout/sim/exploration_truth.hpp"

#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/grid_limits.hpp"

namespace roomscout::sim {

GridGeometry mapGeometryFor(const WorldModel& world, double resolution_m) {
  const GridGeometry& r = world.geometry();
  const double width = std::ceil(r.width() * r.resolution_m() / resolution_m - 1e-9);
  const double height = std::ceil(r.height() * r.resolution_m() / resolution_m - 1e-9);
  checkGridSize(world.world().source, "explored map", width, height, resolution_m,
                "mapping.resolution_m");
  return GridGeometry(r.origin_m(), resolution_m, static_cast<int>(width),
                      static_cast<int>(height));
}

ExplorationTruth::ExplorationTruth(const WorldModel& world, const GridGeometry& map_geometry,
                                   double robot_radius_m)
    : geometry_(map_geometry) {
  const GridGeometry& raster = world.geometry();
  if ((raster.origin_m() - map_geometry.origin_m()).norm() > 1e-9) {
    throw InvalidArgument("map grid and world raster must share their origin");
  }
  const int w = geometry_.width(), h = geometry_.height();
  const double ratio = geometry_.resolution_m() / raster.resolution_m();
  const auto& laser = world.laserSolid();
  const auto& robot = world.robotSolid();

  // A map cell is truly free when every raster cell it overlaps is free (and inside).
  cv::Mat free_mask = cv::Mat::zeros(h, w, CV_8U);
  for (int y = 0; y < h; ++y) {
    const int ry0 = static_cast<int>(std::floor(y * ratio + 1e-9));
    const int ry1 = static_cast<int>(std::ceil((y + 1) * ratio - 1e-9));
    for (int x = 0; x < w; ++x) {
      const int rx0 = static_cast<int>(std::floor(x * ratio + 1e-9));
      const int rx1 = static_cast<int>(std::ceil((x + 1) * ratio - 1e-9));
      bool free = rx1 <= raster.width() && ry1 <= raster.height();
      for (int ry = ry0; free && ry < ry1; ++ry) {
        for (int rx = rx0; rx < rx1; ++rx) {
          const std::size_t i = raster.index({rx, ry});
          if (laser[i] || robot[i]) {
            free = false;
            break;
          }
        }
      }
      free_mask.at<std::uint8_t>(y, x) = free ? 255 : 0;
    }
  }
  truly_free_.assign(free_mask.datastart, free_mask.dataend);
  for (auto& v : truly_free_) v = v ? 1 : 0;

  // Centres where the robot disc fits: clearance to the nearest non-free cell >= radius.
  const double res = geometry_.resolution_m();
  cv::Mat padded;
  cv::copyMakeBorder(free_mask, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::Mat dist;
  cv::distanceTransform(padded, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  cv::Mat centres = cv::Mat::zeros(h, w, CV_8U);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double clearance = (dist.at<float>(y + 1, x + 1) - 0.5) * res;
      if (clearance >= robot_radius_m) centres.at<std::uint8_t>(y, x) = 255;
    }
  }
  // Keep the centres connected to the start (or to the nearest centre to it).
  const Cell s = geometry_.cellOf(world.start().position());
  cv::Point seed(-1, -1);
  double best = std::numeric_limits<double>::infinity();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!centres.at<std::uint8_t>(y, x)) continue;
      const double d = std::hypot(x - s.x, y - s.y);
      if (d < best) {
        best = d;
        seed = {x, y};
      }
    }
  }
  if (seed.x < 0) return;  // nothing reachable: rate is defined as 0
  cv::Mat mask = cv::Mat::zeros(h + 2, w + 2, CV_8U);
  cv::floodFill(centres, mask, seed, cv::Scalar(255), nullptr, cv::Scalar(0), cv::Scalar(0),
                8 | cv::FLOODFILL_MASK_ONLY | (255 << 8));
  cv::Mat reachable_centres = mask(cv::Rect(1, 1, w, h));

  // Cells the disc covers from some reachable centre: within radius (+ half a cell) of one.
  cv::Mat not_centre;
  cv::bitwise_not(reachable_centres, not_centre);
  cv::Mat centre_dist;
  cv::distanceTransform(not_centre, centre_dist, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const double reach_cells = robot_radius_m / res + 0.5;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (free_mask.at<std::uint8_t>(y, x) && centre_dist.at<float>(y, x) <= reach_cells) {
        reachable_.push_back(static_cast<std::uint32_t>(geometry_.index({x, y})));
      }
    }
  }
}

double ExplorationTruth::reachableArea_m2() const {
  return static_cast<double>(reachable_.size()) * geometry_.resolution_m() *
         geometry_.resolution_m();
}

double ExplorationTruth::explorationRate(const OccupancyGrid& grid) const {
  if (reachable_.empty()) return 0.0;
  std::size_t known = 0;
  for (std::uint32_t i : reachable_) known += grid.isUnknown(i) ? 0 : 1;
  return static_cast<double>(known) / static_cast<double>(reachable_.size());
}

ExplorationRateCounter::ExplorationRateCounter(const ExplorationTruth& truth)
    : truth_(truth),
      reachable_(truth.geometry().cellCount(), 0),
      counted_(truth.geometry().cellCount(), 0) {
  for (std::uint32_t i : truth.reachableCells()) reachable_[i] = 1;
}

void ExplorationRateCounter::update(const OccupancyGrid& grid, const CellRect& changed) {
  const GridGeometry& g = truth_.geometry();
  const CellRect r = changed.clippedTo(g.width(), g.height());
  for (int y = r.min_y; y < r.max_y; ++y) {
    std::size_t i = g.index({r.min_x, y});
    for (int x = r.min_x; x < r.max_x; ++x, ++i) {
      if (!reachable_[i]) continue;
      const std::uint8_t now = grid.isUnknown(i) ? 0 : 1;
      if (now != counted_[i]) {
        known_ = now ? known_ + 1 : known_ - 1;
        counted_[i] = now;
      }
    }
  }
}

double ExplorationRateCounter::rate() const {
  const std::size_t n = truth_.reachableCells().size();
  return n == 0 ? 0.0 : static_cast<double>(known_) / static_cast<double>(n);
}

}  // namespace roomscout::sim
