#pragma once
// A rendered report figure in both formats, and writing it to disk.

#include <filesystem>
#include <functional>
#include <string>

#include <opencv2/core/mat.hpp>

#include "roomscout/plots/canvas.hpp"

namespace roomscout::plots {

/// Size of a whole figure [px]; the PNG has exactly this size, the SVG this width/height.
struct FigureSize {
  int width_px = 800;
  int height_px = 480;
};

/// The same figure as a BGR raster (for PNG files) and as an SVG document.
struct Figure {
  cv::Mat image;    ///< CV_8UC3, FigureSize rows x cols
  std::string svg;  ///< complete <svg> document (no XML declaration, so it can be inlined)
};

/// Runs `draw` on a PngCanvas and on an SvgCanvas of the same size. Throws InvalidArgument
/// when the size is below 1 x 1 px.
Figure renderFigure(const FigureSize& size, const std::function<void(Canvas&)>& draw);

/// The two files writeFigure() produces.
struct FigureFiles {
  std::filesystem::path png;
  std::filesystem::path svg;
};

/// Writes `stem`.png and `stem`.svg (e.g. stem "out/fig5_small_house"), each atomically
/// (io::writeFileAtomic). Throws InputError when a file cannot be written.
FigureFiles writeFigure(const Figure& figure, const std::filesystem::path& stem);

}  // namespace roomscout::plots
