#include "roomscout/plots/bar_chart.hpp"
#include "roomscout/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "roomscout/core/errors.hpp"
#include "roomscout/plots/chart_frame.hpp"

namespace roomscout::plots {
namespace {

std::string valueLabel(double v, int decimals) {
  if (decimals < 0) {
    decimals = 0;
    while (decimals < 2 && std::abs(v * std::pow(10.0, decimals) -
                                    std::round(v * std::pow(10.0, decimals))) > 1e-9) {
      ++decimals;
    }
  }
  return formatString("%.*f", decimals, v);
}

}  // namespace

Figure renderBarChart(const BarChart& chart) {
  double lo = 0.0, hi = 0.0;
  for (const BarSeries& s : chart.series) {
    if (s.values.size() != chart.categories.size()) {
      throw InvalidArgument("bar chart series '" + s.name + "' has " +
                            std::to_string(s.values.size()) + " values for " +
                            std::to_string(chart.categories.size()) + " categories");
    }
    for (double v : s.values) {
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (hi <= lo) hi = lo + 1.0;

  std::vector<LegendEntry> legend;
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    legend.push_back({chart.series[k].name, chart.series[k].color.value_or(paletteColor(k)), true});
  }
  // Headroom for the value labels above the tallest bar.
  const double headroom = chart.value_labels ? (hi - lo) * 0.08 : 0.0;
  const AxisTicks y = niceTicks(lo, hi + headroom, std::max(2, chart.size.height_px / 60),
                                lo < 0.0 ? std::nullopt : std::optional<double>(0.0), chart.y_max);
  const cv::Rect2d plot = plotArea(chart.size, !chart.title.empty(), !chart.x_label.empty(),
                                   !chart.y_label.empty(), tickLabelWidth(y), legend);

  return makeFigure(chart.size, [=](Canvas& canvas) {
    drawTitle(canvas, chart.size, chart.title);
    drawYAxis(canvas, plot, y, chart.y_label);
    drawXLabel(canvas, chart.size, plot, chart.x_label);
    const std::size_t groups = chart.categories.size();
    const std::size_t n = chart.series.size();
    if (groups > 0) {
      const double slot = plot.width / static_cast<double>(groups);
      const double bar = n > 0 ? slot * 0.8 / static_cast<double>(n) : 0.0;
      const double zero = yPixel(plot, y, std::clamp(0.0, y.min, y.max));
      TextStyle category = tickStyle();
      category.anchor = TextAnchor::kMiddle;
      category.size_px = 12.0;
      category.color = colors::kText;
      TextStyle value = tickStyle();
      value.anchor = TextAnchor::kMiddle;
      value.size_px = std::clamp(bar * 0.45, 8.0, 11.0);
      for (std::size_t g = 0; g < groups; ++g) {
        const double left = plot.x + slot * static_cast<double>(g) + slot * 0.1;
        canvas.text({plot.x + slot * (static_cast<double>(g) + 0.5),
                     plot.y + plot.height + 6.0 + tickStyle().size_px + 4.0},
                    chart.categories[g], category);
        canvas.pushClip(plot);
        for (std::size_t k = 0; k < n; ++k) {
          const double v = chart.series[k].values[g];
          if (!std::isfinite(v)) continue;
          const double top = yPixel(plot, y, std::clamp(v, y.min, y.max));
          const double x0 = left + bar * static_cast<double>(k);
          canvas.fillRect({x0, std::min(top, zero), bar * 0.92, std::abs(zero - top)},
                          chart.series[k].color.value_or(paletteColor(k)), "bar");
        }
        canvas.popClip();
        if (!chart.value_labels) continue;
        for (std::size_t k = 0; k < n; ++k) {
          const double v = chart.series[k].values[g];
          if (!std::isfinite(v)) continue;
          const double top = yPixel(plot, y, std::clamp(v, y.min, y.max));
          const double x_mid = left + bar * (static_cast<double>(k) + 0.46);
          const double y_text = v >= 0.0 ? top - 3.0 : top + value.size_px + 2.0;
          canvas.text({x_mid, y_text}, valueLabel(v, chart.value_decimals), value);
        }
      }
    }
    drawFrame(canvas, plot);
    drawLegend(canvas, plot, legend);
  });
}

}  // namespace roomscout::plots
