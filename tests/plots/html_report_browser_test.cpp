// Opens a report page in headless Chromium and checks that it renders every table and figure.
// Label "browser"; see browser_support.hpp for how Chromium is found.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <regex>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "browser_support.hpp"
#include "plot_test_support.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/plots/html_report.hpp"

namespace roomscout::plots {
namespace {

using roomscout::test::browserRequired;
using roomscout::test::findChromium;
using roomscout::test::shellQuoted;

/// Runs headless Chromium on `page` with `mode_flags`, stdout to `out`; its exit status.
int runChromium(const std::filesystem::path& chromium, const test::TempDir& dir,
                const std::string& mode_flags, const std::filesystem::path& page,
                const std::filesystem::path& out) {
  return roomscout::test::runChromium(chromium, dir.path(), mode_flags, page, out);
}

/// Two tables, three SVG figures (one with map images) and one PNG figure.
HtmlPage browserPage() {
  HtmlPage page;
  page.title = "roomscout report";
  page.intro = {{"Rendered by the browser test."}};
  HtmlSection tables{"Tables", {}};
  tables.blocks.push_back(HtmlTable{"Table I",
                                    {"world", "method", "L98 [m]"},
                                    {{"small_house", "semantic", "61.2"},
                                     {"small_house", "rrt", "80.4"},
                                     {"medium_house", "semantic", "150.0"}}});
  tables.blocks.push_back(
      HtmlTable{"Table II", {"map", "update [ms]"}, {{"occupancy", "1.2"}, {"semantic", "25"}}});
  HtmlSection figures{"Figures", {}};
  figures.blocks.push_back(htmlFigure(renderLineChart(test::exampleLineChart()), "Fig. 5"));
  figures.blocks.push_back(htmlFigure(renderBarChart(test::exampleBarChart()), "Revisits"));
  // Rooms in a colour no chart uses, to find the map images in a screenshot.
  const MapPanelFigure maps = test::exampleMapPanels(cv::Scalar(60, 200, 250));
  figures.blocks.push_back(htmlFigure(renderMapPanels(maps), "Fig. 6 (SVG)"));
  figures.blocks.push_back(
      htmlFigure(renderMapPanels(maps), "Fig. 6 (PNG)", FigureEmbedding::kPng));
  page.sections = {tables, figures};
  return page;
}

/// Appended to a copy of the page: after loading, it writes what rendered into #check.
constexpr const char* kCheckScript = R"html(
<pre id="check">pending</pre>
<script>
var check_errors = 0;
window.addEventListener('error', function () { check_errors++; }, true);
window.addEventListener('load', function () {
  var figures = document.querySelectorAll('figure.report-figure');
  var svg_ok = 0, img_ok = 0, svg_images = 0, broken_refs = 0;
  figures.forEach(function (f) {
    var svg = f.querySelector(':scope > svg');
    if (svg) {
      // Text is glyph outlines placed by <use>; each must find its glyph in its own figure.
      var uses = svg.querySelectorAll('use');
      uses.forEach(function (u) {
        var href = u.getAttribute('href') || u.getAttribute('xlink:href') || '';
        var target = document.getElementById(href.slice(1));
        if (!target || !svg.contains(target)) broken_refs++;
      });
      var box = svg.getBoundingClientRect();
      if (box.width > 100 && box.height > 100 && uses.length > 0) svg_ok++;
      svg_images += svg.querySelectorAll('image').length;
    }
    var img = f.querySelector(':scope > img');
    if (img && img.complete && img.naturalWidth > 100) img_ok++;
  });
  var cells = 0;
  document.querySelectorAll('table.report-table').forEach(function (t) {
    if (t.getBoundingClientRect().height > 20) cells += t.querySelectorAll('td').length;
  });
  document.getElementById('check').textContent =
      'tables=' + document.querySelectorAll('table.report-table').length + ' cells=' + cells +
      ' figures=' + figures.length + ' svg_ok=' + svg_ok + ' svg_images=' + svg_images +
      ' img_ok=' + img_ok + ' broken_refs=' + broken_refs + ' errors=' + check_errors;
});
</script>
)html";

class HtmlReportBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium_ = findChromium();
    if (!chromium_) {
      if (browserRequired()) {
        FAIL() << "ROOMSCOUT_BROWSER_TESTS=1 but no Chromium found (scripts/setup.sh installs it)";
      }
      GTEST_SKIP() << "no Chromium (apt-get install chromium, or ROOMSCOUT_BROWSER_TESTS=1 "
                      "scripts/setup.sh)";
    }
  }
  std::optional<std::filesystem::path> chromium_;
  test::TempDir dir_;
};

TEST_F(HtmlReportBrowser, RendersEveryTableAndFigure) {
  std::string html = renderHtml(browserPage());
  const std::size_t body_end = html.rfind("</body>");
  ASSERT_NE(body_end, std::string::npos);
  html.insert(body_end, kCheckScript);
  io::writeFileAtomic(dir_ / "checked.html", html);
  const int status = runChromium(*chromium_, dir_, "--virtual-time-budget=5000 --dump-dom",
                                 dir_ / "checked.html", dir_ / "dom.html");
  const std::string log = io::readFile(dir_ / "chromium.log");
  ASSERT_EQ(status, 0) << log;
  const std::string dom = io::readFile(dir_ / "dom.html");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(dom, match, std::regex("<pre id=\"check\">([^<]*)</pre>")))
      << dom.substr(0, 2000) << "\n"
      << log;
  EXPECT_EQ(match[1].str(),
            "tables=2 cells=13 figures=4 svg_ok=3 svg_images=4 img_ok=1 broken_refs=0 errors=0");
}

TEST_F(HtmlReportBrowser, ScreenshotShowsChartsAndMaps) {
  writeHtml(browserPage(), dir_ / "report.html");
  const int status = runChromium(
      *chromium_, dir_, "--window-size=1280,3400 --screenshot=" + shellQuoted(dir_ / "shot.png"),
      dir_ / "report.html", dir_ / "stdout.txt");
  ASSERT_EQ(status, 0) << io::readFile(dir_ / "chromium.log");
  const cv::Mat shot = cv::imread((dir_ / "shot.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(shot.empty()) << io::readFile(dir_ / "chromium.log");
  EXPECT_EQ(shot.cols, 1280);
  // Line and bar colours (SVG), the maps' room colour (SVG <image> and <img>), trajectories.
  EXPECT_GT(test::pixelsNear(shot, paletteColor(0), 10), 500);
  EXPECT_GT(test::pixelsNear(shot, paletteColor(1), 10), 500);
  EXPECT_GT(test::pixelsNear(shot, Rgb{250, 200, 60}, 10), 20000);
  EXPECT_GT(test::pixelsNear(shot, colors::kTrajectory, 40), 200);
}

}  // namespace
}  // namespace roomscout::plots
