#include "roomscout/core/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout {

void OccupancyGridOptions::validate() const {
  if (!(resolution_m > 0.0)) throw OptionError("mapping.resolution_m must be > 0");
  if (!(log_odds_hit > 0.0)) throw OptionError("mapping.log_odds_hit must be > 0");
  if (!(log_odds_miss < 0.0)) throw OptionError("mapping.log_odds_miss must be < 0");
  if (!(log_odds_min < free_threshold && free_threshold < 0.0 && 0.0 < occupied_threshold &&
        occupied_threshold < log_odds_max)) {
    throw OptionError(
        "mapping thresholds must satisfy log_odds_min < free_threshold < 0 < "
        "occupied_threshold < log_odds_max");
  }
}

std::vector<ParameterRef> OccupancyGridOptions::parameters() {
  return {
      {"resolution_m", &resolution_m, "cell side [m]"},
      {"log_odds_hit", &log_odds_hit, "log-odds added at a beam end point"},
      {"log_odds_miss", &log_odds_miss, "log-odds added to cells a beam crosses"},
      {"log_odds_min", &log_odds_min, "lower clamp of a cell's log-odds"},
      {"log_odds_max", &log_odds_max, "upper clamp of a cell's log-odds"},
      {"occupied_threshold", &occupied_threshold, "log-odds above which a cell is occupied"},
      {"free_threshold", &free_threshold, "log-odds below which a cell is free"},
  };
}

OccupancyGrid::OccupancyGrid(const GridGeometry& geometry, const OccupancyGridOptions& options)
    : geometry_(geometry), options_(options), log_odds_(geometry.cellCount(), 0.0f),
      states_(geometry.cellCount(), CellState::kUnknown) {
  options_.validate();
  hit_ = static_cast<float>(options_.log_odds_hit);
  miss_ = static_cast<float>(options_.log_odds_miss);
  min_ = static_cast<float>(options_.log_odds_min);
  max_ = static_cast<float>(options_.log_odds_max);
  occupied_threshold_ = static_cast<float>(options_.occupied_threshold);
  free_threshold_ = static_cast<float>(options_.free_threshold);
}

void OccupancyGrid::setState(std::size_t index, CellState state) {
  switch (state) {
    case CellState::kUnknown: log_odds_[index] = 0.0f; break;
    case CellState::kFree: log_odds_[index] = min_; break;
    case CellState::kOccupied: log_odds_[index] = max_; break;
  }
  states_[index] = classify(log_odds_[index]);
}

}  // namespace roomscout
