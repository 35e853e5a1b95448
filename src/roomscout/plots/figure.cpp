#include "roomscout/plots/figure.hpp"

#include "roomscout/io/atomic_file.hpp"
#include "roomscout/plots/png_canvas.hpp"
#include "roomscout/plots/svg_canvas.hpp"

namespace roomscout::plots {

Figure renderFigure(const FigureSize& size, const std::function<void(Canvas&)>& draw) {
  PngCanvas png(size.width_px, size.height_px);
  SvgCanvas svg(size.width_px, size.height_px);
  draw(png);
  draw(svg);
  return {png.image(), svg.svg()};
}

FigureFiles writeFigure(const Figure& figure, const std::filesystem::path& stem) {
  FigureFiles files{stem, stem};
  files.png += ".png";
  files.svg += ".svg";
  io::writeImageAtomic(files.png, figure.image);
  io::writeFileAtomic(files.svg, figure.svg);
  return files;
}

}  // namespace roomscout::plots
