#include "roomscout/core/geometry.hpp"

namespace roomscout {

bool pointInPolygon(const Polygon& polygon, const Vec2& p) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x_cross = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x_cross) inside = !inside;
    }
  }
  return inside;
}

double polygonArea(const Polygon& polygon) {
  double twice_area = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    twice_area += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  }
  return std::abs(twice_area) * 0.5;
}

}  // namespace roomscout
