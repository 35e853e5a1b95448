#include "roomscout/plots/svg_canvas.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/errors.hpp"
#include "roomscout/plots/text_encoding.hpp"

namespace roomscout::plots {
namespace {

/// A coordinate with at most two decimals, trailing zeros dropped.
std::string num(double v) {
  if (std::abs(v) < 0.005) v = 0.0;
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

std::string roleAttribute(std::string_view role) {
  return role.empty() ? std::string() : " class=\"" + escapeXml(role) + "\"";
}

std::string strokeAttributes(const Stroke& stroke) {
  std::string s =
      " stroke=\"" + toHex(stroke.color) + "\" stroke-width=\"" + num(stroke.width_px) + "\"";
  if (stroke.dashed) {
    const double w = std::max(1.0, stroke.width_px);
    s += " stroke-dasharray=\"" + num(6 * w) + " " + num(4 * w) + "\"";
  }
  return s;
}

}  // namespace

SvgCanvas::SvgCanvas(int width_px, int height_px) : width_px_(width_px), height_px_(height_px) {
  if (width_px < 1 || height_px < 1) throw InvalidArgument("figure size must be at least 1 x 1 px");
}

std::string SvgCanvas::svg() const {
  const std::string w = std::to_string(width_px_), h = std::to_string(height_px_);
  std::string out =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" "
      "xmlns:xlink=\"http://www.w3.org/1999/xlink\" version=\"1.1\" width=\"" +
      w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h +
      "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
  out += "<rect x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"#ffffff\"/>\n";
  out += body_;
  for (int k = 0; k < open_clips_; ++k) out += "</svg>\n";
  out += "</svg>\n";
  return out;
}

void SvgCanvas::fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view role) {
  body_ += "<rect x=\"" + num(rect.x) + "\" y=\"" + num(rect.y) + "\" width=\"" + num(rect.width) +
           "\" height=\"" + num(rect.height) + "\" fill=\"" + toHex(fill) + "\"" +
           roleAttribute(role) + "/>\n";
}

void SvgCanvas::strokeRect(const cv::Rect2d& rect, const Stroke& stroke) {
  body_ += "<rect x=\"" + num(rect.x) + "\" y=\"" + num(rect.y) + "\" width=\"" + num(rect.width) +
           "\" height=\"" + num(rect.height) + "\" fill=\"none\"" + strokeAttributes(stroke) +
           "/>\n";
}

void SvgCanvas::line(cv::Point2d a, cv::Point2d b, const Stroke& stroke, std::string_view role) {
  body_ += "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" +
           num(b.y) + "\"" + strokeAttributes(stroke) + roleAttribute(role) + "/>\n";
}

void SvgCanvas::polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                         std::string_view role) {
  if (points.size() < 2) return;
  body_ += "<polyline points=\"";
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (k) body_ += ' ';
    body_ += num(points[k].x) + "," + num(points[k].y);
  }
  body_ += "\" fill=\"none\"" + strokeAttributes(stroke) +
           " stroke-linejoin=\"round\" stroke-linecap=\"round\"" + roleAttribute(role) + "/>\n";
}

void SvgCanvas::circle(cv::Point2d centre, double radius_px, Rgb fill) {
  body_ += "<circle cx=\"" + num(centre.x) + "\" cy=\"" + num(centre.y) + "\" r=\"" +
           num(radius_px) + "\" fill=\"" + toHex(fill) + "\"/>\n";
}

void SvgCanvas::text(cv::Point2d anchor, std::string_view text, const TextStyle& style) {
  if (text.empty()) return;
  body_ += "<text x=\"" + num(anchor.x) + "\" y=\"" + num(anchor.y) + "\" font-size=\"" +
           num(style.size_px) + "\" fill=\"" + toHex(style.color) + "\"";
  if (style.anchor == TextAnchor::kMiddle) body_ += " text-anchor=\"middle\"";
  if (style.anchor == TextAnchor::kEnd) body_ += " text-anchor=\"end\"";
  if (style.bold) body_ += " font-weight=\"bold\"";
  if (style.vertical) {
    body_ += " transform=\"rotate(-90 " + num(anchor.x) + " " + num(anchor.y) + ")\"";
  }
  body_ += '>';
  body_ += escapeXml(text);
  body_ += "</text>\n";
}

void SvgCanvas::image(const cv::Mat& image, const cv::Rect2d& rect) {
  if (image.empty()) return;
  if (image.depth() != CV_8U) throw InvalidArgument("figure images must be 8-bit");
  std::vector<std::uint8_t> png;
  if (!cv::imencode(".png", image, png))
    throw InvalidArgument("cannot encode a figure image as PNG");
  body_ += "<image x=\"" + num(rect.x) + "\" y=\"" + num(rect.y) + "\" width=\"" + num(rect.width) +
           "\" height=\"" + num(rect.height) +
           "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" "
           "xlink:href=\"data:image/png;base64," +
           encodeBase64(std::string_view(reinterpret_cast<const char*>(png.data()), png.size())) +
           "\"/>\n";
}

void SvgCanvas::pushClip(const cv::Rect2d& rect) {
  // A nested viewport clips its content; its viewBox keeps the outer coordinates.
  body_ += "<svg x=\"" + num(rect.x) + "\" y=\"" + num(rect.y) + "\" width=\"" + num(rect.width) +
           "\" height=\"" + num(rect.height) + "\" viewBox=\"" + num(rect.x) + " " + num(rect.y) +
           " " + num(rect.width) + " " + num(rect.height) + "\" overflow=\"hidden\">\n";
  ++open_clips_;
}

void SvgCanvas::popClip() {
  if (open_clips_ == 0) return;
  body_ += "</svg>\n";
  --open_clips_;
}

}  // namespace roomscout::plots
