#include "roomscout/sim/start_pose.hpp"

#include <algorithm>
#include <numbers>
#include <random>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/random.hpp"

namespace roomscout::sim {
namespace {

/// Clearance beyond the robot's radius that a cell needs to connect a start to the world's
/// own start: the costmap's inflation margin and a little more, so that no start lies in a
/// pocket the planner cannot leave.
constexpr double kConnectMargin_m = 0.1;

}  // namespace

Pose2 randomStartPose(const WorldModel& model, std::uint64_t seed, double min_clearance_m) {
  const GridGeometry& g = model.geometry();
  const int w = g.width(), h = g.height();
  const double connect_m = model.options().robot_radius_m + kConnectMargin_m;
  const std::vector<float>& clearance = model.clearanceMap_m();
  cv::Mat passable(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (clearance[static_cast<std::size_t>(y) * w + x] >= connect_m)
        passable.at<std::uint8_t>(y, x) = 255;
    }
  }
  const Cell s = g.cellOf(model.start().position());
  if (!g.contains(s) || passable.at<std::uint8_t>(s.y, s.x) == 0) return model.start();
  cv::Mat mask = cv::Mat::zeros(h + 2, w + 2, CV_8U);
  cv::floodFill(passable, mask, cv::Point(s.x, s.y), cv::Scalar(128), nullptr, cv::Scalar(0),
                cv::Scalar(0), 4 | cv::FLOODFILL_MASK_ONLY | (1 << 8));
  std::vector<Cell> cells;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (mask.at<std::uint8_t>(y + 1, x + 1) &&
          clearance[static_cast<std::size_t>(y) * w + x] >= min_clearance_m) {
        cells.push_back(Cell{x, y});
      }
    }
  }
  if (cells.empty()) return model.start();
  std::mt19937_64 rng(seed ^ 0x9E3779B97F4A7C15ull);
  const std::size_t pick =
      std::min(cells.size() - 1, static_cast<std::size_t>(unitDouble(rng) * cells.size()));
  const Vec2 p = g.centerOf(cells[pick]);
  const double yaw = (2.0 * unitDouble(rng) - 1.0) * std::numbers::pi;
  return Pose2{p.x(), p.y(), yaw};
}

}  // namespace roomscout::sim
