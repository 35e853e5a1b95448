#include "roomscout/plots/hershey_text.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

namespace roomscout::plots {

HersheyFont hersheyFont(const TextStyle& style) {
  const auto cap_height = [](int face) {
    int baseline = 0;
    return static_cast<double>(cv::getTextSize("H", face, 1.0, 1, &baseline).height);
  };
  // Bold is the double-stroked face: a thicker single stroke smears small text.
  static const double simplex_cap = cap_height(cv::FONT_HERSHEY_SIMPLEX);
  static const double duplex_cap = cap_height(cv::FONT_HERSHEY_DUPLEX);
  HersheyFont font;
  font.face = style.bold ? cv::FONT_HERSHEY_DUPLEX : cv::FONT_HERSHEY_SIMPLEX;
  font.scale = 0.72 * style.size_px / (style.bold ? duplex_cap : simplex_cap);
  font.thickness = std::max(1, static_cast<int>(std::lround(style.size_px / 18.0)));
  return font;
}

TextExtent hersheyTextSize(std::string_view text, const TextStyle& style) {
  const HersheyFont font = hersheyFont(style);
  int baseline = 0;
  const cv::Size size =
      cv::getTextSize(std::string(text), font.face, font.scale, font.thickness, &baseline);
  return {static_cast<double>(size.width), static_cast<double>(size.height),
          static_cast<double>(baseline)};
}

}  // namespace roomscout::plots
