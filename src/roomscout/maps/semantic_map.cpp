#include "roomscout/maps/semantic_map.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/occupancy_grid.hpp"
#include "roomscout/maps/detail/run_components.hpp"

namespace roomscout {

std::array<std::uint8_t, 3> SemanticMap::colourOf(int id) {
  // Golden-angle hues with two saturation/value levels: neighbours in id differ clearly.
  const double hue = std::fmod(id * 137.508, 360.0);
  const double s = (id % 2) ? 0.55 : 0.75, v = (id % 3 == 0) ? 0.80 : 0.95;
  const double c = v * s, hp = hue / 60.0, xx = c * (1.0 - std::fabs(std::fmod(hp, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  if (hp < 1)
    std::tie(r, g, b) = std::make_tuple(c, xx, 0.0);
  else if (hp < 2)
    std::tie(r, g, b) = std::make_tuple(xx, c, 0.0);
  else if (hp < 3)
    std::tie(r, g, b) = std::make_tuple(0.0, c, xx);
  else if (hp < 4)
    std::tie(r, g, b) = std::make_tuple(0.0, xx, c);
  else if (hp < 5)
    std::tie(r, g, b) = std::make_tuple(xx, 0.0, c);
  else
    std::tie(r, g, b) = std::make_tuple(c, 0.0, xx);
  const double m = v - c;
  auto to8 = [&](double u) { return static_cast<std::uint8_t>(std::lround((u + m) * 255.0)); };
  return {to8(r), to8(g), to8(b)};
}

const SemanticRegion* SemanticMap::region(int id) const {
  for (const SemanticRegion& r : regions_) {
    if (r.id == id) return &r;
  }
  return nullptr;
}

void SemanticMap::update(const GridGeometry& geometry, const cv::Mat& segment_labels,
                         const cv::Mat& states) {
  if (segment_labels.type() != CV_32S || segment_labels.rows != geometry.height() ||
      segment_labels.cols != geometry.width()) {
    throw InvalidArgument("SemanticMap::update: labels must be CV_32S of the geometry's size");
  }
  if (!states.empty() && (states.type() != CV_8U || states.size() != segment_labels.size())) {
    throw InvalidArgument("SemanticMap::update: states must be CV_8U of the labels' size");
  }
  // Old labels seen through the new geometry (same cells when the geometry is unchanged).
  int dx = 0, dy = 0;
  const bool have_old =
      !labels_.empty() && std::abs(geometry_.resolution_m() - geometry.resolution_m()) < 1e-9;
  if (have_old) {
    dx = static_cast<int>(std::lround((geometry.origin_m().x() - geometry_.origin_m().x()) /
                                      geometry.resolution_m()));
    dy = static_cast<int>(std::lround((geometry.origin_m().y() - geometry_.origin_m().y()) /
                                      geometry.resolution_m()));
  }
  // Per row, the columns [first, last] that hold room labels (first > last: none), so the
  // passes below skip the unknown part of a partial map.
  const int rows = segment_labels.rows, cols = segment_labels.cols;
  std::vector<int> first(rows, cols), last(rows, -1);
  int max_new = 0;
  for (int y = 0; y < rows; ++y) {
    const int* row = segment_labels.ptr<int>(y);
    int x0 = 0, x1 = cols - 1;
    while (x0 < cols && row[x0] <= 0) ++x0;
    if (x0 == cols) continue;
    while (row[x1] <= 0) --x1;
    first[y] = x0;
    last[y] = x1;
    for (int x = x0; x <= x1; ++x) max_new = std::max(max_new, row[x]);
  }
  const int max_old = next_id_;
  std::vector<int> overlap(have_old ? static_cast<std::size_t>(max_new + 1) * (max_old + 1) : 0,
                           0);  // [new][old]
  for (int y = 0; have_old && y < rows; ++y) {
    const int* row = segment_labels.ptr<int>(y);
    const int oy = y + dy;
    const int* old_row = oy >= 0 && oy < labels_.rows ? labels_.ptr<int>(oy) : nullptr;
    if (!old_row) continue;
    const int x0 = std::max(first[y], -dx), x1 = std::min(last[y], labels_.cols - 1 - dx);
    for (int x = x0; x <= x1; ++x) {
      const int old = old_row[x + dx];
      if (row[x] > 0 && old > 0) ++overlap[static_cast<std::size_t>(row[x]) * (max_old + 1) + old];
    }
  }
  std::vector<std::tuple<int, int, int>> pairs;  // (cells, new, old)
  for (int sn = 1; sn <= max_new && have_old; ++sn) {
    for (int so = 1; so <= max_old; ++so) {
      const int cells = overlap[static_cast<std::size_t>(sn) * (max_old + 1) + so];
      if (cells > 0) pairs.emplace_back(cells, sn, so);
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) > std::get<0>(b) : a < b;
  });
  std::vector<int> id_of(max_new + 1, 0);
  std::set<int> taken;
  for (const auto& [cells, sg, old] : pairs) {
    if (id_of[sg] || taken.count(old)) continue;
    id_of[sg] = old;
    taken.insert(old);
  }

  geometry_ = geometry;
  // A new image, never the old one rewritten: copies of this map keep their labels.
  labels_ = cv::Mat(segment_labels.size(), CV_32S, cv::Scalar(0));
  struct Acc {
    int cells = 0;
    double sx = 0, sy = 0;
    int min_x = 1 << 30, min_y = 1 << 30, max_x = -1, max_y = -1;
    bool open = false;
    std::set<int> neighbours;
  };
  // Indexed by id; ids never exceed next_id_ after this update.
  std::vector<Acc> acc(static_cast<std::size_t>(next_id_ + max_new + 1));
  const auto unknown = static_cast<std::uint8_t>(CellState::kUnknown);
  // One pass, row by row: new segments numbered in row-major order of first appearance get
  // fresh ids in that order; then, on the finished row, the rooms it touches (to its right
  // and in the row below, which is final already) and its room cells next to unknown space.
  // A room is open when such cells form a frontier at least kMinFrontier_m long (single
  // unknown cells on wall faces do not count); the frontier is kept as runs of cells.
  maps::RunComponents fronts;
  for (int y = 0; y < rows; ++y) {
    if (first[y] > last[y]) continue;
    const int* row = segment_labels.ptr<int>(y);
    int* out = labels_.ptr<int>(y);
    for (int x = first[y]; x <= last[y]; ++x) {
      const int sg = row[x];
      if (sg <= 0) continue;
      if (!id_of[sg]) id_of[sg] = next_id_++;
      const int id = id_of[sg];
      out[x] = id;
      Acc& a = acc[id];
      ++a.cells;
      a.sx += x;
      a.sy += y;
      a.min_x = std::min(a.min_x, x);
      a.max_x = std::max(a.max_x, x);
      a.min_y = std::min(a.min_y, y);
      a.max_y = std::max(a.max_y, y);
    }
    const int* below = y > 0 ? labels_.ptr<int>(y - 1) : nullptr;
    const std::uint8_t* st = states.empty() ? nullptr : states.ptr<std::uint8_t>(y);
    const std::uint8_t* st_below = st && y > 0 ? states.ptr<std::uint8_t>(y - 1) : nullptr;
    const std::uint8_t* st_above = st && y + 1 < rows ? states.ptr<std::uint8_t>(y + 1) : nullptr;
    int run_begin = -1;
    for (int x = first[y]; x <= last[y] + 1; ++x) {
      const int id = x <= last[y] ? out[x] : 0;
      bool front = false;
      if (id) {
        Acc& a = acc[id];
        if (x + 1 < cols && out[x + 1] && out[x + 1] != id) {
          a.neighbours.insert(out[x + 1]);
          acc[out[x + 1]].neighbours.insert(id);
        }
        if (below && below[x] && below[x] != id) {
          a.neighbours.insert(below[x]);
          acc[below[x]].neighbours.insert(id);
        }
        front =
            st && ((x + 1 < cols && st[x + 1] == unknown) || (x > 0 && st[x - 1] == unknown) ||
                   (st_above && st_above[x] == unknown) || (st_below && st_below[x] == unknown));
      }
      if (front && run_begin < 0) run_begin = x;
      if (!front && run_begin >= 0) {
        fronts.runs.push_back({y, run_begin, x, 0});
        run_begin = -1;
      }
    }
  }

  const double res = geometry.resolution_m();
  maps::internal::joinRuns(fronts, 8);
  const int min_front_cells = std::max(1, static_cast<int>(std::lround(kMinFrontier_m / res)));
  for (const maps::PixelRun& run : fronts.runs) {
    if (fronts.components[run.component].area < min_front_cells) continue;
    const int* lrow = labels_.ptr<int>(run.y);
    for (int x = run.x_begin; x < run.x_end; ++x) acc[lrow[x]].open = true;
  }
  regions_.clear();
  for (int id = 1; id < static_cast<int>(acc.size()); ++id) {
    Acc& a = acc[id];
    if (a.cells == 0) continue;
    SemanticRegion r;
    r.id = id;
    r.rgb = colourOf(id);
    r.cell_count = a.cells;
    r.area_m2 = a.cells * res * res;
    r.centroid_m = geometry.centerOf(Cell{0, 0}) + Vec2(a.sx / a.cells, a.sy / a.cells) * res;
    r.open = a.open;
    r.neighbours.assign(a.neighbours.begin(), a.neighbours.end());
    // Outline of the region's largest part, from a crop around it.
    const cv::Rect box(a.min_x, a.min_y, a.max_x - a.min_x + 1, a.max_y - a.min_y + 1);
    cv::Mat mask;
    cv::copyMakeBorder(labels_(box) == id, mask, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    std::size_t best = 0;
    for (std::size_t i = 1; i < contours.size(); ++i) {
      if (cv::contourArea(contours[i]) > cv::contourArea(contours[best])) best = i;
    }
    r.label = "room";
    if (!contours.empty()) {
      std::vector<cv::Point> simple;
      cv::approxPolyDP(contours[best], simple, 1.0, true);
      for (const cv::Point& p : simple) {
        // Contour points run along cell centres; widen by half a cell is not worth the noise.
        r.polygon_m.push_back(geometry.centerOf(Cell{p.x - 1 + a.min_x, p.y - 1 + a.min_y}));
      }
      const cv::RotatedRect rect = cv::minAreaRect(contours[best]);
      const double long_side = std::max(rect.size.width, rect.size.height) * res;
      const double short_side =
          std::max(1e-9, static_cast<double>(std::min(rect.size.width, rect.size.height)) * res);
      if (long_side / short_side >= 3.0 && short_side <= 3.0) r.label = "corridor";
    }
    regions_.push_back(std::move(r));
  }
  ++update_count_;
}

}  // namespace roomscout
