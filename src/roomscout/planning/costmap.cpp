#include "roomscout/planning/costmap.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout {

namespace {

/// Clearance reported when the grid has no occupied cell at all [m].
constexpr double kNoObstacleClearance_m = 1e6;

bool finite(double v) { return std::isfinite(v); }

}  // namespace

void CostmapOptions::validate() const {
  if (!(finite(robot_radius_m) && robot_radius_m >= 0.0)) {
    throw OptionError("costmap.robot_radius_m must be a finite number >= 0");
  }
  if (!(finite(inflation_margin_m) && inflation_margin_m >= 0.0)) {
    throw OptionError("costmap.inflation_margin_m must be a finite number >= 0");
  }
  if (!(finite(cost_scaling_distance_m) && cost_scaling_distance_m > lethalRadius_m())) {
    throw OptionError(
        "costmap.cost_scaling_distance_m must be greater than robot_radius_m + "
        "inflation_margin_m (the lethal radius)");
  }
  if (!(finite(max_soft_cost) && max_soft_cost >= 0.0)) {
    throw OptionError("costmap.max_soft_cost must be a finite number >= 0");
  }
  if (!(finite(unknown_cost) && unknown_cost >= 0.0)) {
    throw OptionError("costmap.unknown_cost must be a finite number >= 0");
  }
}

std::vector<ParameterRef> CostmapOptions::parameters() {
  return {
      {"robot_radius_m", &robot_radius_m, "robot footprint radius [m]"},
      {"inflation_margin_m", &inflation_margin_m,
       "extra clearance beyond the robot radius that is still lethal [m]"},
      {"cost_scaling_distance_m", &cost_scaling_distance_m,
       "clearance under which the soft cost rises towards max_soft_cost [m]"},
      {"max_soft_cost", &max_soft_cost, "extra step cost at the lethal boundary (per cell step)"},
      {"unknown_cost", &unknown_cost, "extra step cost of entering an unknown cell"},
  };
}

Costmap::Costmap(const CostmapOptions& options) : options_(options) { options_.validate(); }

void Costmap::update(const OccupancyGrid& grid) {
  geometry_ = grid.geometry();
  const std::size_t n = geometry_.cellCount();
  lethal_.resize(n);
  unknown_.resize(n);
  step_cost_.resize(n);
  clearance_m_.resize(n);
  if (n == 0) return;

  // lethal_ doubles as the distance transform's input: 0 on obstacles, 1 elsewhere.
  bool any_obstacle = false;
  for (std::size_t i = 0; i < n; ++i) {
    const CellState s = grid.state(i);
    lethal_[i] = s == CellState::kOccupied ? 0 : 1;
    unknown_[i] = s == CellState::kUnknown ? 1 : 0;
    any_obstacle |= s == CellState::kOccupied;
  }

  const double resolution_m = geometry_.resolution_m();
  if (any_obstacle) {
    // Both Mats wrap our vectors, so the transform writes straight into clearance_m_.
    const cv::Mat mask(geometry_.height(), geometry_.width(), CV_8U, lethal_.data());
    cv::Mat distance_px(geometry_.height(), geometry_.width(), CV_32F, clearance_m_.data());
    cv::distanceTransform(mask, distance_px, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
    if (distance_px.data != reinterpret_cast<uchar*>(clearance_m_.data())) {
      throw std::logic_error("Costmap: distance transform reallocated its output");
    }
  } else {
    std::fill(clearance_m_.begin(), clearance_m_.end(),
              static_cast<float>(kNoObstacleClearance_m / resolution_m));
  }

  const double lethal_radius_m = options_.lethalRadius_m();
  const double scaling_m = options_.cost_scaling_distance_m;
  const float soft_per_m =
      static_cast<float>(options_.max_soft_cost / (scaling_m - lethal_radius_m));
  const float max_soft = static_cast<float>(options_.max_soft_cost);
  const float unknown_cost = static_cast<float>(options_.unknown_cost);
  for (std::size_t i = 0; i < n; ++i) {
    const double clearance_m = static_cast<double>(clearance_m_[i]) * resolution_m;
    clearance_m_[i] = static_cast<float>(clearance_m);
    const bool occupied = lethal_[i] == 0;
    lethal_[i] = (occupied || clearance_m < lethal_radius_m) ? 1 : 0;
    const float soft =
        std::clamp(static_cast<float>(scaling_m - clearance_m) * soft_per_m, 0.0f, max_soft);
    step_cost_[i] = 1.0f + soft + (unknown_[i] ? unknown_cost : 0.0f);
  }
}

}  // namespace roomscout
