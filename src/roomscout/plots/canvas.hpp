#pragma once
// The drawing surface report figures are laid out on. CairoCanvas draws it onto a Cairo
// surface (PNG, SVG or PDF); tests may record the calls instead. Coordinates are pixels with
// the origin at the top-left corner and y pointing down.

#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include "roomscout/plots/color.hpp"

namespace roomscout::plots {

struct Stroke {
  Rgb color = colors::kBlack;
  double width_px = 1.0;
  bool dashed = false;  ///< dashes of 6 and gaps of 4 stroke widths
};

enum class TextAnchor { kStart, kMiddle, kEnd };

struct TextStyle {
  double size_px = 13.0;  ///< font size (em) [px]
  Rgb color = colors::kText;
  TextAnchor anchor = TextAnchor::kStart;
  bool bold = false;
  bool vertical = false;  ///< rotated 90 degrees counter-clockwise (reads bottom to top)
};

/// Advance width of UTF-8 `text` at `style` [px]: Cairo's extents of the font CairoCanvas
/// draws with (DejaVu Sans), so layouts fit the rendered text in every format. Thread-safe.
double textWidth(std::string_view text, const TextStyle& style);

/// A figure's drawing surface. `role` names what an element is (a "series" polyline, a "bar")
/// for whoever inspects the drawing, such as the tests; rendered files do not carry it. Not
/// thread-safe.
class Canvas {
 public:
  virtual ~Canvas() = default;

  virtual void fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view role = {}) = 0;
  virtual void strokeRect(const cv::Rect2d& rect, const Stroke& stroke) = 0;
  virtual void line(cv::Point2d a, cv::Point2d b, const Stroke& stroke,
                    std::string_view role = {}) = 0;
  /// One connected line through `points` (nothing when fewer than two).
  virtual void polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                        std::string_view role = {}) = 0;
  virtual void circle(cv::Point2d centre, double radius_px, Rgb fill) = 0;
  /// UTF-8 `text`; `anchor` is on its baseline (for vertical text: the baseline runs upwards).
  virtual void text(cv::Point2d anchor, std::string_view text, const TextStyle& style) = 0;
  /// Draws an 8-bit BGR, BGRA (alpha ignored) or grey image stretched over `rect`,
  /// nearest-neighbour when enlarged. Throws InvalidArgument for other pixel types.
  virtual void image(const cv::Mat& image, const cv::Rect2d& rect) = 0;
  /// Until the matching popClip(), drawing outside `rect` is cut away. Clips nest.
  virtual void pushClip(const cv::Rect2d& rect) = 0;
  virtual void popClip() = 0;
};

}  // namespace roomscout::plots
