#include "roomscout/core/geometry.hpp"

namespace roomscout {

double polygonArea(const Polygon& polygon) {
  double twice_area = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    twice_area += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  }
  return std::abs(twice_area) * 0.5;
}

}  // namespace roomscout
