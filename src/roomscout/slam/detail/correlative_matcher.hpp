#pragma once
// A wide search for a scan's pose on a submap, for loop closure: every rotation and shift in a
// window is scored by the mean occupancy probability of the scan's points, and the best is
// found by branch and bound over precomputed grids of maxima over 2^d x 2^d cells (Olson's
// multi-resolution correlative matching, as Cartographer's fast correlative scan matcher).
// The answer is exact at the grid's cell size; matchScan() then refines it.

#include <cstdint>
#include <optional>
#include <vector>

#include "roomscout/core/geometry.hpp"
#include "roomscout/slam/detail/probability_grid.hpp"

namespace roomscout::slam::detail {

struct CorrelativeMatch {
  Pose2 pose;
  double score = 0.0;  ///< mean occupancy probability of the points at `pose`, cell-exact
};

class CorrelativeMatcher {
 public:
  /// Precomputes `depth` levels (>= 1) of maxima over `grid`.
  CorrelativeMatcher(const ProbabilityGrid& grid, int depth);

  /// The best pose within `window_m` (each axis) and `window_rad` of `center` (the sensor in
  /// the grid's frame) for `points` (sensor frame), if its score reaches `min_score`.
  std::optional<CorrelativeMatch> match(const std::vector<Vec2>& points, const Pose2& center,
                                        double window_m, double window_rad, double min_score) const;

 private:
  struct Level {
    int offset = 0;  ///< cell (x, y) of the grid is entry (x + offset, y + offset)
    int width = 0, height = 0;
    std::vector<std::uint8_t> values;  ///< probability * 255, maximum over 2^d x 2^d cells
    std::uint8_t at(int x, int y) const {
      x += offset;
      y += offset;
      if (x < 0 || y < 0 || x >= width || y >= height) return kUnknown;
      return values[static_cast<std::size_t>(y) * width + x];
    }
  };
  static const std::uint8_t kUnknown;

  GridGeometry geometry_;
  std::vector<Level> levels_;
};

}  // namespace roomscout::slam::detail
