#pragma once
// How report text maps onto OpenCV's Hershey font: the scale and stroke thickness for a font
// size, and the resulting extent. Shared by PngCanvas (which draws with it) and textWidth()
// (which both backends lay out with).

#include <string_view>

#include <opencv2/core/types.hpp>

#include "roomscout/plots/canvas.hpp"

namespace roomscout::plots {

struct HersheyFont {
  int face = 0;        ///< cv::HersheyFonts value
  double scale = 1.0;  ///< cv::putText fontScale
  int thickness = 1;   ///< stroke [px]
};

/// The Hershey font whose capital letters are about 0.72 em high, as in sans-serif fonts.
HersheyFont hersheyFont(const TextStyle& style);

/// Advance width and ascent of `text` drawn with hersheyFont(style); `descent` below the
/// baseline [px].
struct TextExtent {
  double width = 0.0;
  double ascent = 0.0;
  double descent = 0.0;
};
TextExtent hersheyTextSize(std::string_view text, const TextStyle& style);

}  // namespace roomscout::plots
