#include "roomscout/plots/chart_frame.hpp"
#include "roomscout/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace roomscout::plots {
namespace {

constexpr double kPad = 10.0;          ///< outer padding [px]
constexpr double kTickLength = 4.0;    ///< [px]
constexpr double kSwatchWidth = 22.0;  ///< legend line / box [px]
constexpr double kLegendGap = 16.0;    ///< between plot area and legend [px]
constexpr double kLegendRow = 18.0;    ///< legend row height [px]

}  // namespace

std::string AxisTicks::label(double value) const {
  std::string s = formatString("%.*f", decimals, value);
  if (s.find_first_not_of("-0.") == std::string::npos && s.front() == '-') s.erase(0, 1);
  return s;
}

AxisTicks niceTicks(double lo, double hi, int target_count, std::optional<double> fixed_min,
                    std::optional<double> fixed_max) {
  if (fixed_min) lo = *fixed_min;
  if (fixed_max) hi = *fixed_max;
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (hi < lo) std::swap(lo, hi);
  if (hi - lo < 1e-12 * std::max(1.0, std::abs(lo))) {
    const double half = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
    if (!fixed_min) lo -= half;
    if (!fixed_max) hi += half;
    if (hi <= lo) hi = lo + 2.0 * half;
  }
  const double raw = (hi - lo) / std::max(1, target_count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double residual = raw / magnitude;
  const double factor = residual <= 1.0   ? 1.0
                        : residual <= 2.0 ? 2.0
                        : residual <= 5.0 ? 5.0
                                          : 10.0;
  const double step = factor * magnitude;
  AxisTicks ticks;
  ticks.min = fixed_min ? lo : std::floor(lo / step + 1e-9) * step;
  ticks.max = fixed_max ? hi : std::ceil(hi / step - 1e-9) * step;
  ticks.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  const double first = std::ceil(ticks.min / step - 1e-9) * step;
  for (double v = first; v <= ticks.max + step * 1e-6; v += step) {
    ticks.values.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  }
  return ticks;
}

TextStyle titleStyle() {
  TextStyle s;
  s.size_px = 16.0;
  s.bold = true;
  s.anchor = TextAnchor::kMiddle;
  return s;
}

TextStyle labelStyle() {
  TextStyle s;
  s.size_px = 13.0;
  s.anchor = TextAnchor::kMiddle;
  return s;
}

TextStyle tickStyle() {
  TextStyle s;
  s.size_px = 11.0;
  s.color = colors::kAxis;
  return s;
}

TextStyle legendStyle() {
  TextStyle s;
  s.size_px = 12.0;
  return s;
}

double tickLabelWidth(const AxisTicks& ticks) {
  double width = 0.0;
  for (double v : ticks.values) width = std::max(width, textWidth(ticks.label(v), tickStyle()));
  return width;
}

cv::Rect2d plotArea(const FigureSize& size, bool has_title, bool has_x_label, bool has_y_label,
                    double y_tick_width, const std::vector<LegendEntry>& legend) {
  const double top = kPad + (has_title ? titleStyle().size_px * 1.6 : 0.0) + 6.0;
  const double left =
      kPad + (has_y_label ? labelStyle().size_px * 1.5 : 0.0) + y_tick_width + kTickLength + 4.0;
  const double bottom = kPad + tickStyle().size_px + kTickLength + 6.0 +
                        (has_x_label ? labelStyle().size_px * 1.6 : 0.0);
  double legend_width = 0.0;
  for (const LegendEntry& e : legend) {
    legend_width = std::max(legend_width, kSwatchWidth + 6.0 + textWidth(e.name, legendStyle()));
  }
  const double right = kPad + (legend.empty() ? 6.0 : legend_width + kLegendGap);
  const double width = std::max(10.0, size.width_px - left - right);
  const double height = std::max(10.0, size.height_px - top - bottom);
  return {left, top, width, height};
}

double yPixel(const cv::Rect2d& plot, const AxisTicks& y, double value) {
  return plot.y + plot.height * (1.0 - (value - y.min) / (y.max - y.min));
}

double xPixel(const cv::Rect2d& plot, const AxisTicks& x, double value) {
  return plot.x + plot.width * (value - x.min) / (x.max - x.min);
}

void drawTitle(Canvas& canvas, const FigureSize& size, const std::string& title) {
  if (title.empty()) return;
  const TextStyle style = titleStyle();
  canvas.text({size.width_px / 2.0, kPad + style.size_px}, title, style);
}

void drawYAxis(Canvas& canvas, const cv::Rect2d& plot, const AxisTicks& y,
               const std::string& label) {
  TextStyle tick = tickStyle();
  tick.anchor = TextAnchor::kEnd;
  double widest = 0.0;
  for (double v : y.values) {
    const double py = yPixel(plot, y, v);
    canvas.line({plot.x, py}, {plot.x + plot.width, py}, {colors::kGrid, 1.0, false}, "grid");
    canvas.line({plot.x - kTickLength, py}, {plot.x, py}, {colors::kAxis, 1.0, false});
    const std::string text = y.label(v);
    canvas.text({plot.x - kTickLength - 3.0, py + tick.size_px * 0.36}, text, tick);
    widest = std::max(widest, textWidth(text, tick));
  }
  if (!label.empty()) {
    TextStyle style = labelStyle();
    style.vertical = true;
    canvas.text({plot.x - kTickLength - 3.0 - widest - 8.0, plot.y + plot.height / 2.0}, label,
                style);
  }
}

void drawXTicks(Canvas& canvas, const cv::Rect2d& plot, const AxisTicks& x) {
  TextStyle tick = tickStyle();
  tick.anchor = TextAnchor::kMiddle;
  const double bottom = plot.y + plot.height;
  for (double v : x.values) {
    const double px = xPixel(plot, x, v);
    canvas.line({px, plot.y}, {px, bottom}, {colors::kGrid, 1.0, false}, "grid");
    canvas.line({px, bottom}, {px, bottom + kTickLength}, {colors::kAxis, 1.0, false});
    canvas.text({px, bottom + kTickLength + 2.0 + tick.size_px}, x.label(v), tick);
  }
}

void drawXLabel(Canvas& canvas, const FigureSize& size, const cv::Rect2d& plot,
                const std::string& label) {
  if (label.empty()) return;
  const TextStyle style = labelStyle();
  const double y = std::min(size.height_px - kPad, plot.y + plot.height + kTickLength + 6.0 +
                                                       tickStyle().size_px + style.size_px * 1.4);
  canvas.text({plot.x + plot.width / 2.0, y}, label, style);
}

void drawFrame(Canvas& canvas, const cv::Rect2d& plot) {
  const Stroke axis{colors::kAxis, 1.0, false};
  canvas.line({plot.x, plot.y}, {plot.x, plot.y + plot.height}, axis, "axis");
  canvas.line({plot.x, plot.y + plot.height}, {plot.x + plot.width, plot.y + plot.height}, axis,
              "axis");
}

void drawLegend(Canvas& canvas, const cv::Rect2d& plot, const std::vector<LegendEntry>& legend) {
  const double x = plot.x + plot.width + kLegendGap;
  double y = plot.y + 4.0;
  const TextStyle style = legendStyle();
  for (const LegendEntry& e : legend) {
    const double mid = y + kLegendRow / 2.0;
    if (e.bar) {
      canvas.fillRect({x + 5.0, mid - 6.0, 12.0, 12.0}, e.color, "legend-swatch");
    } else {
      canvas.line({x, mid}, {x + kSwatchWidth, mid}, {e.color, 2.5, e.dashed}, "legend-swatch");
    }
    canvas.text({x + kSwatchWidth + 6.0, mid + style.size_px * 0.36}, e.name, style);
    y += kLegendRow;
  }
}

}  // namespace roomscout::plots
