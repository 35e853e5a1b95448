#include "roomscout/plots/line_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "roomscout/plots/chart_frame.hpp"

namespace roomscout::plots {

Figure renderLineChart(const LineChart& chart) {
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
  for (const LineSeries& s : chart.series) {
    for (const cv::Point2d& p : s.points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      x_lo = std::min(x_lo, p.x);
      x_hi = std::max(x_hi, p.x);
      y_lo = std::min(y_lo, p.y);
      y_hi = std::max(y_hi, p.y);
    }
  }
  if (chart.reference && std::isfinite(chart.reference->y)) {
    y_lo = std::min(y_lo, chart.reference->y);
    y_hi = std::max(y_hi, chart.reference->y);
  }
  if (!std::isfinite(x_lo)) x_lo = 0.0, x_hi = 1.0;
  if (!std::isfinite(y_lo)) y_lo = 0.0, y_hi = 1.0;

  std::vector<LegendEntry> legend;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const LineSeries& s = chart.series[k];
    legend.push_back({s.name, s.color.value_or(paletteColor(k)), false, s.dashed});
  }
  if (chart.reference && !chart.reference->label.empty()) {
    legend.push_back({chart.reference->label, colors::kReference, false, true});
  }

  const int y_count = std::max(2, chart.size.height_px / 60);
  const AxisTicks y = niceTicks(y_lo, y_hi, y_count, chart.y_min, chart.y_max);
  const cv::Rect2d plot = plotArea(chart.size, !chart.title.empty(), !chart.x_label.empty(),
                                   !chart.y_label.empty(), tickLabelWidth(y), legend);
  const int x_count = std::max(2, static_cast<int>(plot.width / 80.0));
  const AxisTicks x = niceTicks(x_lo, x_hi, x_count, chart.x_min, chart.x_max);

  return makeFigure(chart.size, [=](Canvas& canvas) {
    drawTitle(canvas, chart.size, chart.title);
    drawYAxis(canvas, plot, y, chart.y_label);
    drawXTicks(canvas, plot, x);
    drawXLabel(canvas, chart.size, plot, chart.x_label);
    // Lines on the range's edge stay whole: clip a little outside the plot area.
    const double margin = chart.line_width_px + 1.0;
    canvas.pushClip(
        {plot.x - margin, plot.y - margin, plot.width + 2 * margin, plot.height + 2 * margin});
    if (chart.reference && std::isfinite(chart.reference->y)) {
      const double py = yPixel(plot, y, chart.reference->y);
      canvas.line({plot.x, py}, {plot.x + plot.width, py}, {colors::kReference, 1.5, true},
                  "reference");
    }
    for (std::size_t k = 0; k < chart.series.size(); ++k) {
      const LineSeries& s = chart.series[k];
      std::vector<cv::Point2d> pixels;
      for (const cv::Point2d& p : s.points) {
        if (std::isfinite(p.x) && std::isfinite(p.y)) {
          pixels.push_back({xPixel(plot, x, p.x), yPixel(plot, y, p.y)});
        }
      }
      const Rgb color = s.color.value_or(paletteColor(k));
      if (pixels.size() == 1) canvas.circle(pixels.front(), chart.line_width_px + 1.5, color);
      canvas.polyline(pixels, {color, chart.line_width_px, s.dashed}, "series");
    }
    canvas.popClip();
    drawFrame(canvas, plot);
    drawLegend(canvas, plot, legend);
  });
}

}  // namespace roomscout::plots
