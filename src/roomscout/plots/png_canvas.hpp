#pragma once
// Canvas backend that rasterises into an OpenCV BGR image (anti-aliased lines, Hershey text).

#include <vector>

#include "roomscout/plots/canvas.hpp"

namespace roomscout::plots {

class PngCanvas final : public Canvas {
 public:
  /// A white BGR image of the given size [px] (both >= 1; throws InvalidArgument otherwise).
  PngCanvas(int width_px, int height_px);

  const cv::Mat& image() const { return image_; }

  void fillRect(const cv::Rect2d& rect, Rgb fill, std::string_view role = {}) override;
  void strokeRect(const cv::Rect2d& rect, const Stroke& stroke) override;
  void line(cv::Point2d a, cv::Point2d b, const Stroke& stroke,
            std::string_view role = {}) override;
  void polyline(const std::vector<cv::Point2d>& points, const Stroke& stroke,
                std::string_view role = {}) override;
  void circle(cv::Point2d centre, double radius_px, Rgb fill) override;
  void text(cv::Point2d anchor, std::string_view text, const TextStyle& style) override;
  void image(const cv::Mat& image, const cv::Rect2d& rect) override;
  void pushClip(const cv::Rect2d& rect) override;
  void popClip() override;

 private:
  /// The image region drawing goes to (the innermost clip) and its top-left corner.
  cv::Mat target();
  cv::Point2d offset() const;
  void segment(cv::Mat& roi, cv::Point2d a, cv::Point2d b, const Stroke& stroke);

  cv::Mat image_;
  std::vector<cv::Rect> clips_;
};

}  // namespace roomscout::plots
