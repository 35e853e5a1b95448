#pragma once
// A Canvas that records every drawing call with its role, so tests can check what a figure
// draws (which series, bars, labels, where) apart from how Cairo renders it.

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "roomscout/plots/canvas.hpp"
#include "roomscout/plots/figure.hpp"

namespace roomscout::plots::test {

class RecordingCanvas final : public Canvas {
 public:
  struct Fill {
    cv::Rect2d rect;
    Rgb color;
    std::string role;
  };
  struct Line {
    cv::Point2d a, b;
    Stroke stroke;
    std::string role;
  };
  struct Polyline {
    std::vector<cv::Point2d> points;
    Stroke stroke;
    std::string role;
  };
  struct Circle {
    cv::Point2d centre;
    double radius_px;
    Rgb color;
  };
  struct Text {
    cv::Point2d anchor;
    std::string text;
    TextStyle style;
  };
  struct Image {
    cv::Size size;  ///< of the image drawn
    cv::Rect2d rect;
    int clip_depth;  ///< clips open when it was drawn
  };

  std::vector<Fill> fills;
  std::vector<cv::Rect2d> stroked_rects;
  std::vector<Line> lines;
  std::vector<Polyline> polylines;
  std::vector<Circle> circles;
  std::vector<Text> texts;
  std::vector<Image> images;
  std::vector<cv::Rect2d> clips;  ///< every pushClip() in order
  int clip_depth = 0;             ///< clips open now
  bool unbalanced_pop = false;    ///< a popClip() without an open clip

  void fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view role) override {
    fills.push_back({rect, fill, std::string(role)});
  }
  void strokeRect(const cv::Rect2d& rect, const Stroke&) override { stroked_rects.push_back(rect); }
  void line(cv::Point2d a, cv::Point2d b, const Stroke& stroke, std::string_view role) override {
    lines.push_back({a, b, stroke, std::string(role)});
  }
  void polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                std::string_view role) override {
    polylines.push_back({points, stroke, std::string(role)});
  }
  void circle(cv::Point2d centre, double radius_px, Rgb fill) override {
    circles.push_back({centre, radius_px, fill});
  }
  void text(cv::Point2d anchor, std::string_view text, const TextStyle& style) override {
    texts.push_back({anchor, std::string(text), style});
  }
  void image(const cv::Mat& image, const cv::Rect2d& rect) override {
    images.push_back({image.size(), rect, clip_depth});
  }
  void pushClip(const cv::Rect2d& rect) override {
    clips.push_back(rect);
    ++clip_depth;
  }
  void popClip() override {
    if (clip_depth == 0) unbalanced_pop = true;
    clip_depth = std::max(0, clip_depth - 1);
  }

  /// Fills, lines and polylines (with at least two points) of `role`.
  std::size_t count(std::string_view role) const {
    const auto is = [&](const auto& e) { return e.role == role; };
    return std::count_if(fills.begin(), fills.end(), is) +
           std::count_if(lines.begin(), lines.end(), is) +
           std::count_if(polylines.begin(), polylines.end(),
                         [&](const Polyline& p) { return p.role == role && p.points.size() >= 2; });
  }
  std::vector<Fill> fillsOf(std::string_view role) const {
    std::vector<Fill> out;
    for (const Fill& f : fills)
      if (f.role == role) out.push_back(f);
    return out;
  }
  std::vector<Line> linesOf(std::string_view role) const {
    std::vector<Line> out;
    for (const Line& l : lines)
      if (l.role == role) out.push_back(l);
    return out;
  }
  std::vector<Polyline> polylinesOf(std::string_view role) const {
    std::vector<Polyline> out;
    for (const Polyline& p : polylines)
      if (p.role == role && p.points.size() >= 2) out.push_back(p);
    return out;
  }
  /// The text drawn exactly as `s`, or nullptr.
  const Text* findText(std::string_view s) const {
    for (const Text& t : texts)
      if (t.text == s) return &t;
    return nullptr;
  }
  bool hasText(std::string_view s) const { return findText(s) != nullptr; }
  /// Some text contains `part`.
  bool anyTextContains(std::string_view part) const {
    return std::any_of(texts.begin(), texts.end(),
                       [&](const Text& t) { return t.text.find(part) != std::string::npos; });
  }
};

/// What `figure` draws.
inline RecordingCanvas record(const Figure& figure) {
  RecordingCanvas canvas;
  figure.draw(canvas);
  return canvas;
}

}  // namespace roomscout::plots::test
