#pragma once
// Rows of map images with titles and trajectories drawn over them: one panel per method over
// its final map (the paper's Fig. 6), or the four maps of one run side by side (Fig. 7).

#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include "roomscout/core/grid_geometry.hpp"
#include "roomscout/plots/color.hpp"
#include "roomscout/plots/figure.hpp"

namespace roomscout::plots {

/// A polyline over a panel's image.
struct PanelTrack {
  /// Points in the image's continuous pixel frame: x to the right, y down, (0, 0) the top-left
  /// corner of the top-left pixel, (cols, rows) the bottom-right corner. gridImagePoints()
  /// converts map-frame metres for images drawn north-up from a grid.
  std::vector<cv::Point2d> points_px;
  Rgb color = colors::kTrajectory;
  double width_px = 2.0;  ///< on the figure, whatever the image's scale
  bool mark_ends = true;  ///< a green dot at the start and a red one at the end, as run.png
};

struct MapPanel {
  std::string title;
  cv::Mat image;  ///< 8-bit BGR, BGRA or grey; shown whole, aspect ratio kept
  std::vector<PanelTrack> tracks;
};

struct MapPanelFigure {
  std::string title;  ///< above all panels (none when empty)
  std::vector<MapPanel> panels;
  int columns = 0;  ///< panels per row; 0: all in one row
  FigureSize size{1200, 420};
};

/// Lays the panels out in a grid of equal cells, each with its title above its image scaled
/// to fit, and its tracks over it (Canvas role "track").
/// Throws InvalidArgument when the size is below 1 x 1 px or `columns` is negative.
Figure renderMapPanels(const MapPanelFigure& figure);

/// The image pixel-frame point of a map-frame point, for an image of `grid` drawn north up
/// (image row 0 = the grid's top row, as run.png and semantic.png are).
cv::Point2d gridImagePoint(const GridGeometry& grid, const Vec2& point_m);
std::vector<cv::Point2d> gridImagePoints(const GridGeometry& grid,
                                         const std::vector<Vec2>& points_m);

}  // namespace roomscout::plots
