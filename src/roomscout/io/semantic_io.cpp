#include "roomscout/io/semantic_io.hpp"

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/format.hpp"
#include "roomscout/io/atomic_file.hpp"

namespace roomscout::io {
namespace {

std::string hexColour(const std::array<std::uint8_t, 3>& rgb) {
  return formatString("#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
}

int displayScale(const GridGeometry& g) {
  return std::max(1, std::min(4, 1200 / std::max(1, std::max(g.width(), g.height()))));
}

}  // namespace

cv::Mat occupancyImage(const OccupancyGrid& grid) {
  const GridGeometry& g = grid.geometry();
  cv::Mat image(g.height(), g.width(), CV_8U);
  for (int y = 0; y < g.height(); ++y) {
    auto* row = image.ptr<std::uint8_t>(g.height() - 1 - y);
    for (int x = 0; x < g.width(); ++x) {
      const CellState s = grid.state(Cell{x, y});
      row[x] = s == CellState::kFree ? 254 : s == CellState::kOccupied ? 0 : 205;
    }
  }
  return image;
}

nlohmann::json semanticJson(const SemanticMap& map) {
  const GridGeometry& g = map.geometry();
  nlohmann::json regions = nlohmann::json::array();
  for (const SemanticRegion& r : map.regions()) {
    nlohmann::json polygon = nlohmann::json::array();
    for (const Vec2& p : r.polygon_m) polygon.push_back({p.x(), p.y()});
    regions.push_back({{"id", r.id},
                       {"colour", hexColour(r.rgb)},
                       {"label", r.label},
                       {"area_m2", r.area_m2},
                       {"centroid", {r.centroid_m.x(), r.centroid_m.y()}},
                       {"polygon", polygon},
                       {"open", r.open},
                       {"neighbours", r.neighbours}});
  }
  return {{"frame", "map"},
          {"resolution", g.resolution_m()},
          {"origin", {g.origin_m().x(), g.origin_m().y(), 0.0}},
          {"width", g.width()},
          {"height", g.height()},
          {"labels_image", "semantic_labels.png"},
          {"regions", regions}};
}

cv::Mat semanticLabelImage(const SemanticMap& map) {
  const cv::Mat& labels = map.labels();
  cv::Mat image(labels.size(), CV_16U);
  for (int y = 0; y < labels.rows; ++y) {
    const int* in = labels.ptr<int>(y);
    auto* out = image.ptr<std::uint16_t>(labels.rows - 1 - y);
    for (int x = 0; x < labels.cols; ++x)
      out[x] = static_cast<std::uint16_t>(std::clamp(in[x], 0, 65535));
  }
  return image;
}

cv::Mat colourLabels(const cv::Mat& labels, const cv::Mat& background_grey) {
  cv::Mat image;
  cv::cvtColor(background_grey, image, cv::COLOR_GRAY2BGR);
  for (int y = 0; y < labels.rows; ++y) {
    const int* l = labels.ptr<int>(y);
    auto* out = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (l[x] <= 0) continue;
      const auto rgb = SemanticMap::colourOf(l[x]);
      out[x] = cv::Vec3b(rgb[2], rgb[1], rgb[0]);
    }
  }
  return image;
}

cv::Mat renderSemantic(const SemanticMap& map, const OccupancyGrid& grid) {
  const GridGeometry& g = grid.geometry();
  cv::Mat labels;
  cv::flip(map.labels(), labels, 0);
  cv::Mat image = colourLabels(labels, occupancyImage(grid));
  const int scale = displayScale(g);
  cv::resize(image, image, {}, scale, scale, cv::INTER_NEAREST);
  for (const SemanticRegion& r : map.regions()) {
    auto toPixel = [&](const Vec2& p) {
      return cv::Point(
          static_cast<int>((p.x() - g.origin_m().x()) / g.resolution_m() * scale),
          static_cast<int>((g.height() - (p.y() - g.origin_m().y()) / g.resolution_m()) * scale));
    };
    if (r.open && r.polygon_m.size() >= 3) {
      std::vector<cv::Point> poly;
      for (const Vec2& p : r.polygon_m) poly.push_back(toPixel(p));
      cv::polylines(image, poly, true, cv::Scalar(0, 0, 200), 1, cv::LINE_AA);
    }
    const std::string text = std::to_string(r.id);
    const double font = 0.35 * std::max(1, scale);
    int base = 0;
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font, 1, &base);
    const cv::Point c = toPixel(r.centroid_m) - cv::Point(size.width / 2, -size.height / 2);
    cv::putText(image, text, c, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(30, 30, 30), 1,
                cv::LINE_AA);
  }
  return image;
}

void writeSemanticMap(const std::filesystem::path& directory, const SemanticMap& map,
                      const OccupancyGrid& grid, const nlohmann::json& extra) {
  writeImageAtomic(directory / "semantic_labels.png", semanticLabelImage(map));
  writeImageAtomic(directory / "semantic.png", renderSemantic(map, grid));
  nlohmann::json j = semanticJson(map);
  for (const auto& [key, value] : extra.items()) j[key] = value;
  writeFileAtomic(directory / "semantic.json", j.dump(2) + "\n");
}

}  // namespace roomscout::io
