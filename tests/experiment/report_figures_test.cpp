// The report's figures, oracle column and page: from hand-written results with curves
// (data/results_curves.jsonl), from data/results_small.jsonl with the oracle tours of its
// built-in worlds, and end to end from a short bench on a tiny map.

#include "roomscout/experiment/report_figures.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "../cli/two_room_world.hpp"
#include "../plots/plot_test_support.hpp"
#include "../plots/recording_canvas.hpp"
#include "../support/temp_dir.hpp"
#include "roomscout/experiment/bench_runner.hpp"
#include "roomscout/experiment/oracle_references.hpp"
#include "roomscout/experiment/report.hpp"
#include "roomscout/experiment/report_csv.hpp"
#include "roomscout/experiment/report_figures.hpp"
#include "roomscout/experiment/report_markdown.hpp"
#include "roomscout/experiment/report_writer.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/plots/svg_ids.hpp"

namespace roomscout::experiment {
namespace {

namespace fs = std::filesystem;
using plots::test::record;
using plots::test::RecordingCanvas;

const fs::path kData = fs::path(ROOMSCOUT_SOURCE_DIR) / "tests" / "experiment" / "data";

using roomscout::test::TempDir;

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const ReportFigure* find(const ReportFigures& figures, const std::string& stem) {
  for (const ReportFigure& f : figures.figures) {
    if (f.stem == stem) return &f;
  }
  return nullptr;
}

/// `path` quoted for the shell.
std::string shellQuoted(const fs::path& path) {
  std::string out = "'";
  for (char c : path.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// The executable `name` on PATH, or an empty path.
fs::path findOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (std::size_t start = 0; start <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return {};
}

std::string format(const char* spec, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, v);
  return buf;
}

TEST(ReportFigures, RateCurvesShowTheMedianSeedAndGroupMeans) {
  const ResultSet results = loadResults({kData / "results_curves.jsonl"});
  const Report report = buildReport(results);
  const ReportFigures figures = renderReportFigures(results, report);
  // No run outputs: curves and revisits only.
  std::vector<std::string> stems;
  for (const ReportFigure& f : figures.figures) stems.push_back(f.stem);
  EXPECT_EQ(stems, (std::vector<std::string>{"fig5_rate_small_house", "fig5_rate_he", "revisits"}));

  const ReportFigure* world = find(figures, "fig5_rate_small_house");
  ASSERT_NE(world, nullptr);
  // rrt: L98 30, 20, 25 -> median seed 3; mmpf: never, 40 -> lower median seed 2.
  const RecordingCanvas world_drawn = record(world->figure);
  EXPECT_TRUE(world_drawn.anyTextContains("RRT, seed 3"));
  EXPECT_TRUE(world_drawn.anyTextContains("MMPF, seed 2"));
  EXPECT_EQ(world_drawn.count("series"), 2u);  // no oracle line
  EXPECT_EQ(world_drawn.count("reference"), 1u);
  EXPECT_EQ(plots::renderImage(world->figure).size(), cv::Size(900, 480));

  const ReportFigure* group = find(figures, "fig5_rate_he");
  ASSERT_NE(group, nullptr);
  const RecordingCanvas group_drawn = record(group->figure);
  EXPECT_TRUE(group_drawn.anyTextContains("he (2 worlds): mean exploration rate"));
  EXPECT_TRUE(group_drawn.anyTextContains("MMPF, 1 episode"));
  EXPECT_TRUE(group_drawn.anyTextContains("Nearest frontier (explore_lite), 2 episodes"));
  EXPECT_TRUE(group_drawn.anyTextContains("trajectory length [m]"));  // no oracle: metres

  const ReportFigure* revisits = find(figures, "revisits");
  ASSERT_NE(revisits, nullptr);
  const RecordingCanvas revisits_drawn = record(revisits->figure);
  EXPECT_EQ(revisits_drawn.count("bar"), 4u);  // cells with episodes
  EXPECT_TRUE(revisits_drawn.hasText("3.0"));  // rrt in small_house

  TempDir dir;
  const std::vector<fs::path> files = writeReportFigures(figures.figures, dir / "figures");
  ASSERT_EQ(files.size(), 9u);
  for (const fs::path& f : files) EXPECT_TRUE(fs::exists(f)) << f;
  const cv::Mat png = cv::imread((dir / "figures" / "fig5_rate_small_house.png").string());
  EXPECT_EQ(png.cols, 900);
  EXPECT_EQ(png.rows, 480);
}

TEST(ReportFigures, PdfRastersToTheFigure) {
  const fs::path pdftoppm = findOnPath("pdftoppm");
  ASSERT_FALSE(pdftoppm.empty())
      << "pdftoppm not found on PATH: install poppler-utils (scripts/setup.sh does)";
  const ResultSet results = loadResults({kData / "results_curves.jsonl"});
  const ReportFigures figures = renderReportFigures(results, buildReport(results));
  const ReportFigure* world = find(figures, "fig5_rate_small_house");
  ASSERT_NE(world, nullptr);
  TempDir dir;
  writeReportFigures({*world}, dir / "figures");
  // At 96 dpi a PDF figure has one raster pixel per figure pixel.
  const std::string command = shellQuoted(pdftoppm) + " -r 96 -png -singlefile " +
                              shellQuoted(dir / "figures" / "fig5_rate_small_house.pdf") + " " +
                              shellQuoted(dir / "raster") + " 2>" +
                              shellQuoted(dir / "pdftoppm.log");
  ASSERT_EQ(std::system(command.c_str()), 0) << io::readFile(dir / "pdftoppm.log");
  const cv::Mat raster = cv::imread((dir / "raster.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(raster.empty());
  ASSERT_EQ(raster.size(), cv::Size(900, 480));
  EXPECT_LT(plots::test::pixelsNear(raster, plots::colors::kWhite, 0), 900 * 480 * 98 / 100);
  const std::vector<RecordingCanvas::Polyline> series = record(world->figure).polylinesOf("series");
  ASSERT_EQ(series.size(), 2u);
  for (const RecordingCanvas::Polyline& line : series) {
    EXPECT_GT(plots::test::pixelsNear(raster, line.stroke.color, 10), 300);
  }
  // The PDF shows what the PNG does, where it does (anti-aliasing differs a little).
  cv::Mat difference;
  cv::absdiff(raster, plots::renderImage(world->figure), difference);
  EXPECT_LT(cv::mean(difference)[0], 3.0);
}

TEST(ReportFigures, RevisitsUpToT98HaveTheirOwnFigure) {
  // results_small: rrt in small_house revisits 1 / 2 / 3 over the run, 0 / 1 / 2 up to T98;
  // results_curves records no revisits up to T98, so it has no such figure.
  const ResultSet results = loadResults({kData / "results_small.jsonl"});
  const ReportFigures figures = renderReportFigures(results, buildReport(results));
  const ReportFigure* whole = find(figures, "revisits");
  const ReportFigure* to_t98 = find(figures, "revisits_98");
  ASSERT_NE(whole, nullptr);
  ASSERT_NE(to_t98, nullptr);
  EXPECT_EQ(to_t98->kind, "revisits");  // the report's revisits section shows both
  const RecordingCanvas whole_drawn = record(whole->figure);
  const RecordingCanvas to_t98_drawn = record(to_t98->figure);
  EXPECT_TRUE(to_t98_drawn.hasText("Room revisits up to T98"));
  EXPECT_TRUE(whole_drawn.hasText("2.0"));   // mean of 1, 2, 3
  EXPECT_TRUE(to_t98_drawn.hasText("1.0"));  // mean of 0, 1, 2
  EXPECT_FALSE(to_t98_drawn.hasText("2.0"));
  const ResultSet curves = loadResults({kData / "results_curves.jsonl"});
  EXPECT_EQ(find(renderReportFigures(curves, buildReport(curves)), "revisits_98"), nullptr);
}

TEST(ReportOracle, TableIHasTheOracleColumnDeterministically) {
  ResultSet results = loadResults({kData / "results_small.jsonl"});
  const OracleSummary summary = attachOracleTours(results, {2});
  // small_house and medium_house are built in (no world_source needed); the houseexpo records
  // name no world file.
  EXPECT_EQ(summary.planned, 2u);
  EXPECT_TRUE(summary.notes.empty());
  for (const EpisodeSummary& e : results.episodes) {
    if (e.world_group == "builtin") {
      ASSERT_TRUE(e.oracle) << e.key.text();
      EXPECT_GT(e.oracle->length_m, 10.0);
      EXPECT_GT(e.oracle->coverage, 0.9);
      EXPECT_GT(e.oracle->viewpoints, 0u);
    } else {
      EXPECT_FALSE(e.oracle) << e.key.text();
    }
  }
  const Report report = buildReport(results);
  ASSERT_TRUE(report.hasOracle());
  const double oracle_m = report.oracle.at("small_house").length_m.mean;
  EXPECT_EQ(report.oracle.count("houseexpo"), 0u);
  const MethodStats& rrt = report.table1.at({"small_house", "rrt"});
  // Over the paired episodes, as T98 and L98: seed 1, the one semantic also finished.
  EXPECT_EQ(rrt.l98_oracle_ratio.n, 1u);
  EXPECT_NEAR(rrt.l98_oracle_ratio.mean, 20.0 / oracle_m, 1e-12);

  const std::string md = table1Markdown(report);
  EXPECT_TRUE(contains(md, "small_house L98 / oracle")) << md;
  EXPECT_TRUE(contains(md, "| 20.0 | 31 | 1.00× | 1.00× | " + format("%.2f", 20.0 / oracle_m) +
                               "× | 0/1 (0 %) | 3/3"))
      << md;
  EXPECT_TRUE(contains(md, "## Oracle reference")) << md;
  EXPECT_TRUE(contains(md, "| small_house | 1/1 | " + format("%.1f", oracle_m) + " |")) << md;
  EXPECT_TRUE(contains(md, "| houseexpo (3 worlds) | 0/3 | – |")) << md;
  const std::string csv = table1Csv(report);
  EXPECT_TRUE(contains(csv, ",oracle_worlds,oracle_l_mean_m,")) << csv;

  // The same inputs give the same tables.
  ResultSet again = loadResults({kData / "results_small.jsonl"});
  attachOracleTours(again, {1});
  const Report report2 = buildReport(again);
  EXPECT_EQ(table1Csv(report2), csv);
  EXPECT_EQ(table1Markdown(report2), md);
}

TEST(ReportOracle, AWorldThatDoesNotLoadIsANoteNotAnError) {
  TempDir dir;
  std::ofstream(dir / "results.jsonl")
      << R"({"world": "gone", "world_group": "maps", "world_source": "/nonexistent/gone.yaml", )"
      << R"("method": "mmpf", "seed": 1, "exploration_rate": 0.99, "l98_m": 5.0})"
      << "\n";
  ResultSet results = loadResults({dir / "results.jsonl"});
  const OracleSummary summary = attachOracleTours(results);
  ASSERT_EQ(summary.notes.size(), 1u);
  EXPECT_TRUE(contains(summary.notes[0], "/nonexistent/gone.yaml")) << summary.notes[0];
  EXPECT_FALSE(results.episodes[0].oracle);
  EXPECT_FALSE(buildReport(results).hasOracle());
}

TEST(ReportWriter, WritesTablesFiguresAndPageFromABench) {
  TempDir dir;
  fs::create_directories(dir / "tiny");
  const fs::path world = roomscout::test::writeTwoRoomWorld(dir / "tiny");
  BenchOptions bench;
  bench.worlds = {world.string()};
  bench.methods = {"nearest_frontier", "mmpf"};
  bench.seeds = {1, 2};
  bench.jobs = 2;
  bench.out = dir / "bench";
  bench.settings.max_time_s = 60.0;
  runBench(bench);

  const ReportOutput output = runReport({dir / "bench"}, dir / "report");
  EXPECT_EQ(output.episodes, 4u);
  EXPECT_TRUE(output.notes.empty()) << output.notes.front();
  const fs::path figures = dir / "report" / "figures";
  for (const char* stem :
       {"fig5_rate_rooms", "fig6_trajectories_rooms", "fig7_maps_rooms", "revisits"}) {
    for (const char* ext : {".png", ".svg", ".pdf"}) {
      const fs::path f = figures / (std::string(stem) + ext);
      EXPECT_NE(std::find(output.files.begin(), output.files.end(), f), output.files.end()) << f;
      EXPECT_TRUE(fs::exists(f)) << f;
    }
  }
  for (const char* f : {"table1.md", "table1.csv", "table2.md", "table3.md", "report.html"})
    EXPECT_TRUE(fs::exists(dir / "report" / f)) << f;

  // Sizes: charts as laid out, map figures 1200 px wide and as tall as their maps need.
  const cv::Mat rate = cv::imread((figures / "fig5_rate_rooms.png").string());
  EXPECT_EQ(rate.cols, 900);
  EXPECT_EQ(rate.rows, 480);
  const cv::Mat trajectories = cv::imread((figures / "fig6_trajectories_rooms.png").string());
  EXPECT_EQ(trajectories.cols, 1200);
  EXPECT_GT(trajectories.rows, 200);
  EXPECT_LT(trajectories.rows, 1200);
  const cv::Mat maps = cv::imread((figures / "fig7_maps_rooms.png").string());
  EXPECT_EQ(maps.cols, 1200);
  EXPECT_GT(maps.rows, 300);

  // What the figures show, as drawn by the report again from the same results.
  ResultSet results = loadResults({dir / "bench"});
  attachOracleTours(results, {2});
  const ReportFigures again = renderReportFigures(results, buildReport(results));
  const ReportFigure* rate_figure = find(again, "fig5_rate_rooms");
  const ReportFigure* trajectories_figure = find(again, "fig6_trajectories_rooms");
  const ReportFigure* maps_figure = find(again, "fig7_maps_rooms");
  ASSERT_TRUE(rate_figure && trajectories_figure && maps_figure);
  const RecordingCanvas rate_drawn = record(rate_figure->figure);
  const RecordingCanvas trajectories_drawn = record(trajectories_figure->figure);
  const RecordingCanvas maps_drawn = record(maps_figure->figure);
  for (const char* method : {"MMPF", "Nearest frontier (explore_lite)"}) {
    EXPECT_TRUE(rate_drawn.anyTextContains(method)) << method;
    EXPECT_TRUE(trajectories_drawn.hasText(method)) << method;
  }
  EXPECT_TRUE(rate_drawn.anyTextContains("oracle tour"));
  EXPECT_EQ(trajectories_drawn.count("track"), 2u);
  EXPECT_EQ(trajectories_drawn.images.size(), 2u);
  EXPECT_EQ(maps_drawn.images.size(), 4u);
  // No "semantic" run: the first method's.
  EXPECT_TRUE(maps_drawn.anyTextContains("MMPF, seed 1"));
  // The files are these figures.
  const std::string rate_svg = io::readFile(figures / "fig5_rate_rooms.svg");
  EXPECT_EQ(rate_svg, plots::renderSvg(rate_figure->figure));
  EXPECT_EQ(io::readFile(figures / "fig7_maps_rooms.pdf"), plots::renderPdf(maps_figure->figure));
  EXPECT_EQ(count(io::readFile(figures / "fig6_trajectories_rooms.svg"), "<image "), 2u);

  // The page holds every table and every figure, inline.
  const std::string html = io::readFile(dir / "report" / "report.html");
  EXPECT_EQ(count(html, "<table class=\"report-table\">"), 5u);  // I, revisits, oracle, II, III
  EXPECT_EQ(count(html, "<figure class=\"report-figure\">"),
            5u);  // Fig. 5-7, revisits (run, to T98)
  for (const char* part : {"Table I: exploration time", "Revisits", "Oracle reference",
                           "Table II: map types", "Table III: storage", "Fig. 5, rooms",
                           "Fig. 6, rooms", "Fig. 7, rooms", "Room revisits per method",
                           "Room revisits up to T98 per method", "tiny (1 world) L98 / oracle"}) {
    EXPECT_TRUE(contains(html, part)) << part;
  }
  // Inline: the first figure on the page is Fig. 5, its ids prefixed "fig1-".
  EXPECT_TRUE(contains(html, plots::numberSvgIds(rate_svg.substr(rate_svg.find("<svg")), "fig1-")));
  EXPECT_FALSE(contains(html, "src=\"http")) << "self-contained";

  // Deterministic: a second report writes the same tables and figure drawings.
  runReport({dir / "bench"}, dir / "report2");
  EXPECT_EQ(io::readFile(dir / "report2" / "table1.csv"),
            io::readFile(dir / "report" / "table1.csv"));
  for (const char* file : {"fig6_trajectories_rooms.png", "fig6_trajectories_rooms.svg",
                           "fig6_trajectories_rooms.pdf", "revisits.pdf"}) {
    EXPECT_EQ(io::readFile(dir / "report2" / "figures" / file),
              io::readFile(dir / "report" / "figures" / file))
        << file;
  }
  EXPECT_EQ(io::readFile(dir / "report2" / "report.html"), html);
}

}  // namespace
}  // namespace roomscout::experiment
