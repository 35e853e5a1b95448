#pragma once
// What line and bar charts share: "nice" axis ticks, the layout of title, axes, labels and
// legend around the plot area, and drawing them.

#include <optional>
#include <string>
#include <vector>

#include "roomscout/plots/canvas.hpp"
#include "roomscout/plots/figure.hpp"

namespace roomscout::plots {

/// Axis ticks at 1, 2 or 5 times a power of ten.
struct AxisTicks {
  double min = 0.0;  ///< axis range (the outer ticks when the range was widened to ticks)
  double max = 1.0;
  std::vector<double> values;
  int decimals = 0;  ///< digits after the point that tell the tick values apart

  /// Tick label of `value`, with `decimals` digits ("-0" printed as "0").
  std::string label(double value) const;
};

/// About `target_count` ticks covering [lo, hi]; the range widens to the outer ticks unless
/// fixed by `fixed_min` / `fixed_max`. A degenerate range (lo == hi) is widened around lo.
AxisTicks niceTicks(double lo, double hi, int target_count, std::optional<double> fixed_min = {},
                    std::optional<double> fixed_max = {});

struct LegendEntry {
  std::string name;
  Rgb color;
  bool bar = false;     ///< a filled square swatch (bars) instead of a line (series)
  bool dashed = false;  ///< line swatch dashed
};

/// Text styles of chart parts.
TextStyle titleStyle();
TextStyle labelStyle();
TextStyle tickStyle();
TextStyle legendStyle();

/// Places the plot area in a figure of `size`, leaving room for the title, axis labels, y
/// tick labels of `y_tick_width` px, and a legend of `legend` entries on the right.
cv::Rect2d plotArea(const FigureSize& size, bool has_title, bool has_x_label, bool has_y_label,
                    double y_tick_width, const std::vector<LegendEntry>& legend);

/// Widest tick label of `ticks` [px].
double tickLabelWidth(const AxisTicks& ticks);

/// Pixel row of a y value in `plot`.
double yPixel(const cv::Rect2d& plot, const AxisTicks& y, double value);
/// Pixel column of an x value in `plot`.
double xPixel(const cv::Rect2d& plot, const AxisTicks& x, double value);

void drawTitle(Canvas& canvas, const FigureSize& size, const std::string& title);
/// Horizontal grid lines, y tick labels and the vertical y label.
void drawYAxis(Canvas& canvas, const cv::Rect2d& plot, const AxisTicks& y,
               const std::string& label);
/// Vertical grid lines and x tick labels under the plot.
void drawXTicks(Canvas& canvas, const cv::Rect2d& plot, const AxisTicks& x);
/// The x label centred under the tick labels.
void drawXLabel(Canvas& canvas, const FigureSize& size, const cv::Rect2d& plot,
                const std::string& label);
/// The plot area's frame (left and bottom axes).
void drawFrame(Canvas& canvas, const cv::Rect2d& plot);
/// The legend to the right of the plot area, top-aligned with it.
void drawLegend(Canvas& canvas, const cv::Rect2d& plot, const std::vector<LegendEntry>& legend);

}  // namespace roomscout::plots
