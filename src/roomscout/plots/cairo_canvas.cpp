#include "roomscout/plots/detail/cairo_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"

namespace roomscout::plots {
namespace {

constexpr const char* kFontFamily = "DejaVu Sans";
constexpr double kPi = 3.14159265358979323846;

/// Font options of every context: grey anti-aliasing and unhinted metrics (advances do not
/// depend on the surface); outlines slightly hinted on raster surfaces only.
void setFontOptions(cairo_t* cr, bool raster) {
  const CairoPtr<cairo_font_options_t> options(cairo_font_options_create());
  cairo_font_options_set_antialias(options.get(), CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_metrics(options.get(), CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_hint_style(options.get(),
                                    raster ? CAIRO_HINT_STYLE_SLIGHT : CAIRO_HINT_STYLE_NONE);
  checkCairo(cairo_font_options_status(options.get()), "cannot set the font options");
  cairo_set_font_options(cr, options.get());
}

void selectFont(cairo_t* cr, const TextStyle& style) {
  cairo_select_font_face(cr, kFontFamily, CAIRO_FONT_SLANT_NORMAL,
                         style.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, style.size_px);
}

void setSource(cairo_t* cr, Rgb color) {
  cairo_set_source_rgb(cr, color.r / 255.0, color.g / 255.0, color.b / 255.0);
}

/// Cairo rejects text that is not UTF-8 (and the context with it): invalid bytes become
/// U+FFFD.
std::string validUtf8(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(text[i]); };
  const auto continuation = [&](std::size_t i, std::uint8_t lo = 0x80, std::uint8_t hi = 0xBF) {
    return i < text.size() && byte(i) >= lo && byte(i) <= hi;
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const std::uint8_t c = byte(i);
    std::size_t length = 0;
    if (c < 0x80) {
      length = 1;
    } else if (c >= 0xC2 && c <= 0xDF) {
      length = continuation(i + 1) ? 2 : 0;
    } else if (c >= 0xE0 && c <= 0xEF) {
      const std::uint8_t lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
      length = continuation(i + 1, lo, hi) && continuation(i + 2) ? 3 : 0;
    } else if (c >= 0xF0 && c <= 0xF4) {
      const std::uint8_t lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
      length = continuation(i + 1, lo, hi) && continuation(i + 2) && continuation(i + 3) ? 4 : 0;
    }
    if (length == 0) {
      out += "\xEF\xBF\xBD";
      ++i;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

/// `v` moved to where a line of `width_px` along the pixel grid covers whole pixels: a pixel
/// centre for odd widths, a pixel edge for even ones.
double crisp(double v, double width_px) {
  const long width = std::max(1L, std::lround(width_px));
  return width % 2 == 1 ? std::floor(v) + 0.5 : std::round(v);
}

void setStroke(cairo_t* cr, const Stroke& stroke) {
  setSource(cr, stroke.color);
  cairo_set_line_width(cr, stroke.width_px);
  if (stroke.dashed) {
    const double unit = std::max(1.0, stroke.width_px);
    const double dashes[] = {6.0 * unit, 4.0 * unit};
    cairo_set_dash(cr, dashes, 2, 0.0);
  }
}

/// An 8-bit BGR copy of `image` (grey and BGRA converted).
cv::Mat bgrImage(const cv::Mat& image) {
  if (image.depth() != CV_8U) throw InvalidArgument("figure images must be 8-bit");
  cv::Mat bgr;
  switch (image.channels()) {
    case 1:
      cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
      break;
    case 3:
      bgr = image;
      break;
    case 4:
      cv::cvtColor(image, bgr, cv::COLOR_BGRA2BGR);
      break;
    default:
      throw InvalidArgument("figure images must be grey, BGR or BGRA");
  }
  return bgr;
}

/// A Cairo RGB24 surface holding the pixels of `bgr`.
CairoPtr<cairo_surface_t> cairoImage(const cv::Mat& bgr) {
  CairoPtr<cairo_surface_t> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, bgr.cols, bgr.rows));
  checkCairo(cairo_surface_status(surface.get()), "cannot create a figure image");
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y);
    auto* out = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < bgr.cols; ++x) {
      out[x] = 0xFF000000u | (std::uint32_t{in[x][2]} << 16) | (std::uint32_t{in[x][1]} << 8) |
               std::uint32_t{in[x][0]};
    }
  }
  cairo_surface_mark_dirty(surface.get());
  return surface;
}

/// A context for measuring text as the canvases draw it.
struct TextMeasure {
  CairoPtr<cairo_surface_t> surface{cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1)};
  CairoPtr<cairo_t> cr{cairo_create(surface.get())};
  TextMeasure() {
    checkCairo(cairo_status(cr.get()), "cannot create a context to measure text");
    setFontOptions(cr.get(), false);
  }
};

}  // namespace

void checkCairo(cairo_status_t status, std::string_view what) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cairo: " + std::string(what) + ": " + cairo_status_to_string(status));
  }
}

double textWidth(std::string_view text, const TextStyle& style) {
  if (text.empty()) return 0.0;
  thread_local TextMeasure measure;
  cairo_t* cr = measure.cr.get();
  selectFont(cr, style);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, validUtf8(text).c_str(), &extents);
  const cairo_status_t status = cairo_status(cr);
  if (status != CAIRO_STATUS_SUCCESS) {
    measure = TextMeasure();  // a Cairo context stays in error: the next call starts afresh
    checkCairo(status, "cannot measure text");
  }
  return extents.x_advance;
}

CairoCanvas::CairoCanvas(cairo_t* cr)
    : cr_(cr), svg_(cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_SVG) {
  setFontOptions(cr_, cairo_surface_get_type(cairo_get_target(cr)) == CAIRO_SURFACE_TYPE_IMAGE);
}

CairoCanvas::~CairoCanvas() {
  while (open_clips_ > 0) popClip();
}

void CairoCanvas::fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view) {
  const double x0 = std::round(rect.x), y0 = std::round(rect.y);
  const double x1 = std::round(rect.x + rect.width), y1 = std::round(rect.y + rect.height);
  if (x1 <= x0 || y1 <= y0) return;
  cairo_save(cr_);
  setSource(cr_, fill);
  cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  cairo_fill(cr_);
  cairo_restore(cr_);
}

void CairoCanvas::strokeRect(const cv::Rect2d& rect, const Stroke& stroke) {
  const double x0 = crisp(rect.x, stroke.width_px), y0 = crisp(rect.y, stroke.width_px);
  const double x1 = crisp(rect.x + rect.width, stroke.width_px);
  const double y1 = crisp(rect.y + rect.height, stroke.width_px);
  cairo_save(cr_);
  setStroke(cr_, stroke);
  cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void CairoCanvas::line(cv::Point2d a, cv::Point2d b, const Stroke& stroke, std::string_view) {
  if (a.x == b.x) a.x = b.x = crisp(a.x, stroke.width_px);
  if (a.y == b.y) a.y = b.y = crisp(a.y, stroke.width_px);
  cairo_save(cr_);
  setStroke(cr_, stroke);
  cairo_move_to(cr_, a.x, a.y);
  cairo_line_to(cr_, b.x, b.y);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void CairoCanvas::polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                           std::string_view) {
  if (points.size() < 2) return;
  cairo_save(cr_);
  setStroke(cr_, stroke);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
  cairo_move_to(cr_, points.front().x, points.front().y);
  for (std::size_t k = 1; k < points.size(); ++k) cairo_line_to(cr_, points[k].x, points[k].y);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void CairoCanvas::circle(cv::Point2d centre, double radius_px, Rgb fill) {
  if (!(radius_px > 0.0)) return;
  cairo_save(cr_);
  setSource(cr_, fill);
  cairo_new_path(cr_);
  cairo_arc(cr_, centre.x, centre.y, radius_px, 0.0, 2.0 * kPi);
  cairo_fill(cr_);
  cairo_restore(cr_);
}

void CairoCanvas::text(cv::Point2d anchor, std::string_view text, const TextStyle& style) {
  if (text.empty()) return;
  const std::string utf8 = validUtf8(text);
  cairo_save(cr_);
  selectFont(cr_, style);
  cairo_text_extents_t extents;
  cairo_text_extents(cr_, utf8.c_str(), &extents);
  const double shift = style.anchor == TextAnchor::kStart    ? 0.0
                       : style.anchor == TextAnchor::kMiddle ? extents.x_advance / 2.0
                                                             : extents.x_advance;
  cairo_translate(cr_, anchor.x, anchor.y);
  if (style.vertical) cairo_rotate(cr_, -kPi / 2.0);
  cairo_move_to(cr_, -shift, 0.0);
  setSource(cr_, style.color);
  cairo_show_text(cr_, utf8.c_str());
  cairo_new_path(cr_);
  cairo_restore(cr_);
}

void CairoCanvas::image(const cv::Mat& image, const cv::Rect2d& rect) {
  if (image.empty() || !(rect.width > 0.0) || !(rect.height > 0.0)) return;
  cv::Mat bgr = bgrImage(image);
  const bool enlarged = rect.width >= bgr.cols && rect.height >= bgr.rows;
  if (enlarged && svg_) {
    const cv::Size drawn(static_cast<int>(std::lround(rect.width)),
                         static_cast<int>(std::lround(rect.height)));
    cv::resize(bgr, bgr, drawn, 0, 0, cv::INTER_NEAREST);
  }
  const CairoPtr<cairo_surface_t> surface = cairoImage(bgr);
  cairo_save(cr_);
  cairo_rectangle(cr_, rect.x, rect.y, rect.width, rect.height);
  cairo_clip(cr_);
  cairo_translate(cr_, rect.x, rect.y);
  cairo_scale(cr_, rect.width / bgr.cols, rect.height / bgr.rows);
  cairo_set_source_surface(cr_, surface.get(), 0.0, 0.0);
  cairo_pattern_set_filter(cairo_get_source(cr_),
                           enlarged ? CAIRO_FILTER_NEAREST : CAIRO_FILTER_GOOD);
  cairo_paint(cr_);
  cairo_restore(cr_);
}

void CairoCanvas::pushClip(const cv::Rect2d& rect) {
  cairo_save(cr_);
  cairo_rectangle(cr_, rect.x, rect.y, std::max(0.0, rect.width), std::max(0.0, rect.height));
  cairo_clip(cr_);
  ++open_clips_;
}

void CairoCanvas::popClip() {
  if (open_clips_ == 0) return;
  cairo_restore(cr_);
  --open_clips_;
}

}  // namespace roomscout::plots
