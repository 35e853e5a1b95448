#include "roomscout/exploration/frontier_cells.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/maps/grid_image.hpp"

namespace roomscout {

namespace {

constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

/// SMMR-Explore's frontier cell test, without the robot-region condition (see the header).
class FrontierCellTest {
 public:
  FrontierCellTest(const OccupancyGrid& grid, const Costmap& costmap, int obstacle_l1_cells,
                   const std::vector<std::uint8_t>* exhausted)
      : grid_(grid),
        costmap_(costmap),
        exhausted_(exhausted),
        w_(grid.geometry().width()),
        h_(grid.geometry().height()),
        r_(obstacle_l1_cells - 1) {}

  bool operator()(int x, int y) const {
    if (x < 2 || y < 2 || x >= w_ - 2 || y >= h_ - 2) return false;
    const std::size_t i = static_cast<std::size_t>(y) * w_ + x;
    if (!grid_.isUnknown(i)) return false;
    if (exhausted_ != nullptr && i < exhausted_->size() && (*exhausted_)[i] != 0) return false;
    bool reachable = false;
    for (int k = 0; k < 4 && !reachable; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (!free(nx, ny)) continue;
      // The free neighbour needs a further free neighbour: ahead, left or right of it.
      reachable = free(nx + kDx[k], ny + kDy[k]) || free(nx + kDy[k], ny + kDx[k]) ||
                  free(nx - kDy[k], ny - kDx[k]);
    }
    if (!reachable || costmap_.isLethal(i)) return false;
    for (int dy = -r_; dy <= r_; ++dy) {  // occupied cells at L1 <= r_ reject the cell
      const int yy = y + dy;
      if (yy < 0 || yy >= h_) continue;
      const int span = r_ - std::abs(dy);
      for (int xx = std::max(0, x - span); xx <= std::min(w_ - 1, x + span); ++xx) {
        if (grid_.isOccupied(static_cast<std::size_t>(yy) * w_ + xx)) return false;
      }
    }
    return true;
  }

 private:
  bool free(int x, int y) const { return grid_.isFree(static_cast<std::size_t>(y) * w_ + x); }

  const OccupancyGrid& grid_;
  const Costmap& costmap_;
  const std::vector<std::uint8_t>* exhausted_;
  int w_, h_, r_;
};

/// Throws unless `costmap` was computed for a grid of `grid`'s size (cells are read by index).
void requireMatchingCostmap(const OccupancyGrid& grid, const Costmap& costmap) {
  if (costmap.lethalMask().size() != grid.geometry().cellCount()) {
    throw InvalidArgument("frontier cells: the costmap was not computed for this grid");
  }
}

/// The known-free, non-lethal cell the robot's free region starts from (the robot's own, else the
/// nearest within 1 m), if any.
std::optional<Cell> regionStart(const OccupancyGrid& grid, const Costmap& costmap,
                                const Vec2& from_m) {
  const GridGeometry& g = grid.geometry();
  auto open = [&](std::size_t i) { return grid.isFree(i) && !costmap.isLethal(i); };
  const Cell c = g.cellOf(from_m);
  if (g.contains(c) && open(g.index(c))) return c;
  std::optional<Cell> start;
  const int r = static_cast<int>(std::ceil(1.0 / g.resolution_m()));
  long best = std::numeric_limits<long>::max();
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const Cell q{c.x + dx, c.y + dy};
      const long d2 = static_cast<long>(dx) * dx + static_cast<long>(dy) * dy;
      if (d2 < best && g.contains(q) && open(g.index(q))) {
        best = d2;
        start = q;
      }
    }
  }
  return start;
}

/// The known-free, non-lethal cells 4-connected to `start` (which must be one), as 1 in an
/// image of the grid's size (OpenCV's scanline flood fill on the image of such cells).
cv::Mat freeRegionMask(const OccupancyGrid& grid, const Costmap& costmap, Cell start) {
  const GridGeometry& g = grid.geometry();
  const cv::Mat lethal(g.height(), g.width(), CV_8U,
                       const_cast<std::uint8_t*>(costmap.lethalMask().data()));
  const cv::Mat open =
      (maps::stateView(grid) == static_cast<std::uint8_t>(CellState::kFree)) & (lethal == 0);
  cv::Mat mask = cv::Mat::zeros(g.height() + 2, g.width() + 2, CV_8U);
  cv::floodFill(open, mask, cv::Point(start.x, start.y), cv::Scalar(), nullptr, cv::Scalar(),
                cv::Scalar(), 4 | cv::FLOODFILL_MASK_ONLY | (1 << 8));
  return mask(cv::Rect(1, 1, g.width(), g.height()));
}

/// Scanline flood fill of the open cells 4-connected to `start`: each seed is widened to the
/// whole open run of its row, and the rows above and below are seeded once per open run along
/// it. Calls `visit(index)` for each cell as it is reached and stops early when it returns
/// false. Cells are marked 1 in `region`; cells already non-zero there are not entered.
template <typename Visit>
void floodOpenRegion(const OccupancyGrid& grid, const Costmap& costmap, Cell start,
                     std::vector<std::uint8_t>& region, Visit&& visit) {
  const GridGeometry& g = grid.geometry();
  const int w = g.width(), h = g.height();
  auto open = [&](std::size_t i) {
    return region[i] == 0 && grid.isFree(i) && !costmap.isLethal(i);
  };
  std::vector<Cell> seeds{start};
  while (!seeds.empty()) {
    const Cell s = seeds.back();
    seeds.pop_back();
    const std::size_t row = static_cast<std::size_t>(s.y) * w;
    if (!open(row + s.x)) continue;
    int x0 = s.x, x1 = s.x;
    while (x0 > 0 && open(row + x0 - 1)) --x0;
    while (x1 + 1 < w && open(row + x1 + 1)) ++x1;
    for (int x = x0; x <= x1; ++x) region[row + x] = 1;
    for (int x = x0; x <= x1; ++x) {
      if (!visit(row + x)) return;
    }
    for (const int ny : {s.y - 1, s.y + 1}) {
      if (ny < 0 || ny >= h) continue;
      const std::size_t nrow = static_cast<std::size_t>(ny) * w;
      bool in_run = false;
      for (int x = x0; x <= x1; ++x) {
        const bool o = open(nrow + x);
        if (o && !in_run) seeds.push_back({x, ny});
        in_run = o;
      }
    }
  }
}

}  // namespace

std::vector<Cell> reachableFrontierCells(const OccupancyGrid& grid, const Costmap& costmap,
                                         int obstacle_l1_cells,
                                         const std::vector<std::uint8_t>* exhausted,
                                         const Vec2* robot_m) {
  requireMatchingCostmap(grid, costmap);
  const GridGeometry& g = grid.geometry();
  const int w = g.width(), h = g.height();
  std::vector<Cell> out;
  if (w < 5 || h < 5) return out;
  const FrontierCellTest isFrontier(grid, costmap, obstacle_l1_cells, exhausted);
  // Candidates: unknown cells (with the robot: only those with a 4-neighbour in its region),
  // found by whole-image operations; the full test runs on these only, in row-major order.
  const cv::Mat unknown = maps::stateView(grid) == static_cast<std::uint8_t>(CellState::kUnknown);
  cv::Mat candidates;
  if (robot_m != nullptr) {
    const std::optional<Cell> start = regionStart(grid, costmap, *robot_m);
    if (!start) return out;
    cv::dilate(freeRegionMask(grid, costmap, *start), candidates,
               cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3)), cv::Point(-1, -1), 1,
               cv::BORDER_CONSTANT, cv::Scalar(0));
    candidates &= unknown;
  } else {
    candidates = unknown;
  }
  // Row-major over the inner part (the test needs two cells of margin). Candidates are
  // sparse: eight bytes are skipped at a time where all are zero (cv::findNonZero visits
  // every byte, and took 4 % of an mmpf episode).
  for (int y = 2; y < h - 2; ++y) {
    const std::uint8_t* row = candidates.ptr<std::uint8_t>(y);
    int x = 2;
    while (x < w - 2) {
      if (x + 8 <= w - 2) {
        std::uint64_t word;
        std::memcpy(&word, row + x, sizeof word);
        if (word == 0) {
          x += 8;
          continue;
        }
      }
      if (row[x] && isFrontier(x, y)) out.push_back({x, y});
      ++x;
    }
  }
  return out;
}

std::size_t countReachableFrontierCells(const OccupancyGrid& grid, const Costmap& costmap,
                                        int obstacle_l1_cells,
                                        const std::vector<std::uint8_t>* exhausted,
                                        const Vec2& robot_m, std::size_t limit) {
  requireMatchingCostmap(grid, costmap);
  const GridGeometry& g = grid.geometry();
  if (g.width() < 5 || g.height() < 5 || limit == 0) return 0;
  const std::optional<Cell> start = regionStart(grid, costmap, robot_m);
  if (!start) return 0;
  const FrontierCellTest isFrontier(grid, costmap, obstacle_l1_cells, exhausted);
  std::vector<std::uint8_t> region(g.cellCount(), 0);
  std::vector<std::size_t> found;  // at most `limit` cells
  floodOpenRegion(grid, costmap, *start, region, [&](std::size_t i) {
    const Cell q = g.cellAt(i);
    for (int k = 0; k < 4; ++k) {
      const int x = q.x + kDx[k], y = q.y + kDy[k];
      if (!isFrontier(x, y)) continue;
      const std::size_t j = static_cast<std::size_t>(y) * g.width() + x;
      if (std::find(found.begin(), found.end(), j) == found.end()) found.push_back(j);
      if (found.size() >= limit) return false;
    }
    return true;
  });
  return found.size();
}

void knownCellsBox(const OccupancyGrid& grid, const Vec2& robot, int padding_cells, Vec2& min_m,
                   Vec2& max_m) {
  const GridGeometry& g = grid.geometry();
  const cv::Rect known =
      g.cellCount() == 0 ? cv::Rect() : maps::knownBounds(maps::stateView(grid), padding_cells);
  if (known.empty()) {
    min_m = max_m = robot;
    return;
  }
  min_m = g.origin_m() + Vec2(known.x * g.resolution_m(), known.y * g.resolution_m());
  max_m = g.origin_m() + Vec2(known.br().x * g.resolution_m(), known.br().y * g.resolution_m());
}

void markDisc(std::vector<std::uint8_t>& mask, const GridGeometry& geometry, const Vec2& p_m,
              double radius_m) {
  if (mask.size() != geometry.cellCount()) mask.assign(geometry.cellCount(), 0);
  const Cell c = geometry.cellOf(p_m);
  const int r = static_cast<int>(std::ceil(radius_m / geometry.resolution_m()));
  const double r2 = radius_m * radius_m;
  for (int y = std::max(0, c.y - r); y <= std::min(geometry.height() - 1, c.y + r); ++y) {
    for (int x = std::max(0, c.x - r); x <= std::min(geometry.width() - 1, c.x + r); ++x) {
      const Cell q{x, y};
      if ((geometry.centerOf(q) - p_m).squaredNorm() <= r2) mask[geometry.index(q)] = 1;
    }
  }
}

std::optional<Vec2> nearestGoalCell(const OccupancyGrid& grid, const Costmap& costmap,
                                    const Vec2& p_m, double max_radius_m, bool free_only) {
  requireMatchingCostmap(grid, costmap);
  const GridGeometry& g = grid.geometry();
  const Cell c = g.cellOf(p_m);
  const int r = static_cast<int>(std::ceil(max_radius_m / g.resolution_m()));
  std::optional<Cell> best;
  long best_d2 = std::numeric_limits<long>::max();
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const long d2 = static_cast<long>(dx) * dx + static_cast<long>(dy) * dy;
      if (d2 > static_cast<long>(r) * r || d2 >= best_d2) continue;
      const Cell q{c.x + dx, c.y + dy};
      if (!g.contains(q)) continue;
      const std::size_t i = g.index(q);
      if (costmap.isLethal(i) || grid.isOccupied(i)) continue;
      if (free_only && !grid.isFree(i)) continue;
      best_d2 = d2;
      best = q;
    }
  }
  if (!best) return std::nullopt;
  return g.centerOf(*best);
}

void markUnknownPockets(std::vector<std::uint8_t>& exhausted, const OccupancyGrid& grid,
                        const Costmap& costmap, const std::vector<Cell>& cells, double min_area_m2,
                        double min_opening_m) {
  requireMatchingCostmap(grid, costmap);
  const GridGeometry& g = grid.geometry();
  if (exhausted.size() != g.cellCount()) exhausted.assign(g.cellCount(), 0);
  if (cells.empty()) return;
  const double res = g.resolution_m();
  const std::size_t min_cells = static_cast<std::size_t>(std::ceil(min_area_m2 / (res * res)));
  // 0: reaching the border does not make a component large.
  const std::size_t min_border_cells =
      min_opening_m > 0.0
          ? static_cast<std::size_t>(std::max(1.0, std::ceil(min_opening_m / res - 1e-9)))
          : std::numeric_limits<std::size_t>::max();
  // The bounding box of the known cells, one cell wider: the unknown beyond it is taken to be
  // outside the outer walls (with min_opening_m > 0: unless the component reaches the box's
  // border through an opening at least that wide, as a corridor leading on would).
  Vec2 box_min, box_max;
  knownCellsBox(grid, g.centerOf(cells.front()), 0, box_min, box_max);
  const int x0 =
      std::max(0, static_cast<int>(std::floor((box_min.x() - g.origin_m().x()) / res)) - 1);
  const int y0 =
      std::max(0, static_cast<int>(std::floor((box_min.y() - g.origin_m().y()) / res)) - 1);
  const int x1 =
      std::min(g.width() - 1, static_cast<int>(std::ceil((box_max.x() - g.origin_m().x()) / res)));
  const int y1 =
      std::min(g.height() - 1, static_cast<int>(std::ceil((box_max.y() - g.origin_m().y()) / res)));
  const int w = g.width();
  auto open = [&](int x, int y) {
    if (x < x0 || y < y0 || x > x1 || y > y1) return false;
    const std::size_t i = static_cast<std::size_t>(y) * w + x;
    return grid.isUnknown(i) && !costmap.isLethal(i);
  };
  // Components of open cells, labelled 1, 2, ...; a fill stops at min_cells (the component is
  // large) or when it meets a component already found large.
  std::vector<std::uint32_t> label(g.cellCount(), 0);
  std::vector<std::uint8_t> large{0};
  std::vector<Cell> stack;
  for (const Cell& f : cells) {
    const std::size_t fi = g.index(f);
    if (label[fi] != 0 || !open(f.x, f.y)) continue;
    const auto id = static_cast<std::uint32_t>(large.size());
    large.push_back(0);
    label[fi] = id;
    stack.assign(1, f);
    std::size_t n = 0, border = 0;
    while (!stack.empty() && !large[id]) {
      const Cell q = stack.back();
      stack.pop_back();
      if (q.x == x0 || q.y == y0 || q.x == x1 || q.y == y1) ++border;
      if (++n >= min_cells || border >= min_border_cells) large[id] = 1;
      for (int k = 0; k < 4 && !large[id]; ++k) {
        const int x = q.x + kDx[k], y = q.y + kDy[k];  // order does not matter here
        if (!open(x, y)) continue;
        const std::size_t j = static_cast<std::size_t>(y) * w + x;
        if (label[j] == 0) {
          label[j] = id;
          stack.push_back({x, y});
        } else if (label[j] != id) {
          large[id] = 1;  // a fill that stopped early: only large components do
        }
      }
    }
  }
  for (const Cell& f : cells) {
    const std::size_t fi = g.index(f);
    if (label[fi] == 0 || !large[label[fi]]) exhausted[fi] = 1;
  }
}

void EndTestPockets::validate(std::string_view group) const {
  if (!(min_area_m2 >= 0.0) || !(min_opening_m >= 0.0)) {
    throw OptionError(std::string(group) + ": min_unknown_area_m2 and min_opening_m must be >= 0");
  }
  if (!(period_s > 0.0) || !std::isfinite(period_s)) {
    throw OptionError(std::string(group) + ".pocket_check_period_s must be > 0");
  }
}

std::vector<ParameterRef> EndTestPockets::parameters() {
  return {
      {"min_unknown_area_m2", &min_area_m2,
       "end test: frontier cells with less unknown, non-lethal area behind them (inside the known "
       "box) are ignored [m^2]"},
      {"min_opening_m", &min_opening_m,
       "end test: unknown space reaching the known box's border through an opening this wide is no "
       "pocket, whatever its area [m]; 0: the border does not matter (unsafe: a corridor's "
       "frontier at the box's edge counts as a pocket)"},
      {"pocket_check_period_s", &period_s,
       "period of the end test's pocket search (a full-map scan) [s]"},
  };
}

std::size_t countEndTestFrontierCells(const OccupancyGrid& grid, const Costmap& costmap,
                                      int obstacle_l1_cells, std::vector<std::uint8_t>& exhausted,
                                      const Vec2& robot_m, std::size_t enough,
                                      const EndTestPockets& pockets, double time_s,
                                      double& last_search_s) {
  const auto count = [&] {
    return countReachableFrontierCells(grid, costmap, obstacle_l1_cells, &exhausted, robot_m,
                                       enough);
  };
  std::size_t cells = count();
  if (cells >= enough && pockets.min_area_m2 > 0.0 &&
      time_s - last_search_s >= pockets.period_s - 1e-9) {
    last_search_s = time_s;
    const std::vector<Cell> all =
        reachableFrontierCells(grid, costmap, obstacle_l1_cells, &exhausted, &robot_m);
    markUnknownPockets(exhausted, grid, costmap, all, pockets.min_area_m2, pockets.min_opening_m);
    cells = count();
  }
  return cells;
}

}  // namespace roomscout
