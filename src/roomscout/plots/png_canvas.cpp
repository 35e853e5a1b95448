#include "roomscout/plots/png_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/plots/hershey_text.hpp"

namespace roomscout::plots {
namespace {

constexpr int kShift = 4;  ///< sub-pixel bits of OpenCV's drawing calls
constexpr double kOne = 1 << kShift;

cv::Point fixedPoint(cv::Point2d p) {
  return {static_cast<int>(std::lround(p.x * kOne)), static_cast<int>(std::lround(p.y * kOne))};
}

int thickness(double width_px) { return std::max(1, static_cast<int>(std::lround(width_px))); }

/// Pixels covered by `rect` (rounded to whole pixels).
cv::Rect pixelRect(const cv::Rect2d& rect) {
  const int x0 = static_cast<int>(std::lround(rect.x));
  const int y0 = static_cast<int>(std::lround(rect.y));
  const int x1 = static_cast<int>(std::lround(rect.x + rect.width));
  const int y1 = static_cast<int>(std::lround(rect.y + rect.height));
  return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

/// Blends `color` into `dst` with `alpha` (CV_8U, same size) as coverage.
void blend(cv::Mat dst, const cv::Mat& alpha, Rgb color) {
  const cv::Vec3b c(color.b, color.g, color.r);
  for (int y = 0; y < dst.rows; ++y) {
    cv::Vec3b* d = dst.ptr<cv::Vec3b>(y);
    const std::uint8_t* a = alpha.ptr<std::uint8_t>(y);
    for (int x = 0; x < dst.cols; ++x) {
      if (!a[x]) continue;
      for (int k = 0; k < 3; ++k)
        d[x][k] = static_cast<std::uint8_t>((d[x][k] * (255 - a[x]) + c[k] * a[x] + 127) / 255);
    }
  }
}

}  // namespace

PngCanvas::PngCanvas(int width_px, int height_px) {
  if (width_px < 1 || height_px < 1) throw InvalidArgument("figure size must be at least 1 x 1 px");
  image_ = cv::Mat(height_px, width_px, CV_8UC3, cv::Scalar(255, 255, 255));
}

cv::Mat PngCanvas::target() {
  if (clips_.empty()) return image_;
  return clips_.back().area() > 0 ? image_(clips_.back()) : cv::Mat();
}

cv::Point2d PngCanvas::offset() const {
  return clips_.empty() ? cv::Point2d(0, 0) : cv::Point2d(clips_.back().x, clips_.back().y);
}

void PngCanvas::fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view) {
  cv::Mat roi = target();
  if (roi.empty()) return;
  const cv::Point2d o = offset();
  const cv::Rect r = pixelRect({rect.x - o.x, rect.y - o.y, rect.width, rect.height}) &
                     cv::Rect(0, 0, roi.cols, roi.rows);
  if (r.area() > 0) roi(r).setTo(toBgr(fill));
}

void PngCanvas::strokeRect(const cv::Rect2d& rect, const Stroke& stroke) {
  const cv::Point2d a(rect.x, rect.y), b(rect.x + rect.width, rect.y),
      c(rect.x + rect.width, rect.y + rect.height), d(rect.x, rect.y + rect.height);
  polyline({a, b, c, d, a}, stroke);
}

void PngCanvas::segment(cv::Mat& roi, cv::Point2d a, cv::Point2d b, const Stroke& stroke) {
  const cv::Point2d o = offset();
  a -= o;
  b -= o;
  if (!stroke.dashed) {
    cv::line(roi, fixedPoint(a), fixedPoint(b), toBgr(stroke.color), thickness(stroke.width_px),
             cv::LINE_AA, kShift);
    return;
  }
  const double dash = 6.0 * std::max(1.0, stroke.width_px),
               gap = 4.0 * std::max(1.0, stroke.width_px);
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  if (length <= 0.0) return;
  const cv::Point2d u = (b - a) / length;
  for (double s = 0.0; s < length; s += dash + gap) {
    const double e = std::min(length, s + dash);
    cv::line(roi, fixedPoint(a + u * s), fixedPoint(a + u * e), toBgr(stroke.color),
             thickness(stroke.width_px), cv::LINE_AA, kShift);
  }
}

void PngCanvas::line(cv::Point2d a, cv::Point2d b, const Stroke& stroke, std::string_view) {
  cv::Mat roi = target();
  if (roi.empty()) return;
  segment(roi, a, b, stroke);
}

void PngCanvas::polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                         std::string_view) {
  if (points.size() < 2) return;
  cv::Mat roi = target();
  if (roi.empty()) return;
  if (stroke.dashed) {
    for (std::size_t k = 1; k < points.size(); ++k) segment(roi, points[k - 1], points[k], stroke);
    return;
  }
  const cv::Point2d o = offset();
  std::vector<cv::Point> fixed;
  fixed.reserve(points.size());
  for (const cv::Point2d& p : points) fixed.push_back(fixedPoint(p - o));
  cv::polylines(roi, fixed, false, toBgr(stroke.color), thickness(stroke.width_px), cv::LINE_AA,
                kShift);
}

void PngCanvas::circle(cv::Point2d centre, double radius_px, Rgb fill) {
  cv::Mat roi = target();
  if (roi.empty()) return;
  cv::circle(roi, fixedPoint(centre - offset()), static_cast<int>(std::lround(radius_px * kOne)),
             toBgr(fill), cv::FILLED, cv::LINE_AA, kShift);
}

void PngCanvas::text(cv::Point2d anchor, std::string_view text, const TextStyle& style) {
  if (text.empty()) return;
  const HersheyFont font = hersheyFont(style);
  const TextExtent extent = hersheyTextSize(text, style);
  const double shift = style.anchor == TextAnchor::kStart    ? 0.0
                       : style.anchor == TextAnchor::kMiddle ? extent.width / 2.0
                                                             : extent.width;
  // Draw the text as a coverage mask, then blend it in (rotated when vertical).
  const int pad = font.thickness + 1;
  const int mask_w = static_cast<int>(std::ceil(extent.width)) + 2 * pad;
  const int mask_h = static_cast<int>(std::ceil(extent.ascent + extent.descent)) + 2 * pad;
  cv::Mat mask = cv::Mat::zeros(mask_h, mask_w, CV_8U);
  cv::putText(mask, std::string(text), {pad, pad + static_cast<int>(std::lround(extent.ascent))},
              font.face, font.scale, cv::Scalar(255), font.thickness, cv::LINE_AA);
  cv::Point top_left;
  const double baseline_row = pad + std::lround(extent.ascent);
  if (style.vertical) {
    cv::rotate(mask, mask, cv::ROTATE_90_COUNTERCLOCKWISE);
    // Mask pixel (x, y) moved to (y, mask_w - 1 - x): the baseline is column baseline_row,
    // the text start is row mask_w - pad.
    top_left = {static_cast<int>(std::lround(anchor.x - baseline_row)),
                static_cast<int>(std::lround(anchor.y + shift - (mask_w - pad)))};
  } else {
    top_left = {static_cast<int>(std::lround(anchor.x - shift - pad)),
                static_cast<int>(std::lround(anchor.y - baseline_row))};
  }
  cv::Mat roi = target();
  const cv::Point2d o = offset();
  const cv::Rect placed(top_left.x - static_cast<int>(o.x), top_left.y - static_cast<int>(o.y),
                        mask.cols, mask.rows);
  const cv::Rect visible = placed & cv::Rect(0, 0, roi.cols, roi.rows);
  if (visible.area() == 0) return;
  blend(roi(visible), mask(visible - placed.tl()), style.color);
}

void PngCanvas::image(const cv::Mat& image, const cv::Rect2d& rect) {
  if (image.empty()) return;
  const cv::Point2d o = offset();
  const cv::Rect placed = pixelRect({rect.x - o.x, rect.y - o.y, rect.width, rect.height});
  if (placed.area() == 0) return;
  cv::Mat bgr;
  if (image.channels() == 1) {
    cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
  } else if (image.channels() == 4) {
    cv::cvtColor(image, bgr, cv::COLOR_BGRA2BGR);
  } else {
    bgr = image;
  }
  if (bgr.depth() != CV_8U) throw InvalidArgument("figure images must be 8-bit");
  const bool enlarge = placed.width >= bgr.cols && placed.height >= bgr.rows;
  cv::Mat scaled;
  cv::resize(bgr, scaled, placed.size(), 0, 0, enlarge ? cv::INTER_NEAREST : cv::INTER_AREA);
  cv::Mat roi = target();
  const cv::Rect visible = placed & cv::Rect(0, 0, roi.cols, roi.rows);
  if (visible.area() == 0) return;
  scaled(visible - placed.tl()).copyTo(roi(visible));
}

void PngCanvas::pushClip(const cv::Rect2d& rect) {
  const cv::Rect parent = clips_.empty() ? cv::Rect(0, 0, image_.cols, image_.rows) : clips_.back();
  clips_.push_back(pixelRect(rect) & parent);
}

void PngCanvas::popClip() {
  if (!clips_.empty()) clips_.pop_back();
}

}  // namespace roomscout::plots
