#pragma once
// The Canvas of report figures on a Cairo context: one drawing code for every surface the
// context targets (an image surface for PNG, an SVG or a PDF surface). Text is DejaVu Sans
// through Cairo's fontconfig/FreeType fonts, anti-aliased, with unhinted metrics so that
// textWidth() and the drawn text agree on every surface.

#include <memory>
#include <string_view>

#include <cairo.h>

#include "roomscout/plots/canvas.hpp"

namespace roomscout::plots {

/// Destroys Cairo objects held in std::unique_ptr (CairoPtr).
struct CairoDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
  void operator()(cairo_font_options_t* options) const { cairo_font_options_destroy(options); }
};
template <class T>
using CairoPtr = std::unique_ptr<T, CairoDeleter>;

/// Throws std::runtime_error("cairo: <what>: <Cairo's message>") unless `status` is success.
void checkCairo(cairo_status_t status, std::string_view what);

class CairoCanvas final : public Canvas {
 public:
  /// Draws through `cr`, which the caller owns and keeps alive while the canvas lives. Sets
  /// the context's font options (see the file comment); everything else it changes is
  /// restored after each call. Errors stay in the context: check cairo_status(cr) after.
  explicit CairoCanvas(cairo_t* cr);
  /// Closes the clips left open.
  ~CairoCanvas() override;
  CairoCanvas(const CairoCanvas&) = delete;
  CairoCanvas& operator=(const CairoCanvas&) = delete;

  /// Edges on whole pixels, so bars and boxes are crisp in the PNG.
  void fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view role = {}) override;
  void strokeRect(const cv::Rect2d& rect, const Stroke& stroke) override;
  /// Horizontal and vertical lines lie on pixel centres (odd widths) or edges (even widths),
  /// so a 1 px grid line is one pixel wide in the PNG.
  void line(cv::Point2d a, cv::Point2d b, const Stroke& stroke,
            std::string_view role = {}) override;
  /// Round joins and caps.
  void polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                std::string_view role = {}) override;
  void circle(cv::Point2d centre, double radius_px, Rgb fill) override;
  /// Bytes that are not UTF-8 are drawn as U+FFFD.
  void text(cv::Point2d anchor, std::string_view text, const TextStyle& style) override;
  /// On an SVG surface an enlarged image is embedded enlarged (nearest-neighbour) to the size
  /// it is drawn at: Cairo 1.16 marks no SVG image as pixelated, so viewers would smooth it.
  void image(const cv::Mat& image, const cv::Rect2d& rect) override;
  void pushClip(const cv::Rect2d& rect) override;
  void popClip() override;

 private:
  cairo_t* cr_;
  bool svg_;  ///< the target is an SVG surface
  int open_clips_ = 0;
};

}  // namespace roomscout::plots
