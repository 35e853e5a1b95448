#pragma once
// Grouped bar charts: categories along x, one bar per series in each category (e.g. room
// revisits per method, one group per world).

#include <optional>
#include <string>
#include <vector>

#include "roomscout/plots/color.hpp"
#include "roomscout/plots/figure.hpp"

namespace roomscout::plots {

struct BarSeries {
  std::string name;            ///< legend text
  std::vector<double> values;  ///< one per category; NaN = no bar (e.g. no data)
  std::optional<Rgb> color;    ///< default: paletteColor(index in BarChart::series)
};

struct BarChart {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<std::string> categories;
  std::vector<BarSeries> series;
  bool value_labels = true;     ///< print each bar's value above it
  int value_decimals = -1;      ///< digits of value labels; -1: as few as show the value
                                ///< (up to 2)
  std::optional<double> y_max;  ///< default: from the data, widened to a tick
  FigureSize size;
};

/// Lays out the chart: bars from zero (Canvas role "bar"), grouped by category with the
/// category names under the groups, y axis with ticks and grid, legend on the right.
/// Throws InvalidArgument when a series has not one value per category or the size is below
/// 1 x 1 px.
Figure renderBarChart(const BarChart& chart);

}  // namespace roomscout::plots
