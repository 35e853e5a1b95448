#include "roomscout/maps/semantic_map.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout {

std::array<std::uint8_t, 3> SemanticMap::colourOf(int id) {
  // Golden-angle hues with two saturation/value levels: neighbours in id differ clearly.
  const double hue = std::fmod(id * 137.508, 360.0);
  const double s = (id % 2) ? 0.55 : 0.75, v = (id % 3 == 0) ? 0.80 : 0.95;
  const double c = v * s, hp = hue / 60.0, xx = c * (1.0 - std::fabs(std::fmod(hp, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  if (hp < 1) std::tie(r, g, b) = std::make_tuple(c, xx, 0.0);
  else if (hp < 2) std::tie(r, g, b) = std::make_tuple(xx, c, 0.0);
  else if (hp < 3) std::tie(r, g, b) = std::make_tuple(0.0, c, xx);
  else if (hp < 4) std::tie(r, g, b) = std::make_tuple(0.0, xx, c);
  else if (hp < 5) std::tie(r, g, b) = std::make_tuple(xx, 0.0, c);
  else std::tie(r, g, b) = std::make_tuple(c, 0.0, xx);
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

void SemanticMap::update(const GridGeometry& geometry, const cv::Mat& segment_labels, const cv::Mat& states) {
  if (segment_labels.type() != CV_32S || segment_labels.rows != geometry.height() ||
      segment_labels.cols != geometry.width()) {
    throw InvalidArgument("SemanticMap::update: labels must be CV_32S of the geometry's size");
  }
  if (!states.empty() && (states.type() != CV_8U || states.size() != segment_labels.size())) {
    throw InvalidArgument("SemanticMap::update: states must be CV_8U of the labels' size");
  }
  // Old labels seen through the new geometry (same cells when the geometry is unchanged).
  int dx = 0, dy = 0;
  const bool have_old = !labels_.empty() && std::abs(geometry_.resolution_m() - geometry.resolution_m()) < 1e-9;
  if (have_old) {
    dx = static_cast<int>(std::lround((geometry.origin_m().x() - geometry_.origin_m().x()) / geometry.resolution_m()));
    dy = static_cast<int>(std::lround((geometry.origin_m().y() - geometry_.origin_m().y()) / geometry.resolution_m()));
  }
  double max_label = 0;
  cv::minMaxLoc(segment_labels, nullptr, &max_label);
  const int max_new = std::max(0, static_cast<int>(max_label));
  const int max_old = next_id_;
  std::vector<int> overlap(have_old ? static_cast<std::size_t>(max_new + 1) * (max_old + 1) : 0, 0);  // [new][old]
  for (int y = 0; have_old && y < segment_labels.rows; ++y) {
    const int* row = segment_labels.ptr<int>(y);
    const int oy = y + dy;
    const int* old_row = oy >= 0 && oy < labels_.rows ? labels_.ptr<int>(oy) : nullptr;
    if (!old_row) continue;
    for (int x = 0; x < segment_labels.cols; ++x) {
      const int ox = x + dx;
      if (row[x] > 0 && ox >= 0 && ox < labels_.cols && old_row[ox] > 0) {
        ++overlap[static_cast<std::size_t>(row[x]) * (max_old + 1) + old_row[ox]];
      }
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
  for (const auto& [cells, s, old] : pairs) {
    if (id_of[s] || taken.count(old)) continue;
    id_of[s] = old;
    taken.insert(old);
  }

  geometry_ = geometry;
  labels_ = cv::Mat::zeros(segment_labels.size(), CV_32S);
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
  // New segments numbered in row-major order of first appearance get fresh ids in that order.
  for (int y = 0; y < segment_labels.rows; ++y) {
    const int* row = segment_labels.ptr<int>(y);
    int* out = labels_.ptr<int>(y);
    for (int x = 0; x < segment_labels.cols; ++x) {
      const int s = row[x];
      if (s <= 0) continue;
      if (!id_of[s]) id_of[s] = next_id_++;
      const int id = id_of[s];
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
  }
  // Room cells next to unknown space; a room is open when such cells form a frontier at
  // least kMinFrontier_m long (single unknown cells on wall faces do not count).
  cv::Mat frontier = cv::Mat::zeros(labels_.size(), CV_8U);
  for (int y = 0; y < labels_.rows; ++y) {
    const int* row = labels_.ptr<int>(y);
    const int* up = y + 1 < labels_.rows ? labels_.ptr<int>(y + 1) : nullptr;
    for (int x = 0; x < labels_.cols; ++x) {
      const int id = row[x];
      if (!id) continue;
      Acc& a = acc[id];
      if (x + 1 < labels_.cols && row[x + 1] && row[x + 1] != id) {
        a.neighbours.insert(row[x + 1]);
        acc[row[x + 1]].neighbours.insert(id);
      }
      if (up && up[x] && up[x] != id) {
        a.neighbours.insert(up[x]);
        acc[up[x]].neighbours.insert(id);
      }
      if (!states.empty()) {
        for (const auto& [nx, ny] : {std::pair{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}}) {
          if (nx >= 0 && ny >= 0 && nx < states.cols && ny < states.rows && states.ptr<std::uint8_t>(ny)[nx] == unknown) {
            frontier.ptr<std::uint8_t>(y)[x] = 255;
            break;
          }
        }
      }
    }
  }

  const double res = geometry.resolution_m();
  {
    cv::Mat cc, stats, centroids;
    const int n = cv::connectedComponentsWithStats(frontier, cc, stats, centroids, 8, CV_32S);
    const int min_cells = std::max(1, static_cast<int>(std::lround(kMinFrontier_m / res)));
    for (int y = 0; y < cc.rows; ++y) {
      const int* crow = cc.ptr<int>(y);
      const int* lrow = labels_.ptr<int>(y);
      for (int x = 0; x < cc.cols; ++x) {
        if (crow[x] > 0 && stats.at<int>(crow[x], cv::CC_STAT_AREA) >= min_cells) acc[lrow[x]].open = true;
      }
    }
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
      const double short_side = std::max(1e-9, static_cast<double>(std::min(rect.size.width, rect.size.height)) * res);
      if (long_side / short_side >= 3.0 && short_side <= 3.0) r.label = "corridor";
    }
    regions_.push_back(std::move(r));
  }
  ++update_count_;
}

}  // namespace roomscout
