// Rendering figures with Cairo: text in real fonts, lines, clips and images on the raster,
// the same drawing in SVG and PDF, reproducible bytes, and errors.

#include "roomscout/plots/figure.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "plot_test_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"

namespace roomscout::plots {
namespace {

using test::count;

/// The bounding box of the pixels that are not white (empty when there are none).
cv::Rect ink(const cv::Mat& bgr) {
  cv::Mat grey, mask;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::threshold(grey, mask, 250, 255, cv::THRESH_BINARY_INV);
  return cv::boundingRect(mask);
}

/// `text` drawn black at `style` with its anchor at (x, y) on a white figure.
cv::Mat renderText(const std::string& text, TextStyle style, cv::Point2d anchor,
                   FigureSize size = {300, 120}) {
  style.color = colors::kBlack;
  return renderImage(makeFigure(size, [=](Canvas& canvas) { canvas.text(anchor, text, style); }));
}

TEST(Figure, TextWidthIsTheDrawnAdvance) {
  TextStyle style;
  style.size_px = 20.0;
  const std::string text = "Nearest frontier 98 %";
  const double width = textWidth(text, style);
  EXPECT_GT(width, 150.0);
  EXPECT_LT(width, 260.0);
  EXPECT_EQ(textWidth("", style), 0.0);
  TextStyle bold = style;
  bold.bold = true;
  EXPECT_GT(textWidth(text, bold), width);
  TextStyle big = style;
  big.size_px = 40.0;
  EXPECT_NEAR(textWidth(text, big), 2.0 * width, 0.5);
  // Ending at x draws where starting at x - width does, to the pixel.
  TextStyle end = style;
  end.anchor = TextAnchor::kEnd;
  const cv::Rect start_ink = ink(renderText(text, style, {20.0, 60.0}));
  const cv::Rect end_ink = ink(renderText(text, end, {20.0 + width, 60.0}));
  EXPECT_LE(std::abs(start_ink.x - end_ink.x), 1);
  EXPECT_LE(std::abs(start_ink.br().x - end_ink.br().x), 1);
  // The ink fits within the advance (DejaVu's side bearings are small).
  EXPECT_GE(start_ink.x, 20);
  EXPECT_LE(start_ink.br().x, 20 + static_cast<int>(std::ceil(width)) + 1);
}

TEST(Figure, DrawsNonAsciiTextWithItsOwnGlyphs) {
  TextStyle style;
  style.size_px = 60.0;
  // A superscript two sits high above the baseline (a missing glyph's box would reach down
  // to it); é is an e with an accent above.
  const cv::Rect two = ink(renderText("\u00b2", style, {20.0, 100.0}));
  ASSERT_GT(two.area(), 0);
  EXPECT_LT(two.br().y, 100 - 15);
  const cv::Rect e = ink(renderText("e", style, {20.0, 100.0}));
  const cv::Rect e_acute = ink(renderText("\u00e9", style, {20.0, 100.0}));
  EXPECT_NEAR(e_acute.br().y, e.br().y, 1);
  EXPECT_LT(e_acute.y, e.y - 8);
  EXPECT_NEAR(e_acute.width, e.width, 3);
  // Bytes that are not UTF-8 still draw (as U+FFFD) instead of failing the figure.
  EXPECT_GT(ink(renderText("bad \xff byte", style, {5.0, 100.0}, {600, 120})).area(), 0);
}

TEST(Figure, VerticalTextReadsUpwardsFromItsAnchor) {
  TextStyle style;
  style.size_px = 20.0;
  style.vertical = true;
  style.anchor = TextAnchor::kMiddle;
  const cv::Mat image = renderText("total time", style, {60.0, 150.0}, {120, 300});
  const cv::Rect box = ink(image);
  EXPECT_GT(box.height, 3 * box.width);
  EXPECT_NEAR(box.y + box.height / 2.0, 150.0, 4.0);
  EXPECT_LE(box.br().x, 62);  // the baseline is at x = 60, glyphs to its left
}

TEST(Figure, LinesAreCrispDashedAndClipped) {
  const Figure figure = makeFigure({200, 100}, [](Canvas& canvas) {
    canvas.line({10.0, 20.0}, {190.0, 20.0}, {colors::kBlack, 1.0, false});
    canvas.line({10.0, 50.0}, {190.0, 50.0}, {colors::kBlack, 2.0, true});
    canvas.pushClip({50.0, 60.0, 100.0, 30.0});
    canvas.fillRect({0.0, 0.0, 200.0, 100.0}, Rgb{214, 39, 40}, "bar");
    canvas.popClip();
    canvas.circle({20.0, 80.0}, 8.0, Rgb{44, 160, 44});
  });
  const cv::Mat image = renderImage(figure);
  // A 1 px line on whole pixels: one black row.
  EXPECT_EQ(test::pixelsNear(image.row(20), colors::kBlack, 0), 180);
  EXPECT_EQ(test::pixelsNear(image.row(19), colors::kWhite, 0), 200);
  EXPECT_EQ(test::pixelsNear(image.row(21), colors::kWhite, 0), 200);
  // Dashes of 12 px and gaps of 8 px.
  const cv::Mat dashed = image.row(50).colRange(10, 190);
  const int on = test::pixelsNear(dashed, colors::kBlack, 60);
  EXPECT_NEAR(on, 180 * 12 / 20, 8);
  // The fill covers its clip and nothing else.
  EXPECT_EQ(test::pixelsNear(image, Rgb{214, 39, 40}, 0), 100 * 30);
  EXPECT_EQ(test::pixelsNear(image(cv::Rect(50, 60, 100, 30)), Rgb{214, 39, 40}, 0), 100 * 30);
  // A filled circle of radius 8.
  EXPECT_NEAR(test::pixelsNear(image, Rgb{44, 160, 44}, 60), 3.14159 * 64, 20);
}

TEST(Figure, ImagesAreGreyOrColourAnd8BitOnly) {
  const cv::Mat grey(10, 10, CV_8U, cv::Scalar(0));
  const cv::Mat deep(10, 10, CV_16U, cv::Scalar(0));
  const cv::Mat image = renderImage(makeFigure({100, 100}, [&](Canvas& canvas) {
    canvas.image(grey, {20.0, 20.0, 40.0, 40.0});
  }));
  EXPECT_EQ(test::pixelsNear(image, colors::kBlack, 0), 40 * 40);
  const Figure bad = makeFigure({100, 100}, [&](Canvas& canvas) {
    canvas.image(deep, {0, 0, 50, 50});
  });
  EXPECT_THROW(renderImage(bad), InvalidArgument);
  EXPECT_THROW(renderSvg(bad), InvalidArgument);
}

TEST(Figure, SvgAndPdfHoldTheDrawing) {
  const Figure figure = renderMapPanels(test::exampleMapPanels());
  const std::string svg = renderSvg(figure);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_TRUE(test::TagsBalanced(svg));
  EXPECT_NE(svg.find("width=\"800px\" height=\"640px\" viewBox=\"0 0 800 640\""),
            std::string::npos);
  EXPECT_GT(count(svg, "<use xlink:href=\"#glyph"), 20u);  // the titles' letters
  EXPECT_EQ(count(svg, "<image "), 4u);
  const std::string pdf = renderPdf(figure);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("DejaVuSans"), std::string::npos);  // the font, embedded
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 600 480 ]"), std::string::npos) << "0.75 pt per px";
  EXPECT_EQ(count(pdf, "/Subtype /Image"), 4u);
}

TEST(Figure, TheSameFigureGivesTheSameBytes) {
  const Figure maps = renderMapPanels(test::exampleMapPanels());
  const Figure chart = renderLineChart(test::exampleLineChart());
  for (const Figure* f : {&maps, &chart}) {
    EXPECT_EQ(renderPng(*f), renderPng(*f));
    EXPECT_EQ(renderSvg(*f), renderSvg(*f));  // Cairo numbers some ids per process
    const std::string pdf = renderPdf(*f);
    EXPECT_EQ(pdf, renderPdf(*f));
    EXPECT_EQ(pdf.find("/CreationDate"), std::string::npos);
  }
}

TEST(Figure, RejectsEmptyFiguresAndUnwritableFiles) {
  EXPECT_THROW(makeFigure({0, 10}, [](Canvas&) {}), InvalidArgument);
  EXPECT_THROW(makeFigure({10, 10}, {}), InvalidArgument);
  EXPECT_THROW(renderPng(Figure{{10, -1}, [](Canvas&) {}}), InvalidArgument);
  test::TempDir dir;
  const Figure figure = renderBarChart(test::exampleBarChart());
  const std::filesystem::path stem = dir / "missing" / "revisits";
  try {
    writeFigure(figure, stem);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), (dir / "missing" / "revisits.png").string());
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

}  // namespace
}  // namespace roomscout::plots
