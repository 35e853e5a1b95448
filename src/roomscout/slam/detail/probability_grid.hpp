#pragma once
// What a scan matcher reads of a submap: the probability that each cell is occupied, with
// unknown cells (and everything outside the grid) at the lowest value, so a scan point is
// drawn to cells seen as walls, never to cells nobody has seen. Kept in step with the submap
// incrementally; read bicubically by Ceres (the Grid2D interface) and cell by cell by the
// correlative search.

#include <cstdint>
#include <vector>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::slam::detail {

class ProbabilityGrid {
 public:
  static constexpr double kMinProbability = 0.1;  ///< unknown, and the floor of free cells
  static constexpr double kMaxProbability = 0.9;

  ProbabilityGrid() = default;
  /// A view of all of `grid`.
  explicit ProbabilityGrid(const OccupancyGrid& grid);
  /// Refreshes the cells of `rect` (cells of `grid`, whose geometry must be unchanged).
  void update(const OccupancyGrid& grid, const CellRect& rect);

  const GridGeometry& geometry() const { return geometry_; }
  /// The probability of cell (x, y); kMinProbability outside the grid.
  double at(int x, int y) const {
    if (x < 0 || y < 0 || x >= geometry_.width() || y >= geometry_.height()) return kMinProbability;
    return values_[static_cast<std::size_t>(y) * geometry_.width() + x];
  }
  /// The probability at a point of the grid's frame, read from the cell it lies in.
  double atPoint(const Vec2& p) const {
    const Cell c = geometry_.cellOf(p);
    return at(c.x, c.y);
  }

  /// ceres::Grid2D's interface (row = y, column = x): lets ceres::BiCubicInterpolator read the
  /// grid with cell centres at integer coordinates.
  enum { DATA_DIMENSION = 1 };
  void GetValue(int row, int col, double* f) const { *f = at(col, row); }

  /// Probability of a log-odds value (0 = unknown -> kMinProbability).
  static float probabilityOf(float log_odds);

 private:
  GridGeometry geometry_;
  std::vector<float> values_;
};

}  // namespace roomscout::slam::detail
