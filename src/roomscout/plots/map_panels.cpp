#include "roomscout/plots/map_panels.hpp"

#include <algorithm>
#include <cmath>

#include "roomscout/core/errors.hpp"
#include "roomscout/plots/chart_frame.hpp"

namespace roomscout::plots {

Figure renderMapPanels(const MapPanelFigure& figure) {
  if (figure.columns < 0) throw InvalidArgument("map panels: columns must be >= 0");
  const std::size_t n = figure.panels.size();
  const int columns =
      figure.columns > 0 ? figure.columns : static_cast<int>(std::max<std::size_t>(1, n));
  const int rows = std::max(1, static_cast<int>((n + columns - 1) / columns));
  const double pad = 8.0;
  const TextStyle title_style = titleStyle();
  TextStyle panel_title = labelStyle();
  panel_title.bold = true;
  const double top = figure.title.empty() ? pad : pad + title_style.size_px * 1.6 + 4.0;
  const double cell_w = (figure.size.width_px - pad) / columns;
  const double cell_h = (figure.size.height_px - top) / rows;

  return makeFigure(figure.size, [=](Canvas& canvas) {
    drawTitle(canvas, figure.size, figure.title);
    for (std::size_t i = 0; i < n; ++i) {
      const MapPanel& panel = figure.panels[i];
      const double cx = pad + cell_w * static_cast<double>(i % columns);
      const double cy = top + cell_h * static_cast<double>(i / columns);
      const double title_h = panel.title.empty() ? 0.0 : panel_title.size_px * 1.5;
      canvas.text({cx + (cell_w - pad) / 2.0, cy + panel_title.size_px}, panel.title, panel_title);
      const double box_w = std::max(1.0, cell_w - pad);
      const double box_h = std::max(1.0, cell_h - pad - title_h);
      if (panel.image.empty()) continue;
      const double scale = std::min(box_w / panel.image.cols, box_h / panel.image.rows);
      const cv::Rect2d rect(cx + (box_w - panel.image.cols * scale) / 2.0, cy + title_h,
                            panel.image.cols * scale, panel.image.rows * scale);
      canvas.image(panel.image, rect);
      canvas.strokeRect(rect, {colors::kGrid, 1.0, false});
      canvas.pushClip(rect);
      for (const PanelTrack& track : panel.tracks) {
        std::vector<cv::Point2d> points;
        points.reserve(track.points_px.size());
        for (const cv::Point2d& p : track.points_px) {
          if (std::isfinite(p.x) && std::isfinite(p.y)) {
            points.push_back({rect.x + p.x * scale, rect.y + p.y * scale});
          }
        }
        canvas.polyline(points, {track.color, track.width_px, false}, "track");
        if (track.mark_ends && !points.empty()) {
          const double r = std::max(3.0, track.width_px * 1.8);
          canvas.circle(points.front(), r, colors::kStart);
          canvas.circle(points.back(), r, colors::kEnd);
        }
      }
      canvas.popClip();
    }
  });
}

cv::Point2d gridImagePoint(const GridGeometry& grid, const Vec2& point_m) {
  const double res = grid.resolution_m();
  return {(point_m.x() - grid.origin_m().x()) / res,
          grid.height() - (point_m.y() - grid.origin_m().y()) / res};
}

std::vector<cv::Point2d> gridImagePoints(const GridGeometry& grid,
                                         const std::vector<Vec2>& points_m) {
  std::vector<cv::Point2d> points;
  points.reserve(points_m.size());
  for (const Vec2& p : points_m) points.push_back(gridImagePoint(grid, p));
  return points;
}

}  // namespace roomscout::plots
