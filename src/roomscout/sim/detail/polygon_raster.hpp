#pragma once
// Scanline rasterisation of polygons and wall rectangles onto a grid, shared by the 2D
// ground-truth rasters (WorldModel) and the 3D column world (ColumnWorld), so both agree on
// which raster cells a piece covers.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/sim/world.hpp"

namespace roomscout::sim {

/// Calls fn(x, y) for every cell of `g` whose centre lies inside `polygon_m` (even-odd rule),
/// by scanlines through the cell centres. Exact for any simple or self-touching polygon.
template <typename Fn>
void forEachCellInPolygon(const GridGeometry& g, const Polygon& polygon_m, Fn&& fn) {
  const std::size_t n = polygon_m.size();
  if (n < 3) return;
  std::vector<Vec2> q(n);
  double y_lo = std::numeric_limits<double>::infinity(), y_hi = -y_lo;
  for (std::size_t i = 0; i < n; ++i) {
    q[i] = (polygon_m[i] - g.origin_m()) / g.resolution_m();  // raster units, cell x spans [x, x+1)
    y_lo = std::min(y_lo, q[i].y());
    y_hi = std::max(y_hi, q[i].y());
  }
  const int row_lo = std::max(0, static_cast<int>(std::ceil(y_lo - 0.5)));
  const int row_hi = std::min(g.height() - 1, static_cast<int>(std::floor(y_hi - 0.5)));
  std::vector<double> crossings;
  for (int row = row_lo; row <= row_hi; ++row) {
    const double yc = row + 0.5;
    crossings.clear();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
      const Vec2& a = q[i];
      const Vec2& b = q[j];
      if ((a.y() > yc) != (b.y() > yc))
        crossings.push_back(a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      // cells whose centre x + 0.5 lies in [crossings[k], crossings[k+1])
      const int x0 = std::max(0, static_cast<int>(std::ceil(crossings[k] - 0.5)));
      const int x1 =
          std::min(g.width() - 1, static_cast<int>(std::ceil(crossings[k + 1] - 0.5)) - 1);
      for (int x = x0; x <= x1; ++x) fn(x, row);
    }
  }
}

/// Sets `value` in the cells of `raster` (rows x cols = g's height x width) that
/// forEachCellInPolygon visits.
template <typename T>
void fillPolygon(cv::Mat& raster, const GridGeometry& g, const Polygon& polygon_m, T value) {
  forEachCellInPolygon(g, polygon_m, [&](int x, int y) { raster.ptr<T>(y)[x] = value; });
}

/// The rectangle a wall occupies in the plane: `thickness_m` wide, centred on a-b.
inline Polygon wallRectangle(const Wall& w) {
  const Vec2 d = w.b_m - w.a_m;
  const double len = d.norm();
  const Vec2 n =
      len > 0 ? Vec2(Vec2(-d.y(), d.x()) / len * (w.thickness_m * 0.5)) : Vec2(Vec2::Zero());
  return {w.a_m - n, w.b_m - n, w.b_m + n, w.a_m + n};
}

}  // namespace roomscout::sim
