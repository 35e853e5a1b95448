#include "roomscout/plots/html_report.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include <opencv2/imgcodecs.hpp>

#include "plot_test_support.hpp"
#include "roomscout/core/errors.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/plots/svg_ids.hpp"
#include "roomscout/plots/text_encoding.hpp"

namespace roomscout::plots {
namespace {

using test::count;

/// The values of `marker`...`end` in `text` (e.g. every id="...").
std::vector<std::string> valuesAfter(const std::string& text, const std::string& marker, char end) {
  std::vector<std::string> values;
  for (std::size_t at = text.find(marker); at != std::string::npos;
       at = text.find(marker, at + 1)) {
    const std::size_t start = at + marker.size();
    values.push_back(text.substr(start, text.find(end, start) - start));
  }
  return values;
}

HtmlPage examplePage() {
  HtmlPage page;
  page.title = "roomscout benchmark <report>";
  page.intro = {{"3 worlds x 3 methods x 2 seeds."}};
  HtmlSection results{"Results", {}};
  results.blocks.push_back(HtmlParagraph{"Exploration time and length at 98 %."});
  results.blocks.push_back(HtmlTable{"Table I",
                                     {"world", "method", "T98 [s]", "L98 [m]"},
                                     {{"small_house", "semantic", "412.5", "61.2"},
                                      {"small_house", "rrt", "530.0 ± 12.1", "80.4"},
                                      {"large_office", "a|b", "-", "n/a"}}});
  results.blocks.push_back(htmlFigure(renderLineChart(test::exampleLineChart()), "Fig. 5"));
  HtmlSection maps{"Maps", {}};
  maps.blocks.push_back(
      htmlFigure(renderMapPanels(test::exampleMapPanels()), "Fig. 6", FigureEmbedding::kPng));
  maps.blocks.push_back(HtmlTable{"", {"map", "bytes"}, {{"occupancy", "12000"}, {"semantic"}}});
  maps.blocks.push_back(htmlFigure(renderBarChart(test::exampleBarChart()), "Revisits"));
  page.sections = {results, maps};
  return page;
}

TEST(HtmlReport, ContainsEveryTableAndFigureSelfContained) {
  const HtmlPage page = examplePage();
  const std::string html = renderHtml(page);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_TRUE(test::TagsBalanced(html));
  EXPECT_NE(html.find("<title>roomscout benchmark &lt;report&gt;</title>"), std::string::npos);
  EXPECT_EQ(count(html, "<table class=\"report-table\">"), 2u);
  EXPECT_EQ(count(html, "<figure class=\"report-figure\">"), 3u);
  EXPECT_EQ(count(html, "<section id=\"section-"), 2u);
  EXPECT_NE(html.find("<a href=\"#section-2\">Maps</a>"), std::string::npos);
  // Every cell, escaped; short rows padded.
  for (const char* cell : {"<th>T98 [s]</th>", ">412.5</td>", ">530.0 ± 12.1</td>", ">a|b</td>",
                           "<td class=\"num\">12000</td>", "<caption>Table I</caption>"}) {
    EXPECT_NE(html.find(cell), std::string::npos) << cell;
  }
  EXPECT_NE(html.find("<td>semantic</td><td></td>"), std::string::npos);
  EXPECT_NE(html.find("<td>small_house</td>"), std::string::npos);
  // Figures: SVG inline with the ids of the page's first figure, the PNG one as a data URI
  // of the rendered image.
  const HtmlSection& results = page.sections[0];
  const std::string& svg = std::get<HtmlFigure>(results.blocks[2]).svg;
  EXPECT_NE(html.find(numberSvgIds(svg.substr(svg.find("<svg")), "fig1-")), std::string::npos);
  EXPECT_EQ(count(html, "<img "), 1u);
  const std::string& png = std::get<HtmlFigure>(page.sections[1].blocks[0]).png_bytes;
  EXPECT_NE(html.find("src=\"data:image/png;base64," + encodeBase64(png) + "\""),
            std::string::npos);
  for (const char* caption : {"<figcaption>Fig. 5</figcaption>", "<figcaption>Fig. 6</figcaption>",
                              "<figcaption>Revisits</figcaption>"}) {
    EXPECT_NE(html.find(caption), std::string::npos) << caption;
  }
  // Nothing is fetched from elsewhere (url(#id) names an element of the page).
  for (const char* external : {"http://", "https://", "<link", "<script"}) {
    std::string rest = html;
    // The SVG namespaces are names, not fetched resources.
    for (const char* ns : {"http://www.w3.org/2000/svg", "http://www.w3.org/1999/xlink"}) {
      for (std::size_t at; (at = rest.find(ns)) != std::string::npos;)
        rest.erase(at, std::strlen(ns));
    }
    EXPECT_EQ(rest.find(external), std::string::npos) << external;
  }
  for (const std::string& url : valuesAfter(html, "url(", ')')) {
    EXPECT_EQ(url.rfind('#', 0), 0u) << url;
  }
}

TEST(HtmlReport, SvgIdsAreUniqueOnThePageAndReferencesStayInTheirFigure) {
  const std::string html = renderHtml(examplePage());
  const std::vector<std::string> ids = valuesAfter(html, " id=\"", '"');
  EXPECT_GT(ids.size(), 20u);  // glyphs, clips, surfaces
  EXPECT_EQ(std::set<std::string>(ids.begin(), ids.end()).size(), ids.size());
  std::size_t figures = 0, references = 0;
  for (std::size_t at = html.find("<figure "); at != std::string::npos;
       at = html.find("<figure ", at + 1)) {
    ++figures;
    const std::string figure = html.substr(at, html.find("</figure>", at) - at);
    const std::vector<std::string> own = valuesAfter(figure, " id=\"", '"');
    const std::set<std::string> own_ids(own.begin(), own.end());
    std::vector<std::string> refs = valuesAfter(figure, "href=\"#", '"');
    for (const std::string& r : valuesAfter(figure, "url(#", ')')) refs.push_back(r);
    for (const std::string& r : refs) EXPECT_EQ(own_ids.count(r), 1u) << r;
    references += refs.size();
  }
  EXPECT_EQ(figures, 3u);
  EXPECT_GT(references, 50u);
}

TEST(HtmlReport, PngFigureDecodesToTheFigureSize) {
  const Figure figure = renderBarChart(test::exampleBarChart());
  const HtmlFigure html = htmlFigure(figure, "bars", FigureEmbedding::kPng);
  EXPECT_TRUE(html.svg.empty());
  const std::vector<std::uint8_t> bytes(html.png_bytes.begin(), html.png_bytes.end());
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_COLOR);
  EXPECT_EQ(decoded.size(), cv::Size(640, 360));
}

TEST(HtmlReport, WritesThePageAtomically) {
  test::TempDir dir;
  const HtmlPage page = examplePage();
  writeHtml(page, dir / "report.html");
  EXPECT_EQ(io::readFile(dir / "report.html"), renderHtml(page));
  EXPECT_THROW(writeHtml(page, dir / "missing" / "report.html"), InputError);
}

TEST(HtmlReport, DropsAnXmlDeclarationAndRejectsEmptyFigures) {
  HtmlPage page;
  page.title = "t";
  page.sections = {{"s", {HtmlFigure{"c", "<?xml version=\"1.0\"?>\n<svg></svg>", ""}}}};
  const std::string html = renderHtml(page);
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_NE(html.find("<svg></svg>"), std::string::npos);
  EXPECT_EQ(html.find("<nav>"), std::string::npos);  // one section: no contents list
  page.sections[0].blocks = {HtmlFigure{"empty", "", ""}};
  EXPECT_THROW(renderHtml(page), InvalidArgument);
}

TEST(HtmlReport, MarkdownTableAlignsNumericColumns) {
  const HtmlTable table{
      "Table I", {"world", "L98 [m]"}, {{"small|house", "61.2"}, {"medium", "80"}}};
  EXPECT_EQ(markdownTable(table),
            "**Table I**\n\n"
            "| world | L98 [m] |\n"
            "| --- | ---: |\n"
            "| small\\|house | 61.2 |\n"
            "| medium | 80 |\n");
}

}  // namespace
}  // namespace roomscout::plots
