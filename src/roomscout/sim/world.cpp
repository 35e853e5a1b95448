#include "roomscout/sim/world.hpp"

#include <algorithm>
#include <limits>

namespace roomscout::sim {

std::pair<Vec2, Vec2> World::bounds() const {
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = -lo;
  auto include = [&](const Vec2& p, double pad) {
    lo = lo.cwiseMin(p - Vec2::Constant(pad));
    hi = hi.cwiseMax(p + Vec2::Constant(pad));
  };
  for (const Wall& w : walls) {
    include(w.a_m, w.thickness_m * 0.5);
    include(w.b_m, w.thickness_m * 0.5);
  }
  for (const FurniturePiece& f : furniture) {
    for (const Vec2& p : f.footprint_m) include(p, 0.0);
  }
  for (const Room& r : rooms) {
    for (const Vec2& p : r.polygon_m) include(p, 0.0);
  }
  if (image) {
    include(image->origin_m, 0.0);
    include(image->origin_m + Vec2(image->solid.cols, image->solid.rows) * image->resolution_m,
            0.0);
  }
  if (!(lo.x() <= hi.x())) return {Vec2::Zero(), Vec2::Zero()};
  return {lo, hi};
}

}  // namespace roomscout::sim
