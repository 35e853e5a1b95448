#include "roomscout/slam/detail/correlative_matcher.hpp"

#include <algorithm>
#include <cmath>

namespace roomscout::slam::detail {

const std::uint8_t CorrelativeMatcher::kUnknown =
    static_cast<std::uint8_t>(std::lround(ProbabilityGrid::kMinProbability * 255.0));

CorrelativeMatcher::CorrelativeMatcher(const ProbabilityGrid& grid, int depth)
    : geometry_(grid.geometry()) {
  depth = std::max(1, depth);
  const int w = geometry_.width(), h = geometry_.height();
  Level base;
  base.width = w;
  base.height = h;
  base.values.resize(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      base.values[static_cast<std::size_t>(y) * w + x] =
          static_cast<std::uint8_t>(std::lround(grid.at(x, y) * 255.0));
  levels_.push_back(std::move(base));
  // Level d at (x, y): the maximum over cells [x, x + 2^d) x [y, y + 2^d), from level d - 1's
  // maxima at (x, y), (x + h, y), (x, y + h), (x + h, y + h) with h = 2^(d-1). Entries start
  // 2^d - 1 cells before the grid, where a window still overlaps it.
  for (int d = 1; d < depth; ++d) {
    const Level& prev = levels_.back();
    const int half = 1 << (d - 1);
    Level level;
    level.offset = (1 << d) - 1;
    level.width = w + level.offset;
    level.height = h + level.offset;
    level.values.resize(static_cast<std::size_t>(level.width) * level.height);
    for (int ly = 0; ly < level.height; ++ly) {
      const int y = ly - level.offset;
      for (int lx = 0; lx < level.width; ++lx) {
        const int x = lx - level.offset;
        level.values[static_cast<std::size_t>(ly) * level.width + lx] =
            std::max({prev.at(x, y), prev.at(x + half, y), prev.at(x, y + half),
                      prev.at(x + half, y + half)});
      }
    }
    levels_.push_back(std::move(level));
  }
}

std::optional<CorrelativeMatch> CorrelativeMatcher::match(const std::vector<Vec2>& points,
                                                          const Pose2& center, double window_m,
                                                          double window_rad,
                                                          double min_score) const {
  if (points.empty()) return std::nullopt;
  const double res = geometry_.resolution_m();
  double max_range = 0.0;
  for (const Vec2& p : points) max_range = std::max(max_range, p.norm());
  if (!(max_range > 0.0)) return std::nullopt;
  // The angular step that moves the farthest point by about one cell.
  const double step =
      std::acos(std::clamp(1.0 - res * res / (2.0 * max_range * max_range), -1.0, 1.0));
  const int angles = static_cast<int>(std::ceil(window_rad / step));
  const int shifts = static_cast<int>(std::ceil(window_m / res));

  // The points' cells for each rotation, with the sensor at the centre's position.
  struct Rotation {
    double yaw;
    std::vector<Cell> cells;
  };
  std::vector<Rotation> rotations;
  for (int a = -angles; a <= angles; ++a) {
    Rotation r;
    r.yaw = center.yaw_rad + a * step;
    const double c = std::cos(r.yaw), s = std::sin(r.yaw);
    r.cells.reserve(points.size());
    for (const Vec2& p : points) {
      r.cells.push_back(geometry_.cellOf(
          Vec2(center.x_m + c * p.x() - s * p.y(), center.y_m + s * p.x() + c * p.y())));
    }
    rotations.push_back(std::move(r));
  }
  const double n = static_cast<double>(points.size());
  auto score = [&](const Rotation& r, int level, int dx, int dy) {
    const Level& l = levels_[level];
    long sum = 0;
    for (const Cell& c : r.cells) sum += l.at(c.x + dx, c.y + dy);
    return static_cast<double>(sum) / (255.0 * n);
  };

  struct Candidate {
    int rotation, dx, dy;
    double score;
  };
  const int top = static_cast<int>(levels_.size()) - 1;
  std::vector<Candidate> candidates;
  const int top_step = 1 << top;
  for (int r = 0; r < static_cast<int>(rotations.size()); ++r) {
    for (int dy = -shifts; dy <= shifts; dy += top_step) {
      for (int dx = -shifts; dx <= shifts; dx += top_step) {
        candidates.push_back({r, dx, dy, score(rotations[r], top, dx, dy)});
      }
    }
  }
  auto byScore = [](const Candidate& a, const Candidate& b) {
    if (a.score != b.score) return a.score > b.score;
    if (a.rotation != b.rotation) return a.rotation < b.rotation;  // a fixed order: repeatable
    if (a.dy != b.dy) return a.dy < b.dy;
    return a.dx < b.dx;
  };
  std::sort(candidates.begin(), candidates.end(), byScore);

  std::optional<Candidate> best;
  double best_score = min_score;
  // Depth-first, best bound first; a candidate's score bounds every pose below it.
  auto search = [&](auto&& self, const std::vector<Candidate>& list, int level) -> void {
    for (const Candidate& c : list) {
      if (c.score < best_score || (best && c.score == best_score)) break;
      if (level == 0) {
        best = c;
        best_score = c.score;
        continue;
      }
      const int half = 1 << (level - 1);
      std::vector<Candidate> children;
      for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
          const int dx = c.dx + i * half, dy = c.dy + j * half;
          if (dx > shifts || dy > shifts) continue;
          children.push_back({c.rotation, dx, dy, score(rotations[c.rotation], level - 1, dx, dy)});
        }
      }
      std::sort(children.begin(), children.end(), byScore);
      self(self, children, level - 1);
    }
  };
  search(search, candidates, top);
  if (!best) return std::nullopt;
  return CorrelativeMatch{Pose2{center.x_m + best->dx * res, center.y_m + best->dy * res,
                                wrapAngle(rotations[best->rotation].yaw)},
                          best->score};
}

}  // namespace roomscout::slam::detail
