#include "roomscout/experiment/report_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "roomscout/core/format.hpp"
#include "roomscout/experiment/paper_reference.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/map_server.hpp"
#include "roomscout/io/semantic_io.hpp"
#include "roomscout/plots/bar_chart.hpp"
#include "roomscout/plots/line_chart.hpp"
#include "roomscout/plots/map_panels.hpp"

namespace roomscout::experiment {
namespace fs = std::filesystem;
namespace {

constexpr plots::Rgb kOracleColor{90, 90, 90};
constexpr double kPad = 8.0;  // the map panels' padding [px] (plots/map_panels.cpp)

/// A file-name-safe version of a world or group name.
std::string fileSafe(const std::string& name) {
  std::string out;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    out += ok ? c : '_';
  }
  return out.empty() ? std::string("_") : out;
}

/// The episodes of the results, by (world, method) sorted by seed, and the worlds of each row.
struct EpisodeIndex {
  std::map<std::pair<std::string, std::string>, std::vector<const EpisodeSummary*>> by_cell;
  std::map<std::string, std::set<std::string>> worlds_of_row;
  std::map<std::string, std::vector<const EpisodeSummary*>> by_row;

  explicit EpisodeIndex(const ResultSet& results) {
    for (const EpisodeSummary& e : results.episodes) {
      by_cell[{e.key.world, e.key.method}].push_back(&e);
      worlds_of_row[rowNameOf(e)].insert(e.key.world);
      by_row[rowNameOf(e)].push_back(&e);
    }
    for (auto& [key, list] : by_cell) {
      std::sort(list.begin(), list.end(), [](const EpisodeSummary* a, const EpisodeSummary* b) {
        return a->key.seed < b->key.seed;
      });
    }
  }
  const std::vector<const EpisodeSummary*>& cell(const std::string& world,
                                                 const std::string& method) const {
    static const std::vector<const EpisodeSummary*> kNone;
    const auto it = by_cell.find({world, method});
    return it == by_cell.end() ? kNone : it->second;
  }
};

plots::Rgb methodColor(const Report& report, const std::string& method) {
  const auto it = std::find(report.methods.begin(), report.methods.end(), method);
  return plots::paletteColor(static_cast<std::size_t>(it - report.methods.begin()));
}

/// The episode of median L98 among those with a curve (never reaching 98 % ranks last).
const EpisodeSummary* medianEpisode(const std::vector<const EpisodeSummary*>& episodes) {
  std::vector<const EpisodeSummary*> with_curve;
  for (const EpisodeSummary* e : episodes) {
    if (!e->curve.empty()) with_curve.push_back(e);
  }
  if (with_curve.empty()) return nullptr;
  const auto rank = [](const EpisodeSummary* e) {
    return std::pair(e->l98_m.value_or(std::numeric_limits<double>::infinity()), e->key.seed);
  };
  std::sort(with_curve.begin(), with_curve.end(),
            [&](const EpisodeSummary* a, const EpisodeSummary* b) { return rank(a) < rank(b); });
  return with_curve[(with_curve.size() - 1) / 2];
}

/// A vertical dashed line at x from 0 to 100 %, as a series.
plots::LineSeries verticalLine(const std::string& name, double x) {
  plots::LineSeries s;
  s.name = name;
  s.points = {{x, 0.0}, {x, 100.0}};
  s.color = kOracleColor;
  s.dashed = true;
  return s;
}

plots::LineChart rateChart(const std::string& title, const std::string& x_label) {
  plots::LineChart chart;
  chart.title = title;
  chart.x_label = x_label;
  chart.y_label = "exploration rate [%]";
  chart.reference = plots::ReferenceLine{98.0, "98 %"};
  chart.x_min = 0.0;
  chart.y_min = 0.0;
  chart.y_max = 100.0;
  chart.size = {900, 480};
  return chart;
}

/// Fig. 5 of one world: per method the median-L98 episode's curve.
std::optional<ReportFigure> worldRateFigure(const Report& report, const EpisodeIndex& index,
                                            const std::string& row, const std::string& world) {
  plots::LineChart chart =
      rateChart(world + ": exploration rate vs trajectory length", "trajectory length [m]");
  std::optional<double> oracle_m;
  for (const std::string& method : report.methods) {
    const std::vector<const EpisodeSummary*>& episodes = index.cell(world, method);
    for (const EpisodeSummary* e : episodes) {
      if (e->oracle && !oracle_m) oracle_m = e->oracle->length_m;
    }
    const EpisodeSummary* e = medianEpisode(episodes);
    if (!e) continue;
    plots::LineSeries s;
    s.name = methodLabel(method) + ", seed " + std::to_string(e->key.seed);
    s.color = methodColor(report, method);
    for (const CurvePoint& p : e->curve) s.points.push_back({p.length_m, 100.0 * p.rate});
    chart.series.push_back(std::move(s));
  }
  if (chart.series.empty()) return std::nullopt;
  if (oracle_m)
    chart.series.push_back(
        verticalLine("oracle tour " + formatString("%.1f m", *oracle_m), *oracle_m));
  ReportFigure f;
  f.stem = "fig5_rate_" + fileSafe(world);
  f.kind = "rate";
  f.row = row;
  f.caption = "Fig. 5, " + world +
              ": exploration rate against trajectory length. Per method the episode of median "
              "L98 over its seeds (episodes that never reached 98 % rank last; seed in the "
              "legend). Dashed: the 98 % line" +
              std::string(oracle_m ? " and the length of the full-knowledge oracle tour" : "") +
              ".";
  f.figure = plots::renderLineChart(chart);
  return f;
}

/// Rate of a curve at length x (linear between rows; the last rate after the end).
double rateAt(const std::vector<CurvePoint>& curve, double x, double scale) {
  if (x <= curve.front().length_m * scale) return curve.front().rate;
  const auto it = std::lower_bound(
      curve.begin(), curve.end(), x,
      [&](const CurvePoint& p, double value) { return p.length_m * scale < value; });
  if (it == curve.end()) return curve.back().rate;
  const CurvePoint& b = *it;
  const CurvePoint& a = *(it - 1);
  const double xa = a.length_m * scale, xb = b.length_m * scale;
  if (xb <= xa) return b.rate;
  return a.rate + (b.rate - a.rate) * (x - xa) / (xb - xa);
}

/// Fig. 5 of a group: per method the mean curve of all its episodes.
std::optional<ReportFigure> groupRateFigure(const Report& report, const EpisodeIndex& index,
                                            const ReportRow& row) {
  const auto it = index.by_row.find(row.name);
  if (it == index.by_row.end()) return std::nullopt;
  std::vector<const EpisodeSummary*> episodes;
  bool normalised = true;
  for (const EpisodeSummary* e : it->second) {
    if (e->curve.empty()) continue;
    episodes.push_back(e);
    if (!e->oracle || e->oracle->length_m <= 0.0) normalised = false;
  }
  if (episodes.empty()) return std::nullopt;
  const auto scaleOf = [&](const EpisodeSummary* e) {
    return normalised ? 1.0 / e->oracle->length_m : 1.0;
  };
  double x_max = 0.0;
  for (const EpisodeSummary* e : episodes)
    x_max = std::max(x_max, e->curve.back().length_m * scaleOf(e));
  if (!(x_max > 0.0)) x_max = 1.0;
  constexpr int kSamples = 240;
  const std::string title = rowTitle(row) + ": mean exploration rate";
  plots::LineChart chart = rateChart(
      title, normalised ? "trajectory length / oracle tour length" : "trajectory length [m]");
  for (const std::string& method : report.methods) {
    std::vector<const EpisodeSummary*> mine;
    for (const EpisodeSummary* e : episodes) {
      if (e->key.method == method) mine.push_back(e);
    }
    if (mine.empty()) continue;
    plots::LineSeries s;
    s.name = methodLabel(method) + ", " + std::to_string(mine.size()) +
             (mine.size() == 1 ? " episode" : " episodes");
    s.color = methodColor(report, method);
    for (int k = 0; k <= kSamples; ++k) {
      const double x = x_max * k / kSamples;
      double sum = 0.0;
      for (const EpisodeSummary* e : mine) sum += rateAt(e->curve, x, scaleOf(e));
      s.points.push_back({x, 100.0 * sum / static_cast<double>(mine.size())});
    }
    chart.series.push_back(std::move(s));
  }
  if (normalised) chart.series.push_back(verticalLine("oracle tour", 1.0));
  ReportFigure f;
  f.stem = "fig5_rate_" + fileSafe(row.name);
  f.kind = "rate";
  f.row = row.name;
  f.caption = "Fig. 5, " + rowTitle(row) +
              ": mean exploration rate of every world × seed episode of each method against " +
              (normalised ? std::string("trajectory length divided by the length of the world's "
                                        "full-knowledge oracle tour (1 = the oracle tour)")
                          : std::string("trajectory length")) +
              "; an episode that ended keeps its final rate. Dashed: the 98 % line.";
  f.figure = plots::renderLineChart(chart);
  return f;
}

/// `image` shrunk (area averaging) to fit `box_w` x `box_h` px when larger; the factor applied.
double shrinkToFit(cv::Mat& image, double box_w, double box_h) {
  if (image.empty()) return 1.0;
  const double f = std::min({1.0, box_w / image.cols, box_h / image.rows});
  if (f >= 1.0) return 1.0;
  cv::Mat small;
  cv::resize(image, small,
             {std::max(1, static_cast<int>(std::lround(image.cols * f))),
              std::max(1, static_cast<int>(std::lround(image.rows * f)))},
             0, 0, cv::INTER_AREA);
  const double applied = static_cast<double>(small.cols) / image.cols;
  image = small;
  return applied;
}

/// Panels laid out `columns` wide in a figure `width_px` wide, as tall as the tallest image
/// needs; images shrunk to their cells (tracks scaled along).
plots::MapPanelFigure layoutPanels(std::string title, std::vector<plots::MapPanel> panels,
                                   int columns, int width_px) {
  plots::MapPanelFigure figure;
  figure.title = std::move(title);
  figure.columns = columns;
  const int rows = static_cast<int>((panels.size() + columns - 1) / columns);
  const double cell_w = (width_px - kPad) / columns;
  const double box_w = cell_w - kPad;
  double aspect = 0.3;  // height / width of the tallest image
  for (const plots::MapPanel& p : panels) {
    if (!p.image.empty())
      aspect = std::max(aspect, static_cast<double>(p.image.rows) / p.image.cols);
  }
  aspect = std::min(aspect, 2.0);
  const double title_h = 13.0 * 1.5 + 4.0;  // panel titles (plots::labelStyle bold)
  const double cell_h = box_w * aspect + title_h + kPad;
  const double top = figure.title.empty() ? kPad : kPad + 18.0 * 1.6 + 4.0;
  figure.size = {width_px, static_cast<int>(std::ceil(top + rows * cell_h + kPad))};
  for (plots::MapPanel& p : panels) {
    const double f = shrinkToFit(p.image, box_w, box_w * aspect);
    for (plots::PanelTrack& t : p.tracks) {
      for (cv::Point2d& q : t.points_px) q *= f;
    }
  }
  figure.panels = std::move(panels);
  return figure;
}

/// The lowest-seed episode of a cell whose outputs folder exists.
const EpisodeSummary* runWithOutputs(const std::vector<const EpisodeSummary*>& episodes) {
  for (const EpisodeSummary* e : episodes) {
    std::error_code ec;
    if (!e->outputs_dir.empty() && fs::is_directory(e->outputs_dir, ec)) return e;
  }
  return nullptr;
}

/// The final map of a run with its rooms coloured, and the grid it is drawn from.
struct RunMap {
  cv::Mat image;  ///< BGR, row 0 at the top
  GridGeometry geometry;
  bool rooms = false;
};

std::optional<RunMap> loadRunMap(const fs::path& dir, std::vector<std::string>& notes) {
  RunMap map;
  try {
    const OccupancyGrid grid = io::loadOccupancyMap(dir / "occupancy.yaml");
    map.geometry = grid.geometry();
    const cv::Mat grey = io::occupancyImage(grid);
    const cv::Mat labels16 =
        cv::imread((dir / "semantic_labels.png").string(), cv::IMREAD_UNCHANGED);
    if (!labels16.empty() && labels16.channels() == 1 && labels16.size() == grey.size()) {
      cv::Mat labels;
      labels16.convertTo(labels, CV_32S);
      map.image = io::colourLabels(labels, grey);
      map.rooms = true;
    } else {
      cv::cvtColor(grey, map.image, cv::COLOR_GRAY2BGR);
      notes.push_back("figures: " + (dir / "semantic_labels.png").string() +
                      " missing or of another size; rooms not coloured");
    }
  } catch (const std::exception& e) {
    notes.push_back("figures: cannot read the map of " + dir.string() + ": " + e.what());
    return std::nullopt;
  }
  return map;
}

/// Fig. 6 of one world: each method's trajectory over its final map.
std::optional<ReportFigure> trajectoryFigure(const Report& report, const EpisodeIndex& index,
                                             const std::string& row, const std::string& world,
                                             std::vector<std::string>& notes) {
  std::vector<plots::MapPanel> panels;
  std::vector<std::string> seeds;
  for (const std::string& method : report.methods) {
    const std::vector<const EpisodeSummary*>& episodes = index.cell(world, method);
    if (episodes.empty()) continue;
    const EpisodeSummary* e = runWithOutputs(episodes);
    if (!e) continue;
    const std::optional<RunMap> map = loadRunMap(e->outputs_dir, notes);
    if (!map) continue;
    plots::MapPanel panel;
    panel.title = methodLabel(method);
    panel.image = map->image;
    plots::PanelTrack track;
    track.points_px = plots::gridImagePoints(map->geometry, e->trajectory_m);
    track.color = plots::colors::kTrajectory;
    panel.tracks.push_back(std::move(track));
    panels.push_back(std::move(panel));
    seeds.push_back(methodLabel(method) + " seed " + std::to_string(e->key.seed));
  }
  if (panels.empty()) return std::nullopt;
  const int columns = static_cast<int>(std::min<std::size_t>(panels.size(), 4));
  ReportFigure f;
  f.stem = "fig6_trajectories_" + fileSafe(world);
  f.kind = "trajectories";
  f.row = row;
  std::string which;
  for (const std::string& s : seeds) which += (which.empty() ? "" : ", ") + s;
  f.caption = "Fig. 6, " + world +
              ": each method's trajectory (blue; start green, end red) over its final "
              "occupancy map with the rooms of its own semantic map coloured (" +
              which + ").";
  f.figure = plots::renderMapPanels(
      layoutPanels(world + ": trajectories", std::move(panels), columns, 1200));
  return f;
}

/// Fig. 7 of one world: the four maps of one run.
std::optional<ReportFigure> mapsFigure(const Report& report, const EpisodeIndex& index,
                                       const std::string& row, const std::string& world,
                                       std::vector<std::string>& notes) {
  const EpisodeSummary* run = nullptr;
  std::vector<std::string> order = {"semantic"};
  order.insert(order.end(), report.methods.begin(), report.methods.end());
  for (const std::string& method : order) {
    run = runWithOutputs(index.cell(world, method));
    if (run) break;
  }
  if (!run) return std::nullopt;
  struct Part {
    const char* title;
    const char* file;
  };
  static constexpr Part kParts[] = {{"2D occupancy grid", "occupancy.pgm"},
                                    {"3D point cloud", "pointcloud.png"},
                                    {"Topological map", "topology.png"},
                                    {"Semantic map", "semantic.png"}};
  std::vector<plots::MapPanel> panels;
  for (const Part& part : kParts) {
    const fs::path file = run->outputs_dir / part.file;
    plots::MapPanel panel;
    panel.title = part.title;
    panel.image = cv::imread(file.string(), cv::IMREAD_COLOR);
    if (panel.image.empty()) {
      notes.push_back("figures: cannot read " + file.string() + "; left out of Fig. 7");
      continue;
    }
    panels.push_back(std::move(panel));
  }
  if (panels.empty()) return std::nullopt;
  const int columns = static_cast<int>(std::min<std::size_t>(panels.size(), 2));
  ReportFigure f;
  f.stem = "fig7_maps_" + fileSafe(world);
  f.kind = "maps";
  f.row = row;
  f.caption = "Fig. 7, " + world + ": the four maps of one run (" + methodLabel(run->key.method) +
              ", seed " + std::to_string(run->key.seed) +
              "): occupancy grid, point cloud (top view and oblique, coloured by height), "
              "topological map, semantic map.";
  f.figure =
      plots::renderMapPanels(layoutPanels(world + ": maps of " + methodLabel(run->key.method) +
                                              ", seed " + std::to_string(run->key.seed),
                                          std::move(panels), columns, 1200));
  return f;
}

/// Mean room revisits per method and row: over the whole run, or (to_t98) up to T98.
std::optional<ReportFigure> revisitsFigure(const Report& report, bool to_t98) {
  plots::BarChart chart;
  chart.title = to_t98 ? "Room revisits up to T98" : "Room revisits";
  chart.y_label = "revisits (mean over episodes)";
  bool any = false;
  for (const ReportRow& row : report.rows) chart.categories.push_back(rowTitle(row));
  for (const std::string& method : report.methods) {
    plots::BarSeries s;
    s.name = methodLabel(method);
    s.color = methodColor(report, method);
    for (const ReportRow& row : report.rows) {
      const auto it = report.table1.find({row.name, method});
      const Stat* stat = it == report.table1.end() ? nullptr
                         : to_t98                  ? &it->second.revisits_98
                                                   : &it->second.revisits;
      if (stat != nullptr && stat->n > 0) {
        s.values.push_back(stat->mean);
        any = true;
      } else {
        s.values.push_back(std::nan(""));
      }
    }
    chart.series.push_back(std::move(s));
  }
  if (!any) return std::nullopt;
  chart.value_decimals = 1;
  const int bars = static_cast<int>(report.rows.size() * report.methods.size());
  chart.size = {std::clamp(420 + 34 * bars, 720, 1600), 440};
  ReportFigure f;
  f.stem = to_t98 ? "revisits_98" : "revisits";
  f.kind = "revisits";
  f.caption =
      to_t98
          ? "Room revisits up to T98 per method and world: the revisits of the exploration itself, "
            "whatever a method does once the map is 98 % complete (mean over the episodes that "
            "reached 98 %; a group pools every world × seed episode)."
          : "Room revisits per method and world: entries into a ground-truth room entered "
            "before, mean over the episodes (a group pools every world × seed episode).";
  f.figure = plots::renderBarChart(chart);
  return f;
}

}  // namespace

ReportFigures renderReportFigures(const ResultSet& results, const Report& report) {
  ReportFigures out;
  const EpisodeIndex index(results);
  for (const ReportRow& row : report.rows) {
    const auto worlds = index.worlds_of_row.find(row.name);
    if (worlds == index.worlds_of_row.end()) continue;
    if (worlds->second.size() == 1) {
      const std::string& world = *worlds->second.begin();
      if (auto f = worldRateFigure(report, index, row.name, world))
        out.figures.push_back(std::move(*f));
      if (auto f = trajectoryFigure(report, index, row.name, world, out.notes))
        out.figures.push_back(std::move(*f));
      if (auto f = mapsFigure(report, index, row.name, world, out.notes))
        out.figures.push_back(std::move(*f));
    } else if (auto f = groupRateFigure(report, index, row)) {
      out.figures.push_back(std::move(*f));
    }
  }
  if (auto f = revisitsFigure(report, false)) out.figures.push_back(std::move(*f));
  if (auto f = revisitsFigure(report, true)) out.figures.push_back(std::move(*f));
  return out;
}

std::vector<fs::path> writeReportFigures(const std::vector<ReportFigure>& figures,
                                         const fs::path& directory) {
  std::vector<fs::path> written;
  if (figures.empty()) return written;
  io::ensureWritableDirectory(directory);
  for (const ReportFigure& f : figures) {
    const plots::FigureFiles files = plots::writeFigure(f.figure, directory / f.stem);
    written.push_back(files.png);
    written.push_back(files.svg);
    written.push_back(files.pdf);
  }
  return written;
}

}  // namespace roomscout::experiment
