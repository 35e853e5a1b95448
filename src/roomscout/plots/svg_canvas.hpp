#pragma once
// Canvas backend that writes an SVG 1.1 document: one element per drawing call, clips as
// nested <svg> viewports (no ids, so several figures can be inlined in one HTML page).

#include <string>

#include "roomscout/plots/canvas.hpp"

namespace roomscout::plots {

class SvgCanvas final : public Canvas {
 public:
  /// An empty white figure of the given size [px] (both >= 1; throws InvalidArgument).
  SvgCanvas(int width_px, int height_px);

  /// The complete document (closes any clip left open).
  std::string svg() const;

  void fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view role = {}) override;
  void strokeRect(const cv::Rect2d& rect, const Stroke& stroke) override;
  void line(cv::Point2d a, cv::Point2d b, const Stroke& stroke,
            std::string_view role = {}) override;
  void polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                std::string_view role = {}) override;
  void circle(cv::Point2d centre, double radius_px, Rgb fill) override;
  void text(cv::Point2d anchor, std::string_view text, const TextStyle& style) override;
  /// Embeds the image as a PNG data URI at its own resolution, shown pixelated.
  void image(const cv::Mat& image, const cv::Rect2d& rect) override;
  void pushClip(const cv::Rect2d& rect) override;
  void popClip() override;

 private:
  int width_px_;
  int height_px_;
  std::string body_;
  int open_clips_ = 0;
};

}  // namespace roomscout::plots
