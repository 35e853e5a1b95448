#include "roomscout/sim/column_world.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/sim/detail/polygon_raster.hpp"

namespace roomscout::sim {

namespace {

struct CellInterval {
  std::uint32_t cell;
  ZInterval z;
};

}  // namespace

ColumnWorld::ColumnWorld(const WorldModel& world)
    : geometry_(world.geometry()), ceiling_m_(world.world().wall_height_m) {
  const World& w = world.world();
  std::vector<CellInterval> pieces;
  auto add = [&](const Polygon& footprint, double z_min, double z_max) {
    const ZInterval z{static_cast<float>(z_min), static_cast<float>(z_max)};
    forEachCellInPolygon(geometry_, footprint, [&](int x, int y) {
      pieces.push_back({static_cast<std::uint32_t>(geometry_.index({x, y})), z});
    });
  };
  if (w.image) {
    // The 2D raster of an image world is its solid pixels (already flipped to grid rows).
    const auto& solid = world.laserSolid();
    const ZInterval z{0.0f, static_cast<float>(ceiling_m_)};
    for (std::size_t i = 0; i < solid.size(); ++i) {
      if (solid[i]) pieces.push_back({static_cast<std::uint32_t>(i), z});
    }
  } else {
    for (const Wall& wall : w.walls) add(wallRectangle(wall), wall.z_min_m, wall.z_max_m);
    for (const FurniturePiece& f : w.furniture) add(f.footprint_m, f.z_min_m, f.z_max_m);
  }
  std::sort(pieces.begin(), pieces.end(), [](const CellInterval& a, const CellInterval& b) {
    return a.cell != b.cell ? a.cell < b.cell : a.z.z_min_m < b.z.z_min_m;
  });

  // Merge overlapping or touching intervals per cell and lay them out in CSR form.
  const std::size_t n_cells = geometry_.cellCount();
  offsets_.assign(n_cells + 1, 0);
  intervals_.reserve(pieces.size());
  std::size_t k = 0;
  for (std::size_t cell = 0; cell < n_cells; ++cell) {
    offsets_[cell] = static_cast<std::uint32_t>(intervals_.size());
    const std::size_t first = intervals_.size();
    for (; k < pieces.size() && pieces[k].cell == cell; ++k) {
      const ZInterval& z = pieces[k].z;
      if (intervals_.size() > first && z.z_min_m <= intervals_.back().z_max_m) {
        intervals_.back().z_max_m = std::max(intervals_.back().z_max_m, z.z_max_m);
      } else {
        intervals_.push_back(z);
      }
    }
  }
  offsets_[n_cells] = static_cast<std::uint32_t>(intervals_.size());
  intervals_.shrink_to_fit();
}

bool ColumnWorld::solidAt(const Eigen::Vector3d& p_map) const {
  const Cell c = geometry_.cellOf(p_map.head<2>());
  if (!geometry_.contains(c)) return false;
  if (p_map.z() <= floor_m() || p_map.z() >= ceiling_m_) return true;
  for (const ZInterval& z : intervals(geometry_.index(c))) {
    if (z.z_min_m <= p_map.z() && p_map.z() <= z.z_max_m) return true;
  }
  return false;
}

bool ColumnWorld::nearSurface(const Eigen::Vector3d& p_map, double tolerance_m) const {
  if (std::abs(p_map.z() - floor_m()) <= tolerance_m ||
      std::abs(p_map.z() - ceiling_m_) <= tolerance_m) {
    return true;
  }
  const Cell c = geometry_.cellOf(p_map.head<2>());
  const int r = static_cast<int>(std::ceil(tolerance_m / geometry_.resolution_m()));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const Cell n{c.x + dx, c.y + dy};
      if (!geometry_.contains(n)) continue;
      for (const ZInterval& z : intervals(geometry_.index(n))) {
        if (z.z_min_m - tolerance_m <= p_map.z() && p_map.z() <= z.z_max_m + tolerance_m)
          return true;
      }
    }
  }
  return false;
}

}  // namespace roomscout::sim
