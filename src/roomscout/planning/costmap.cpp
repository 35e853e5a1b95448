#include "roomscout/planning/costmap.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout {

namespace {

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
      {"robot_radius_m", &robot_radius_m, "robot footprint radius (TurtleBot3 Burger) [m]"},
      {"inflation_margin_m", &inflation_margin_m,
       "extra clearance beyond the robot radius that is still lethal [m]"},
      {"cost_scaling_distance_m", &cost_scaling_distance_m,
       "clearance under which the soft cost rises towards max_soft_cost [m]"},
      {"max_soft_cost", &max_soft_cost, "extra step cost at the lethal boundary (per cell step)"},
      {"unknown_cost", &unknown_cost, "extra step cost of entering an unknown cell"},
  };
}

Costmap::Costmap(const CostmapOptions& options) : options_(options) { options_.validate(); }

void Costmap::update(const OccupancyGrid& grid) { update(grid, grid.geometry().bounds()); }

void Costmap::update(const OccupancyGrid& grid, const CellRect& hint) {
  if (grid.geometry() != geometry_ || states_.size() != geometry_.cellCount()) {
    rebuild(grid);
    return;
  }
  // Only the cells whose state changed, and the clearance window around those that became or
  // stopped being obstacles, need recomputing.
  CellRect changed, obstacles_changed;
  const int w = geometry_.width();
  const int h = geometry_.height();
  const CellRect scan = hint.clippedTo(w, h);
  for (int y = scan.min_y; y < scan.max_y; ++y) {
    std::size_t i = static_cast<std::size_t>(y) * w + scan.min_x;
    for (int x = scan.min_x; x < scan.max_x; ++x, ++i) {
      const CellState s = grid.state(i);
      if (s == states_[i]) continue;
      if ((s == CellState::kOccupied) != (states_[i] == CellState::kOccupied)) {
        obstacles_changed.expandToInclude({x, y});
      }
      changed.expandToInclude({x, y});
      states_[i] = s;
    }
  }
  if (changed.empty()) return;
  if (!obstacles_changed.empty()) {
    // A cell's capped clearance depends only on obstacles within the cap.
    const int pad = static_cast<int>(std::ceil(maxClearance_m() / geometry_.resolution_m())) + 1;
    const CellRect window = CellRect{obstacles_changed.min_x - pad, obstacles_changed.min_y - pad,
                                     obstacles_changed.max_x + pad, obstacles_changed.max_y + pad}
                                .clippedTo(w, h);
    computeClearance(window);
    changed.unite(window);
  }
  computeCosts(changed);
}

void Costmap::rebuild(const OccupancyGrid& grid) {
  geometry_ = grid.geometry();
  const std::size_t n = geometry_.cellCount();
  lethal_.assign(n, 0);
  unknown_.assign(n, 0);
  step_cost_.assign(n, 1.0f);
  clearance_px_.assign(n, 0.0f);
  states_ = grid.states();
  if (n == 0) return;
  computeClearance(geometry_.bounds());
  computeCosts(geometry_.bounds());
}

void Costmap::computeClearance(const CellRect& rect) {
  const double resolution_m = geometry_.resolution_m();
  const float cap_px = static_cast<float>(maxClearance_m() / resolution_m);
  // The obstacles that can lie within the cap of a cell of `rect`.
  const int pad = static_cast<int>(std::ceil(maxClearance_m() / resolution_m)) + 1;
  const CellRect source =
      CellRect{rect.min_x - pad, rect.min_y - pad, rect.max_x + pad, rect.max_y + pad}.clippedTo(
          geometry_.width(), geometry_.height());
  const int sw = source.max_x - source.min_x;
  const int sh = source.max_y - source.min_y;
  cv::Mat mask(sh, sw, CV_8U);
  bool any_obstacle = false;
  for (int y = 0; y < sh; ++y) {
    const CellState* row = &states_[geometry_.index(Cell{source.min_x, source.min_y + y})];
    auto* out = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < sw; ++x) {
      const bool occupied = row[x] == CellState::kOccupied;
      out[x] = occupied ? 0 : 1;
      any_obstacle |= occupied;
    }
  }
  cv::Mat distance_px;
  if (any_obstacle)
    cv::distanceTransform(mask, distance_px, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  for (int y = rect.min_y; y < rect.max_y; ++y) {
    const float* d = any_obstacle ? distance_px.ptr<float>(y - source.min_y) : nullptr;
    float* out = &clearance_px_[geometry_.index(Cell{rect.min_x, y})];
    for (int x = rect.min_x; x < rect.max_x; ++x)
      out[x - rect.min_x] = d ? std::min(d[x - source.min_x], cap_px) : cap_px;
  }
}

void Costmap::computeCosts(const CellRect& rect) {
  const double resolution_m = geometry_.resolution_m();
  const double lethal_radius_m = options_.lethalRadius_m();
  const double scaling_m = options_.cost_scaling_distance_m;
  const float soft_per_m =
      static_cast<float>(options_.max_soft_cost / (scaling_m - lethal_radius_m));
  const float max_soft = static_cast<float>(options_.max_soft_cost);
  const float unknown_cost = static_cast<float>(options_.unknown_cost);
  for (int y = rect.min_y; y < rect.max_y; ++y) {
    std::size_t i = geometry_.index(Cell{rect.min_x, y});
    for (int x = rect.min_x; x < rect.max_x; ++x, ++i) {
      const double clearance_m = static_cast<double>(clearance_px_[i]) * resolution_m;
      const bool occupied = states_[i] == CellState::kOccupied;
      unknown_[i] = states_[i] == CellState::kUnknown ? 1 : 0;
      lethal_[i] = (occupied || clearance_m < lethal_radius_m) ? 1 : 0;
      const float soft =
          std::clamp(static_cast<float>(scaling_m - clearance_m) * soft_per_m, 0.0f, max_soft);
      step_cost_[i] = 1.0f + soft + (unknown_[i] ? unknown_cost : 0.0f);
    }
  }
}

}  // namespace roomscout
