// `roomscout report` end to end in a browser: a short bench on a tiny map (its seed-1 runs give
// the map figures), then the report, then report.html in headless Chromium: every table and
// figure must render, with no script or loading error. Label "browser"; see
// tests/plots/browser_support.hpp for how Chromium is found.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>

#include <opencv2/imgcodecs.hpp>

#include "../plots/browser_support.hpp"
#include "../support/temp_dir.hpp"
#include "roomscout/maps/semantic_map.hpp"
#include "two_room_world.hpp"

namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Appended to a copy of the page: after loading, it writes what rendered into #check.
constexpr const char* kCheckScript = R"html(
<pre id="check">pending</pre>
<script>
var check_errors = 0;
window.addEventListener('error', function () { check_errors++; }, true);
window.addEventListener('load', function () {
  var figures = document.querySelectorAll('figure.report-figure');
  var svg_ok = 0, svg_images = 0, images_ok = 0, broken_refs = 0;
  figures.forEach(function (f) {
    var svg = f.querySelector(':scope > svg');
    if (!svg) return;
    // Glyphs and images are defined once and placed by <use>; each must find its target in
    // its own figure. A placed image is measured where its <use> puts it.
    var uses = svg.querySelectorAll('use');
    uses.forEach(function (u) {
      var href = u.getAttribute('href') || u.getAttribute('xlink:href') || '';
      var target = document.getElementById(href.slice(1));
      if (!target || !svg.contains(target)) {
        broken_refs++;
      } else if (target.tagName === 'image') {
        var r = u.getBoundingClientRect();
        if (r.width > 20 && r.height > 20) images_ok++;
      }
    });
    var box = svg.getBoundingClientRect();
    if (box.width > 100 && box.height > 100 && uses.length > 0) svg_ok++;
    svg_images += svg.querySelectorAll('image').length;
  });
  var tables = document.querySelectorAll('table.report-table');
  var tables_ok = 0, cells = 0, empty_tables = 0;
  tables.forEach(function (t) {
    var n = t.querySelectorAll('tbody td').length;
    cells += n;
    if (t.getBoundingClientRect().height > 20 && n > 0) tables_ok++;
  });
  document.getElementById('check').textContent =
      'tables=' + tables.length + ' tables_ok=' + tables_ok + ' figures=' + figures.length +
      ' svg_ok=' + svg_ok + ' svg_images=' + svg_images + ' images_ok=' + images_ok +
      ' broken_refs=' + broken_refs + ' errors=' + check_errors;
});
</script>
)html";

class ReportBrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    chromium_ = roomscout::test::findChromium();
    if (!chromium_) {
      if (roomscout::test::browserRequired()) {
        FAIL() << "ROOMSCOUT_BROWSER_TESTS=1 but no Chromium found (scripts/setup.sh installs it)";
      }
      GTEST_SKIP() << "no Chromium (apt-get install chromium, or ROOMSCOUT_BROWSER_TESTS=1 "
                      "scripts/setup.sh)";
    }
    fs::create_directories(dir_ / "tiny");
    roomscout::test::writeTwoRoomWorld(dir_ / "tiny");
  }
  /// Runs the roomscout binary; exit code and output.
  std::pair<int, std::string> run(const std::string& args) {
    const fs::path log = dir_ / "log.txt";
    const int status = std::system(
        (std::string(ROOMSCOUT_BINARY) + " " + args + " > " + log.string() + " 2>&1").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(log)};
  }

  /// Bench (2 methods x 2 seeds, at most 60 s simulated each) and report into dir_/report.
  void benchAndReport() {
    auto [code, output] = run("bench --worlds " + (dir_ / "tiny" / "rooms.yaml").string() +
                              " --methods nearest_frontier,mmpf --seeds 2 --jobs 2 --max-time 60"
                              " --out " +
                              (dir_ / "bench").string());
    ASSERT_EQ(code, 0) << output;
    std::tie(code, output) =
        run("report " + (dir_ / "bench").string() + " --out " + (dir_ / "report").string());
    ASSERT_EQ(code, 0) << output;
    EXPECT_EQ(output.find("note:"), std::string::npos) << output;
    ASSERT_TRUE(fs::exists(dir_ / "report" / "report.html")) << output;
  }

  std::optional<fs::path> chromium_;
  roomscout::test::TempDir tmp_;
  const fs::path dir_ = tmp_.path();
};

TEST_F(ReportBrowserTest, EveryTableAndFigureRenders) {
  benchAndReport();
  std::string html = readFile(dir_ / "report" / "report.html");
  const std::size_t body_end = html.rfind("</body>");
  ASSERT_NE(body_end, std::string::npos);
  html.insert(body_end, kCheckScript);
  std::ofstream(dir_ / "report" / "checked.html", std::ios::binary) << html;
  fs::create_directories(dir_ / "chromium");
  const int status = roomscout::test::runChromium(
      *chromium_, dir_ / "chromium", "--virtual-time-budget=5000 --dump-dom",
      dir_ / "report" / "checked.html", dir_ / "dom.html");
  const std::string log = readFile(dir_ / "chromium" / "chromium.log");
  ASSERT_EQ(status, 0) << log;
  const std::string dom = readFile(dir_ / "dom.html");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(dom, match, std::regex("<pre id=\"check\">([^<]*)</pre>")))
      << dom.substr(0, 2000) << "\n"
      << log;
  // Tables I, revisits, oracle reference, II, III; Fig. 5, 6 (2 map panels), 7 (4 maps) and
  // the revisits charts (whole run, up to T98), all inline SVG.
  EXPECT_EQ(
      match[1].str(),
      "tables=5 tables_ok=5 figures=5 svg_ok=5 svg_images=6 images_ok=6 broken_refs=0 errors=0");
}

TEST_F(ReportBrowserTest, ScreenshotShowsMethodsAndTrajectories) {
  benchAndReport();
  fs::create_directories(dir_ / "chromium");
  const int status = roomscout::test::runChromium(
      *chromium_, dir_ / "chromium",
      "--window-size=1280,6000 --screenshot=" + roomscout::test::shellQuoted(dir_ / "shot.png"),
      dir_ / "report" / "report.html", dir_ / "stdout.txt");
  ASSERT_EQ(status, 0) << readFile(dir_ / "chromium" / "chromium.log");
  const cv::Mat shot = cv::imread((dir_ / "shot.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(shot.empty());
  const auto pixelsNear = [&](int r, int g, int b, int tolerance) {
    int n = 0;
    for (int y = 0; y < shot.rows; ++y) {
      for (int x = 0; x < shot.cols; ++x) {
        const cv::Vec3b p = shot.at<cv::Vec3b>(y, x);
        n += std::abs(p[0] - b) <= tolerance && std::abs(p[1] - g) <= tolerance &&
             std::abs(p[2] - r) <= tolerance;
      }
    }
    return n;
  };
  // The curves (the second method's orange is drawn over the first's blue where they agree),
  // the maps with their rooms coloured (Fig. 6 and 7), and the trajectories' blue over them.
  EXPECT_GT(pixelsNear(255, 127, 14, 10), 300);
  const std::array<std::uint8_t, 3> room = roomscout::SemanticMap::colourOf(1);
  EXPECT_GT(pixelsNear(room[0], room[1], room[2], 10), 20000);
  EXPECT_GT(pixelsNear(20, 90, 200, 12), 100);
}

}  // namespace
