#include "roomscout/core/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

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
      {"log_odds_hit", &log_odds_hit,
       "log-odds added at a beam end point (p = 0.83; worth almost four misses, so that wall cells "
       "grazing beams cross stay occupied)"},
      {"log_odds_miss", &log_odds_miss, "log-odds added to cells a beam crosses (p = 0.40)"},
      {"log_odds_min", &log_odds_min,
       "lower clamp of a cell's log-odds, so that a cell can change its mind"},
      {"log_odds_max", &log_odds_max, "upper clamp of a cell's log-odds"},
      {"occupied_threshold", &occupied_threshold,
       "log-odds above which a cell is occupied (p > 0.65)"},
      {"free_threshold", &free_threshold,
       "log-odds below which a cell is free (p < 0.41: one scan's miss)"},
  };
}

OccupancyGrid::OccupancyGrid(const GridGeometry& geometry, const OccupancyGridOptions& options)
    : geometry_(geometry),
      options_(options),
      log_odds_(geometry.cellCount(), 0.0f),
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
    case CellState::kUnknown:
      log_odds_[index] = 0.0f;
      break;
    case CellState::kFree:
      log_odds_[index] = min_;
      break;
    case CellState::kOccupied:
      log_odds_[index] = max_;
      break;
  }
  states_[index] = classify(log_odds_[index]);
}

Cell OccupancyGrid::latticeOffset(const GridGeometry& other) const {
  const double res = geometry_.resolution_m();
  if (std::abs(other.resolution_m() - res) > 1e-9 * res) {
    throw InvalidArgument("grid of resolution " + std::to_string(other.resolution_m()) +
                          " m laid on a map of resolution " + std::to_string(res) + " m");
  }
  const Vec2 shift_cells = (other.origin_m() - geometry_.origin_m()) / res;
  const double sx = std::round(shift_cells.x()), sy = std::round(shift_cells.y());
  if (std::abs(shift_cells.x() - sx) > 1e-6 || std::abs(shift_cells.y() - sy) > 1e-6) {
    throw InvalidArgument("grid origin is not a whole number of cells from the map's");
  }
  return {static_cast<int>(sx), static_cast<int>(sy)};
}

OccupancyGrid OccupancyGrid::reframed(const GridGeometry& geometry) const {
  const Cell d = latticeOffset(geometry);
  // Keep this grid's origin exactly where the lattices coincide, so that cellOf() agrees.
  const double res = geometry_.resolution_m();
  const GridGeometry aligned(geometry_.origin_m() + Vec2(d.x * res, d.y * res), res,
                             geometry.width(), geometry.height());
  OccupancyGrid out(aligned, options_);
  out.copyCells(*this, geometry_.bounds());
  return out;
}

void OccupancyGrid::copyCells(const OccupancyGrid& source, const CellRect& rect) {
  // Source cell (x, y) lands on this grid's cell (x - d.x, y - d.y).
  const Cell d = source.latticeOffset(geometry_);
  const CellRect in_source = rect.clippedTo(source.geometry_.width(), source.geometry_.height());
  const int x0 = std::max(in_source.min_x, d.x),
            x1 = std::min(in_source.max_x, d.x + geometry_.width());
  const int y0 = std::max(in_source.min_y, d.y),
            y1 = std::min(in_source.max_y, d.y + geometry_.height());
  for (int y = y0; y < y1 && x0 < x1; ++y) {
    const std::size_t from = source.geometry_.index({x0, y});
    const std::size_t to = geometry_.index({x0 - d.x, y - d.y});
    std::copy_n(source.log_odds_.begin() + from, x1 - x0, log_odds_.begin() + to);
    std::copy_n(source.states_.begin() + from, x1 - x0, states_.begin() + to);
  }
}

}  // namespace roomscout
