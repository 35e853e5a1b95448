#include "roomscout/plots/figure.hpp"

#include <cstring>

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/plots/detail/cairo_canvas.hpp"
#include "roomscout/plots/svg_ids.hpp"

namespace roomscout::plots {
namespace {

constexpr double kPointsPerPixel = 0.75;  ///< 72 pt per inch over 96 px per inch

void checkFigure(const Figure& figure) {
  if (figure.size.width_px < 1 || figure.size.height_px < 1)
    throw InvalidArgument("figure size must be at least 1 x 1 px");
  if (!figure.draw) throw InvalidArgument("figure has no drawing code");
}

/// Runs the figure's drawing code on `surface` (in figure pixels scaled by `scale`) over a
/// white background.
void drawOn(const Figure& figure, cairo_surface_t* surface, double scale = 1.0) {
  checkCairo(cairo_surface_status(surface), "cannot create a figure surface");
  const CairoPtr<cairo_t> cr(cairo_create(surface));
  checkCairo(cairo_status(cr.get()), "cannot create a drawing context");
  cairo_scale(cr.get(), scale, scale);
  cairo_set_source_rgb(cr.get(), 1.0, 1.0, 1.0);
  cairo_paint(cr.get());
  {
    CairoCanvas canvas(cr.get());
    figure.draw(canvas);
  }
  checkCairo(cairo_status(cr.get()), "cannot draw the figure");
}

/// The figure drawn on an RGB24 image surface.
CairoPtr<cairo_surface_t> raster(const Figure& figure) {
  checkFigure(figure);
  CairoPtr<cairo_surface_t> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, figure.size.width_px, figure.size.height_px));
  drawOn(figure, surface.get());
  cairo_surface_flush(surface.get());
  return surface;
}

/// Cairo's write callback into a std::string (the closure). It must not throw into Cairo.
cairo_status_t appendBytes(void* closure, const unsigned char* data, unsigned int length) {
  try {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  } catch (...) {
    return CAIRO_STATUS_WRITE_ERROR;
  }
}

/// Finishes a vector surface (writing its document) and checks that it went well.
void finish(cairo_surface_t* surface, std::string_view format) {
  cairo_surface_finish(surface);
  checkCairo(cairo_surface_status(surface), "cannot write the figure as " + std::string(format));
}

}  // namespace

Figure makeFigure(const FigureSize& size, std::function<void(Canvas&)> draw) {
  Figure figure{size, std::move(draw)};
  checkFigure(figure);
  return figure;
}

cv::Mat renderImage(const Figure& figure) {
  const CairoPtr<cairo_surface_t> surface = raster(figure);
  const unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  cv::Mat image(figure.size.height_px, figure.size.width_px, CV_8UC3);
  for (int y = 0; y < image.rows; ++y) {
    const unsigned char* row = data + static_cast<std::ptrdiff_t>(y) * stride;
    cv::Vec3b* out = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < image.cols; ++x) {
      std::uint32_t pixel;  // 0x??RRGGBB in native byte order
      std::memcpy(&pixel, row + 4 * x, sizeof pixel);
      out[x] = cv::Vec3b(pixel & 0xFF, (pixel >> 8) & 0xFF, (pixel >> 16) & 0xFF);
    }
  }
  return image;
}

std::string renderPng(const Figure& figure) {
  const CairoPtr<cairo_surface_t> surface = raster(figure);
  std::string png;
  checkCairo(cairo_surface_write_to_png_stream(surface.get(), appendBytes, &png),
             "cannot encode the figure as PNG");
  return png;
}

std::string renderSvg(const Figure& figure) {
  checkFigure(figure);
  std::string svg;
  {
    const CairoPtr<cairo_surface_t> surface(cairo_svg_surface_create_for_stream(
        appendBytes, &svg, figure.size.width_px, figure.size.height_px));
    checkCairo(cairo_surface_status(surface.get()), "cannot create an SVG surface");
    cairo_svg_surface_restrict_to_version(surface.get(), CAIRO_SVG_VERSION_1_1);
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
    drawOn(figure, surface.get());
    finish(surface.get(), "SVG");
  }
  return numberSvgIds(svg);
}

std::string renderPdf(const Figure& figure) {
  checkFigure(figure);
  std::string pdf;
  {
    const CairoPtr<cairo_surface_t> surface(cairo_pdf_surface_create_for_stream(
        appendBytes, &pdf, figure.size.width_px * kPointsPerPixel,
        figure.size.height_px * kPointsPerPixel));
    checkCairo(cairo_surface_status(surface.get()), "cannot create a PDF surface");
    // Cairo dates the document now unless told otherwise; a date it cannot read (an empty
    // one) leaves /CreationDate out.
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, "");
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "roomscout");
    drawOn(figure, surface.get(), kPointsPerPixel);
    finish(surface.get(), "PDF");
  }
  return pdf;
}

FigureFiles writeFigure(const Figure& figure, const std::filesystem::path& stem) {
  FigureFiles files{stem, stem, stem};
  files.png += ".png";
  files.svg += ".svg";
  files.pdf += ".pdf";
  const std::string png = renderPng(figure), svg = renderSvg(figure), pdf = renderPdf(figure);
  io::writeFileAtomic(files.png, png);
  io::writeFileAtomic(files.svg, svg);
  io::writeFileAtomic(files.pdf, pdf);
  return files;
}

}  // namespace roomscout::plots
