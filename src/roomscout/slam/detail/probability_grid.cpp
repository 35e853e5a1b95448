#include "roomscout/slam/detail/probability_grid.hpp"

#include <algorithm>
#include <cmath>

namespace roomscout::slam::detail {

float ProbabilityGrid::probabilityOf(float log_odds) {
  if (log_odds == 0.0f) return static_cast<float>(kMinProbability);
  const double p = 1.0 / (1.0 + std::exp(-static_cast<double>(log_odds)));
  return static_cast<float>(std::clamp(p, kMinProbability, kMaxProbability));
}

ProbabilityGrid::ProbabilityGrid(const OccupancyGrid& grid)
    : geometry_(grid.geometry()), values_(grid.geometry().cellCount()) {
  for (std::size_t i = 0; i < values_.size(); ++i) values_[i] = probabilityOf(grid.logOdds(i));
}

void ProbabilityGrid::update(const OccupancyGrid& grid, const CellRect& rect) {
  const CellRect r = rect.clippedTo(geometry_.width(), geometry_.height());
  for (int y = r.min_y; y < r.max_y; ++y) {
    for (int x = r.min_x; x < r.max_x; ++x) {
      const std::size_t i = geometry_.index(Cell{x, y});
      values_[i] = probabilityOf(grid.logOdds(i));
    }
  }
}

}  // namespace roomscout::slam::detail
