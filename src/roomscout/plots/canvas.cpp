#include "roomscout/plots/canvas.hpp"

#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "roomscout/plots/hershey_text.hpp"

namespace roomscout::plots {

double textWidth(std::string_view text, const TextStyle& style) {
  return hersheyTextSize(text, style).width;
}

}  // namespace roomscout::plots
