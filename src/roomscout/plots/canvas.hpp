#pragma once
// The drawing surface report figures are laid out on once and rendered twice: PngCanvas
// rasterises with OpenCV, SvgCanvas writes SVG text. Coordinates are pixels with the origin at
// the top-left corner and y pointing down, as in both formats.

#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

#include "roomscout/plots/color.hpp"

namespace roomscout::plots {

struct Stroke {
  Rgb color = colors::kBlack;
  double width_px = 1.0;
  bool dashed = false;
};

enum class TextAnchor { kStart, kMiddle, kEnd };

struct TextStyle {
  double size_px = 13.0;  ///< font size (em) [px]
  Rgb color = colors::kText;
  TextAnchor anchor = TextAnchor::kStart;
  bool bold = false;
  bool vertical = false;  ///< rotated 90 degrees counter-clockwise (reads bottom to top)
};

/// Estimated advance width of `text` at `style` [px]: the same for both backends, so layouts
/// agree; generous for proportional SVG fonts. PNG text is ASCII only (Hershey fonts).
double textWidth(std::string_view text, const TextStyle& style);

/// A figure's drawing surface. `role` names what an element is (a "series" polyline, a "bar");
/// SVG writes it as the element's class, so pages and tests can find the parts. Not
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
  /// `anchor` is on the text's baseline (for vertical text: the baseline runs upwards).
  virtual void text(cv::Point2d anchor, std::string_view text, const TextStyle& style) = 0;
  /// Draws a BGR (or grey) image stretched over `rect`, nearest-neighbour when enlarged.
  virtual void image(const cv::Mat& image, const cv::Rect2d& rect) = 0;
  /// Until the matching popClip(), drawing outside `rect` is cut away. Clips nest.
  virtual void pushClip(const cv::Rect2d& rect) = 0;
  virtual void popClip() = 0;
};

}  // namespace roomscout::plots
