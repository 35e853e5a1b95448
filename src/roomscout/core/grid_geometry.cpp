#include "roomscout/core/grid_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"

namespace roomscout {

void CellRect::expandToInclude(Cell c) {
  if (empty()) {
    *this = {c.x, c.y, c.x + 1, c.y + 1};
    return;
  }
  min_x = std::min(min_x, c.x);
  min_y = std::min(min_y, c.y);
  max_x = std::max(max_x, c.x + 1);
  max_y = std::max(max_y, c.y + 1);
}

void CellRect::unite(const CellRect& other) {
  if (other.empty()) return;
  if (empty()) {
    *this = other;
    return;
  }
  min_x = std::min(min_x, other.min_x);
  min_y = std::min(min_y, other.min_y);
  max_x = std::max(max_x, other.max_x);
  max_y = std::max(max_y, other.max_y);
}

CellRect CellRect::clippedTo(int width, int height) const {
  return {std::max(min_x, 0), std::max(min_y, 0), std::min(max_x, width), std::min(max_y, height)};
}

GridGeometry::GridGeometry(const Vec2& origin_m, double resolution_m, int width, int height)
    : origin_m_(origin_m), resolution_m_(resolution_m), width_(width), height_(height) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw InvalidArgument("grid resolution must be a positive number of metres per cell");
  }
  if (width < 0 || height < 0) throw InvalidArgument("grid size must not be negative");
  if (!origin_m.allFinite()) throw InvalidArgument("grid origin must be finite");
}

}  // namespace roomscout
