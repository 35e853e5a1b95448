#include "roomscout/exploration/detail/slivers.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout {

void SliverOptions::validate() const {
  auto finiteAtLeast = [](double v, double lo) { return std::isfinite(v) && v >= lo; };
  if (!finiteAtLeast(min_unknown_m2, 0.0))
    throw OptionError("semantic.min_unknown_m2 must be >= 0");
  if (!finiteAtLeast(pocket_area_m2, 0.0))
    throw OptionError("semantic.pocket_area_m2 must be >= 0");
  if (!finiteAtLeast(pocket_area_fraction, 0.0)) {
    throw OptionError("semantic.pocket_area_fraction must be >= 0");
  }
  if (!finiteAtLeast(min_frontier_m, 0.0))
    throw OptionError("semantic.min_frontier_m must be >= 0");
}

int SliverOptions::frontierCellsWanted(double resolution_m) const {
  return static_cast<int>(std::lround(min_frontier_m / resolution_m));
}

double SliverOptions::pocketArea_m2(const OccupancyGrid& grid, bool idle) const {
  if (!idle || pocket_area_fraction <= 0.0) return pocket_area_m2;
  const std::uint8_t* states = grid.stateBytes();
  const auto free_value = static_cast<std::uint8_t>(CellState::kFree);
  const auto free_cells = std::count(states, states + grid.geometry().cellCount(), free_value);
  const double res = grid.geometry().resolution_m();
  const double free_m2 = static_cast<double>(free_cells) * res * res;
  return std::min(pocket_area_m2, pocket_area_fraction * free_m2);
}

SquareAreas squareAreas(const OccupancyGrid& grid, const Vec2& p, double half_m, int frontier_cap) {
  const GridGeometry& g = grid.geometry();
  const Cell c = g.cellOf(p);
  const int r = static_cast<int>(std::lround(half_m / g.resolution_m()));
  const int w = g.width();
  const int x0 = std::max(0, c.x - r), x1 = std::min(w - 1, c.x + r);
  const int y0 = std::max(0, c.y - r), y1 = std::min(g.height() - 1, c.y + r);
  int unknown = 0, occupied = 0, frontier = 0;
  for (int y = y0; y <= y1; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * w;
    for (int x = x0; x <= x1; ++x) {
      const CellState s = grid.state(row + x);
      unknown += s == CellState::kUnknown;
      occupied += s == CellState::kOccupied;
    }
  }
  // Rows from the centre outwards: a frontier point's own frontier is near it, so a square
  // with enough frontier is usually told after a few rows.
  for (int k = 0; frontier < frontier_cap && k <= 2 * r; ++k) {
    const int y = c.y + (k % 2 == 0 ? k / 2 : -(k + 1) / 2);
    if (y < std::max(1, y0) || y > std::min(g.height() - 2, y1)) continue;
    for (int x = std::max(1, x0); x <= std::min(w - 2, x1) && frontier < frontier_cap; ++x) {
      frontier += freeBesideUnknown(grid, x, y);
    }
  }
  const double cell_m2 = g.resolution_m() * g.resolution_m();
  return {unknown * cell_m2, occupied * cell_m2, frontier};
}

bool exhausted(const SquareAreas& a, const SliverOptions& o, double min_unknown_m2,
               double resolution_m) {
  return a.unknown_m2 < min_unknown_m2 || a.frontier_cells < o.frontierCellsWanted(resolution_m);
}

}  // namespace roomscout
