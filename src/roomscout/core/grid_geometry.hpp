#pragma once
// Where a regular grid lies in the map frame: origin, resolution and size.

#include <cmath>
#include <cstdint>

#include "roomscout/core/geometry.hpp"

namespace roomscout {

/// Integer cell coordinates; x grows with the map's x axis, y with its y axis (row 0 is the
/// bottom row, as in ROS nav_msgs/OccupancyGrid).
struct Cell {
  int x = 0;
  int y = 0;
  // Written out rather than defaulted: the ROS 1 nodes include this header as C++17.
  friend bool operator==(const Cell& a, const Cell& b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }
};

/// Axis-aligned rectangle of cells, [min, max) on both axes. Empty when min >= max.
struct CellRect {
  int min_x = 0, min_y = 0, max_x = 0, max_y = 0;
  bool empty() const { return min_x >= max_x || min_y >= max_y; }
  void expandToInclude(Cell c);
  /// Grows to cover `other` too (an empty rectangle changes nothing).
  void unite(const CellRect& other);
  /// The part inside [0, width) x [0, height).
  CellRect clippedTo(int width, int height) const;
};

/// Geometry of a grid: cell (0,0) has its lower-left corner at `origin_m`.
class GridGeometry {
 public:
  GridGeometry() = default;
  /// @param origin_m lower-left corner of cell (0,0) in the map frame [m]
  /// @param resolution_m cell side [m/cell], > 0
  /// @param width, height size in cells, >= 0
  GridGeometry(const Vec2& origin_m, double resolution_m, int width, int height);

  const Vec2& origin_m() const { return origin_m_; }
  double resolution_m() const { return resolution_m_; }
  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t cellCount() const { return static_cast<std::size_t>(width_) * height_; }

  bool contains(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  bool contains(const Vec2& p_m) const { return contains(cellOf(p_m)); }
  /// Row-major index of a cell inside the grid.
  std::size_t index(Cell c) const { return static_cast<std::size_t>(c.y) * width_ + c.x; }
  Cell cellAt(std::size_t index) const {
    return {static_cast<int>(index % width_), static_cast<int>(index / width_)};
  }
  /// The cell containing `p_m` (may lie outside the grid).
  Cell cellOf(const Vec2& p_m) const {
    return {static_cast<int>(std::floor((p_m.x() - origin_m_.x()) / resolution_m_)),
            static_cast<int>(std::floor((p_m.y() - origin_m_.y()) / resolution_m_))};
  }
  /// Centre of a cell in the map frame [m].
  Vec2 centerOf(Cell c) const {
    return {origin_m_.x() + (c.x + 0.5) * resolution_m_,
            origin_m_.y() + (c.y + 0.5) * resolution_m_};
  }
  CellRect bounds() const { return {0, 0, width_, height_}; }

  friend bool operator==(const GridGeometry& a, const GridGeometry& b) {
    return a.origin_m_ == b.origin_m_ && a.resolution_m_ == b.resolution_m_ &&
           a.width_ == b.width_ && a.height_ == b.height_;
  }
  friend bool operator!=(const GridGeometry& a, const GridGeometry& b) { return !(a == b); }

 private:
  Vec2 origin_m_ = Vec2::Zero();
  double resolution_m_ = 0.05;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace roomscout
