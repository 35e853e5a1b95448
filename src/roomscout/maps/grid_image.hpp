#pragma once
// Occupancy grids as OpenCV images for the map analysis (topology, rooms). Images keep the
// grid's orientation: image row y is grid row y (row 0 at the bottom of the map).

#include <optional>

#include <opencv2/core/mat.hpp>

#include "roomscout/core/occupancy_grid.hpp"

namespace roomscout::maps {

/// The grid's own state bytes as an image (CV_8U, one CellState value per cell, row y = grid
/// row y), without a copy: valid while the grid lives, and read-only (writing would put the
/// states out of step with the log-odds).
cv::Mat stateView(const OccupancyGrid& grid);

/// A copy of stateView(grid).
cv::Mat stateImage(const OccupancyGrid& grid);
/// The same into `image`, reusing its buffer when it already has the grid's size.
void stateImage(const OccupancyGrid& grid, cv::Mat& image);

/// Where a grid of geometry `now` lies on one of geometry `before`: cell (x, y) of `now` is
/// cell (x + offset.x, y + offset.y) of `before`. Empty when no whole-cell offset maps one onto
/// the other (another resolution, an origin moved by a fraction of a cell).
std::optional<cv::Point> cellOffset(const GridGeometry& before, const GridGeometry& now);

/// `image` laid onto another grid: a new image of `size` whose pixel p is pixel p + offset of
/// `image`, and `fill` where `image` has none.
cv::Mat shifted(const cv::Mat& image, cv::Point offset, cv::Size size, const cv::Scalar& fill);

/// Number of cells the grid knows (free or occupied).
std::size_t knownCellCount(const OccupancyGrid& grid);
/// The same for an image of CellState values (CV_8U).
std::size_t knownCellCount(const cv::Mat& states);

/// `r` grown by `by` cells on every side, clipped to an image of `size`.
cv::Rect grown(const cv::Rect& r, int by, const cv::Size& size);

/// The smallest rectangle holding every cell whose state differs between two images of the
/// same size (CV_8U); empty when none does.
cv::Rect changedBounds(const cv::Mat& before, const cv::Mat& now);

/// The smallest rectangle holding every known (free or occupied) cell, grown by `margin`
/// cells and clipped to the image; empty when nothing is known. Analysis runs on this crop:
/// during exploration most of the grid is still unknown.
cv::Rect knownBounds(const cv::Mat& states, int margin);

/// The space rooms and paths live in: free cells (255) plus every enclosed blob (8-connected
/// cells that are not free, occupied or unknown, not touching the image border) of at most
/// `max_blob_area_px` cells whose bounding box is at most `max_blob_extent_px` on its longer
/// side. Furniture blobs otherwise cut rooms into pieces and make tiny loops in skeletons.
/// Everything else is 0. `states` is CV_8U of CellState values.
cv::Mat fillableFreeSpace(const cv::Mat& states, int max_blob_area_px, int max_blob_extent_px);

}  // namespace roomscout::maps
