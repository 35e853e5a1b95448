#pragma once
// Per-cell state carried from one grid geometry to another by map position. A SLAM map
// (slam_toolbox, gmapping, Cartographer) grows while the robot explores and its origin moves
// as it grows; a strategy that keeps marks beside the map (visited cells, exhausted frontier
// cells) lays them onto each new geometry with these.

#include <cmath>
#include <optional>
#include <vector>

#include "roomscout/core/grid_geometry.hpp"

namespace roomscout {

/// `values` (one per cell of `from`, row-major) laid onto `to`: each cell of `to` takes the
/// value of the cell of `from` that holds its centre, `fill` where that lies off `from`. With the
/// same resolution and an origin a whole number of cells away, every value moves by that offset
/// exactly; with another resolution, the nearest old cell is taken. Values of another size than
/// `from` (never laid on it, e.g. empty) give `fill` everywhere.
template <class T>
std::vector<T> remapCells(const std::vector<T>& values, const GridGeometry& from,
                          const GridGeometry& to, T fill = T{}) {
  std::vector<T> out(to.cellCount(), fill);
  if (values.empty() || values.size() != from.cellCount()) return out;
  // The grids are axis-aligned: a column of `to` maps to one column of `from`, a row to a row.
  auto source = [](double origin_to, double origin_from, int i, double res_to, double res_from,
                   int n) {
    const int j =
        static_cast<int>(std::floor((origin_to + (i + 0.5) * res_to - origin_from) / res_from));
    return j >= 0 && j < n ? j : -1;
  };
  std::vector<int> column(static_cast<std::size_t>(to.width()));
  for (int x = 0; x < to.width(); ++x) {
    column[x] = source(to.origin_m().x(), from.origin_m().x(), x, to.resolution_m(),
                       from.resolution_m(), from.width());
  }
  for (int y = 0; y < to.height(); ++y) {
    const int fy = source(to.origin_m().y(), from.origin_m().y(), y, to.resolution_m(),
                          from.resolution_m(), from.height());
    if (fy < 0) continue;
    const std::size_t row = static_cast<std::size_t>(y) * to.width();
    const std::size_t from_row = static_cast<std::size_t>(fy) * from.width();
    for (int x = 0; x < to.width(); ++x) {
      if (column[x] >= 0) out[row + x] = values[from_row + column[x]];
    }
  }
  return out;
}

/// Remembers the geometry of the grid a strategy was last given, to tell when a new grid has
/// another one (GridGeometry's operator==: origin, resolution and size exactly).
class GeometryWatch {
 public:
  /// Records `geometry`; returns the one recorded before when it differs (never on the first call).
  std::optional<GridGeometry> update(const GridGeometry& geometry) {
    std::optional<GridGeometry> previous;
    if (seen_ && !(geometry == last_)) previous = last_;
    last_ = geometry;
    seen_ = true;
    return previous;
  }

 private:
  GridGeometry last_;
  bool seen_ = false;
};

/// The corner of `geometry` opposite its origin [m].
inline Vec2 farCorner(const GridGeometry& geometry) {
  return geometry.origin_m() + Vec2(geometry.width() * geometry.resolution_m(),
                                    geometry.height() * geometry.resolution_m());
}

}  // namespace roomscout
