#pragma once
// A report figure as its drawing code, rendered by Cairo (CairoCanvas) as a raster, PNG, SVG
// or PDF, and written to disk in all three file formats.

#include <filesystem>
#include <functional>
#include <string>

#include <opencv2/core/mat.hpp>

#include "roomscout/plots/canvas.hpp"

namespace roomscout::plots {

/// Size of a whole figure [px]: the raster and PNG size, the SVG's width and height in CSS
/// px, and the PDF page at 96 px per inch (0.75 pt per px), so SVG and PDF print alike.
struct FigureSize {
  int width_px = 800;
  int height_px = 480;
};

/// A figure: its size and the code that draws it on a white Canvas of that size. Each render
/// runs `draw` again, so it must draw the same thing every time (it owns its data).
struct Figure {
  FigureSize size;
  std::function<void(Canvas&)> draw;
};

/// A Figure of `draw`. Throws InvalidArgument when the size is below 1 x 1 px.
Figure makeFigure(const FigureSize& size, std::function<void(Canvas&)> draw);

// The renderers throw InvalidArgument for a figure without drawing code or below 1 x 1 px,
// and std::runtime_error when Cairo fails.

/// The rendered figure as an 8-bit BGR image of `size` (CV_8UC3).
cv::Mat renderImage(const Figure& figure);
/// A PNG file (8-bit RGB) of renderImage(); the same bytes for the same figure.
std::string renderPng(const Figure& figure);
/// An SVG 1.1 document, width and height in px, text as glyph outlines; its element ids are
/// numbered in document order, so the same figure gives the same bytes.
std::string renderSvg(const Figure& figure);
/// A one-page PDF file with the fonts embedded, without a creation date, so the same figure
/// gives the same bytes.
std::string renderPdf(const Figure& figure);

/// The three files writeFigure() produces.
struct FigureFiles {
  std::filesystem::path png;
  std::filesystem::path svg;
  std::filesystem::path pdf;
};

/// Renders the figure and writes `stem`.png, `stem`.svg and `stem`.pdf (e.g. stem
/// "out/fig5_small_house"), each atomically (io::writeFileAtomic). Throws InputError naming
/// the file when one cannot be written (and throws as the renderers).
FigureFiles writeFigure(const Figure& figure, const std::filesystem::path& stem);

}  // namespace roomscout::plots
