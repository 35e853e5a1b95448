#pragma once
// Line charts of named series, e.g. exploration rate against trajectory length for every
// method in one world, with the 98 % completion line (the paper's Fig. 5).

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/types.hpp>

#include "roomscout/plots/color.hpp"
#include "roomscout/plots/figure.hpp"

namespace roomscout::plots {

struct LineSeries {
  std::string name;                 ///< legend text
  std::vector<cv::Point2d> points;  ///< (x, y) in data units, joined in order; non-finite
                                    ///< points are skipped
  std::optional<Rgb> color;         ///< default: paletteColor(index in LineChart::series)
  bool dashed = false;
};

/// A horizontal line across the plot, e.g. the completion rate.
struct ReferenceLine {
  double y = 0.0;     ///< in data units
  std::string label;  ///< legend text (none when empty)
};

struct LineChart {
  std::string title;
  std::string x_label;  ///< with units, e.g. "trajectory length [m]"
  std::string y_label;
  std::vector<LineSeries> series;
  std::optional<ReferenceLine> reference;
  /// Axis ranges; unset ends follow the data (and the reference line), widened to ticks.
  std::optional<double> x_min, x_max, y_min, y_max;
  double line_width_px = 2.0;
  FigureSize size;
};

/// Lays out the chart: title, axes with ticks and grid, one polyline (Canvas role "series")
/// per series with at least two points (a dot for a single point), the reference line (role
/// "reference") and a legend on the right. Data outside fixed ranges is clipped.
/// Throws InvalidArgument when the size is below 1 x 1 px.
Figure renderLineChart(const LineChart& chart);

}  // namespace roomscout::plots
