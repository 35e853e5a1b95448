#include "roomscout/experiment/report_tables.hpp"

#include <algorithm>

#include "roomscout/core/format.hpp"
#include "roomscout/experiment/paper_reference.hpp"
#include "roomscout/experiment/result_record.hpp"

namespace roomscout::experiment {
namespace {

/// "mean ± sd", "mean" for one value, "–" for none.
std::string meanSd(const Stat& s, const char* spec = "%.1f") {
  if (s.n == 0) return "–";
  std::string text = formatString(spec, s.mean);
  if (s.sd) text += " ± " + formatString(spec, *s.sd);
  return text;
}

/// Paper columns (T, L) for a built-in world of the paper.
bool paperColumns(const ReportRow& row) { return !row.is_group && worldRank(row.name) < 100; }

std::string percent(std::size_t part, std::size_t whole) {
  return formatString("%.0f", 100.0 * static_cast<double>(part) / static_cast<double>(whole));
}

std::string ratioText(const Stat& s) { return s.n ? formatString("%.2f", s.mean) + "×" : "–"; }

/// "successes/episodes (percent %)".
std::string successText(std::size_t successes, std::size_t episodes) {
  return std::to_string(successes) + "/" + std::to_string(episodes) + " (" +
         percent(successes, episodes) + " %)";
}

const char* kMapTitles[4] = {"2D occupancy grid", "3D point cloud", "Topological", "Semantic"};

/// How a setting is named in Table IV's header.
std::string settingTitle(const std::string& setting) {
  return setting.empty() ? "noise-free" : setting;
}

}  // namespace

std::string sourcesLine(const Report& report) {
  std::string text = std::to_string(report.episodes) + " episodes";
  if (!report.main_setting.empty()) text += " under " + report.main_setting;
  text += " from ";
  for (std::size_t i = 0; i < report.files.size(); ++i) {
    text += (i ? ", " : "") + std::string("`") + report.files[i].string() + "`";
  }
  const std::vector<std::string>& settings = report.table4.settings;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    text += i == 0 ? ", and " : "; ";  // the settings' names hold commas
    const std::size_t n = report.table4.episodes.at(settings[i]);
    text += std::to_string(n) + (n == 1 ? " episode under " : " episodes under ") + settings[i];
  }
  if (!settings.empty()) text += " (Table IV)";
  return text;
}

std::string startPosesLine(const Report& report) {
  if (report.random_start_episodes == 0) return {};
  const std::string n = report.random_start_episodes == report.episodes
                            ? std::string("Every episode")
                            : std::to_string(report.random_start_episodes) + " of " +
                                  std::to_string(report.episodes) + " episodes";
  return n +
         " started at a pose drawn from its seed (bench --random-starts: the same pose for every "
         "method, recorded as `start`), not at its world's start; its oracle tour starts there "
         "too.";
}

std::string sameEverySeedLine(const Report& report) {
  const std::vector<std::string> methods = report.methodsSameEverySeed();
  if (methods.empty()) return {};
  std::string names;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    names += (i == 0 ? "" : i + 1 == methods.size() ? " and " : ", ") + methodLabel(methods[i]);
  }
  return "Every seed gave the same run for " + names +
         " (the same final rate, T98 and L98 in every seed of a world): these methods make no "
         "random choice, so on noise-free sensors (the default) the seed changes nothing and "
         "their sd is 0 by construction.";
}

std::string table1Description() {
  return "T98 [s] and L98 [m]: simulated time and distance driven when the exploration rate "
         "first reached 98 %, mean ± sample standard deviation over the paired episodes of the "
         "world: the (world, seed) pairs that every method run on it finished (final "
         "exploration rate ≥ 98 % and, with SLAM, a pose estimate that did not diverge). Every "
         "method's mean is thus over the same runs: a method that fails the hardest seeds does "
         "not look shorter for it, and a world where no pair was finished by all says \"no "
         "shared pair\". L98 / and T98 / the reference method: the mean over the paired "
         "episodes of the method's L98 (T98) divided by the reference's on the same world and "
         "seed. Beats semantic: of the (world, seed) pairs that both the method and semantic "
         "finished, the share on which the method drove a shorter L98 (a tie does not count; "
         "– for semantic itself). Success: every episode of the method, k/n (%), whether "
         "paired or not. *Paper*: the paper's Table I (T s, L m). L98 / oracle (when the worlds "
         "could be loaded): each paired episode's L98 divided by the length of the "
         "full-knowledge oracle tour of its world (see Oracle reference), averaged. A group of "
         "worlds (world files of one folder, e.g. houseexpo) pools every world × seed episode "
         "and pairs them per world and seed.";
}

std::string pairingLine(const Report& report) {
  if (report.rows.empty()) return {};
  std::string text =
      "Paired (world, seed) pairs, finished by every method of the world out of "
      "those run: ";
  for (const ReportRow& row : report.rows) {
    const auto it = report.paired.find(row.name);
    const PairedRow p = it == report.paired.end() ? PairedRow{} : it->second;
    text += (&row == &report.rows.front() ? "" : "; ") + rowTitle(row) + " " +
            std::to_string(p.pairs) + " of " + std::to_string(p.all_pairs) + " (" +
            std::to_string(p.methods) + (p.methods == 1 ? " method)" : " methods)");
  }
  text += ". Ratios are to " + methodLabel(report.reference) + " (`" + report.reference + "`)";
  text += report.reference == "rrt" ? "." : ", the first method of the table (no rrt episodes).";
  if (report.hasSemantic()) {
    text +=
        " Beats semantic: k/n where n counts the (world, seed) pairs both the method and "
        "semantic finished and k those on which the method's L98 is shorter.";
  }
  return text;
}

std::string revisitsDescription() {
  return "Entries into a ground-truth room that had been entered before (a room counts as "
         "entered after 2 s inside), mean ± sample standard deviation: over the whole episode, "
         "and up to T98 (over the episodes that reached 98 %). A strategy that does not end "
         "itself keeps driving until the time limit; the count up to T98 is that of the "
         "exploration alone.";
}

std::string oracleDescription() {
  return "The tour a robot that already knew the whole map would drive to see 98 % of the "
         "reachable free space (sim/oracle_tour.hpp: greedy set cover of laser viewpoints, "
         "ordered by a TSP heuristic over geodesic distances from the start), planned on the "
         "ground truth with the episodes' options (map resolution, robot radius + safety "
         "margin, laser range). A reference, not a bound: what the laser sees between "
         "viewpoints is not counted. For a group, mean ± sd over its worlds (with random "
         "starts, over its worlds and starts).";
}

std::string table2Description() {
  return "M1: 2D occupancy grid, M2: 3D point cloud, M3: topological map, M4: semantic map. "
         "Above the line: the paper's Table II (its survey of earlier work, and its own "
         "method). Below: each method of these results, ✓ when its episodes recorded that map "
         "(stored bytes or updates). In roomscout every method's episode builds all four maps; "
         "the strategies decide on the occupancy grid, and the semantic ones also read the "
         "rooms.";
}

std::string table3Description() {
  return "S: storage [KB = 1024 bytes] of the map's data files at the end of an episode "
         "(occupancy: occupancy.pgm + occupancy.yaml; point cloud: pointcloud.pcd, "
         "binary_compressed; topological: topology.json; semantic: semantic.json + "
         "semantic_labels.png; pictures such as run.png are not counted), mean over episodes. "
         "U: update time [s] as median / p95 of one episode's updates, each averaged over "
         "episodes (occupancy: one laser scan; point cloud: one keyframe, ray cast + insert; "
         "topological and semantic: one rebuild). Every method's episodes of a world are "
         "pooled. *Paper*: the paper's Table III (S KB, U s).";
}

plots::HtmlTable table1Cells(const Report& report) {
  plots::HtmlTable table;
  const std::string reference = methodLabel(report.reference);
  table.caption =
      "Table I: exploration time and trajectory length, means over the paired "
      "episodes, the (world, seed) pairs every method of the world finished";
  for (const ReportRow& row : report.rows) {
    const auto it = report.paired.find(row.name);
    const PairedRow p = it == report.paired.end() ? PairedRow{} : it->second;
    table.caption += (&row == &report.rows.front() ? " (" : ", ") + rowTitle(row) + " " +
                     std::to_string(p.pairs) + " of " + std::to_string(p.all_pairs);
  }
  table.caption += std::string(report.rows.empty() ? "" : ")") + "; ratios to " + reference +
                   " on the same pairs";
  if (report.hasSemantic()) {
    table.caption +=
        "; beats semantic: share of the pairs it and semantic both finished on "
        "which its L98 is shorter";
  }
  const bool oracle = report.hasOracle();
  const bool semantic = report.hasSemantic();
  table.header = {"Method"};
  for (const ReportRow& row : report.rows) {
    const bool paper = paperColumns(row);
    const std::string t = rowTitle(row);
    table.header.push_back(t + " T98 (s)");
    if (paper) table.header.push_back("paper T");
    table.header.push_back(t + " L98 (m)");
    if (paper) table.header.push_back("paper L");
    table.header.push_back(t + " L98 / " + reference);
    table.header.push_back(t + " T98 / " + reference);
    if (oracle) table.header.push_back(t + " L98 / oracle");
    if (semantic) table.header.push_back(t + " beats semantic");
    table.header.push_back(t + " success");
  }
  for (const std::string& method : report.methods) {
    std::vector<std::string> cells = {methodLabel(method)};
    for (const ReportRow& row : report.rows) {
      const bool paper_cols = paperColumns(row);
      const auto it = report.table1.find({row.name, method});
      const std::optional<PaperTimeLength> paper = paperTable1(row.name, method);
      const bool has = it != report.table1.end();
      const auto paired = report.paired.find(row.name);
      const bool shared = paired != report.paired.end() && paired->second.pairs > 0;
      // A mean over no episodes would read as a number; the cell says why there is none.
      const auto mean = [&](const Stat& stat) {
        return !has ? std::string("–") : shared ? meanSd(stat) : std::string("no shared pair");
      };
      cells.push_back(mean(has ? it->second.t98_s : Stat{}));
      if (paper_cols) cells.push_back(paper ? formatString("%.0f", paper->t_s) : "–");
      cells.push_back(mean(has ? it->second.l98_m : Stat{}));
      if (paper_cols) cells.push_back(paper ? formatString("%.0f", paper->l_m) : "–");
      cells.push_back(has ? ratioText(it->second.l98_reference_ratio) : "–");
      cells.push_back(has ? ratioText(it->second.t98_reference_ratio) : "–");
      if (oracle) cells.push_back(has ? ratioText(it->second.l98_oracle_ratio) : "–");
      if (semantic) {
        const bool pairs = has && method != "semantic" && it->second.semantic_pairs > 0;
        cells.push_back(pairs ? successText(it->second.beats_semantic, it->second.semantic_pairs)
                              : "–");
      }
      cells.push_back(has ? successText(it->second.successes, it->second.episodes) : "–");
    }
    table.rows.push_back(std::move(cells));
  }
  return table;
}

plots::HtmlTable revisitsCells(const Report& report) {
  plots::HtmlTable table;
  table.caption = "Revisits";
  table.header = {"Method"};
  for (const ReportRow& row : report.rows) {
    table.header.push_back(rowTitle(row));
    table.header.push_back(rowTitle(row) + " to T98");
  }
  for (const std::string& method : report.methods) {
    std::vector<std::string> cells = {methodLabel(method)};
    for (const ReportRow& row : report.rows) {
      const auto it = report.table1.find({row.name, method});
      const bool has = it != report.table1.end();
      cells.push_back(has ? meanSd(it->second.revisits) : std::string("–"));
      cells.push_back(has && it->second.revisits_98.n ? meanSd(it->second.revisits_98)
                                                      : std::string("–"));
    }
    table.rows.push_back(std::move(cells));
  }
  return table;
}

std::optional<plots::HtmlTable> oracleCells(const Report& report) {
  if (!report.hasOracle()) return std::nullopt;
  plots::HtmlTable table;
  table.caption = "Oracle reference: full-knowledge tour";
  table.header = {"World", "worlds with oracle", "oracle L (m)", "viewpoints", "coverage (%)"};
  for (const ReportRow& row : report.rows) {
    const auto it = report.oracle.find(row.name);
    if (it == report.oracle.end()) {
      table.rows.push_back({rowTitle(row), "0/" + std::to_string(row.worlds), "–", "–", "–"});
      continue;
    }
    const OracleRowStats& o = it->second;
    Stat coverage = o.coverage;
    coverage.mean *= 100.0;
    if (coverage.sd) *coverage.sd *= 100.0;
    table.rows.push_back({rowTitle(row),
                          std::to_string(o.worlds) + "/" + std::to_string(row.worlds),
                          meanSd(o.length_m), meanSd(o.viewpoints, "%.0f"), meanSd(coverage)});
  }
  return table;
}

plots::HtmlTable table2Cells(const Report& report) {
  plots::HtmlTable table;
  table.caption = "Table II: map types built";
  table.header = {"Method", "M1", "M2", "M3", "M4"};
  const auto row = [&](const std::string& name, const std::array<bool, 4>& maps) {
    std::vector<std::string> cells = {name};
    for (bool m : maps) cells.push_back(m ? "✓" : "");
    table.rows.push_back(std::move(cells));
  };
  for (const PaperMapTypesRow& r : paperTable2()) row(r.work, r.maps);
  table.rows.push_back({"**roomscout**", "", "", "", ""});
  for (const std::string& method : report.methods) {
    const auto it = report.map_types.find(method);
    row(methodLabel(method) + " (`" + method + "`)",
        it == report.map_types.end() ? std::array<bool, 4>{} : it->second);
  }
  return table;
}

plots::HtmlTable table3Cells(const Report& report) {
  plots::HtmlTable table;
  table.caption = "Table III: storage and update time of each map";
  table.header = {"Map type"};
  for (const ReportRow& row : report.rows) {
    const bool paper = paperColumns(row);
    const std::string t = rowTitle(row);
    table.header.push_back(t + " S (KB)");
    if (paper) table.header.push_back("paper S");
    table.header.push_back(t + " U median / p95 (s)");
    if (paper) table.header.push_back("paper U");
  }
  const std::vector<std::string>& types = mapTypes();
  for (std::size_t i = 0; i < types.size(); ++i) {
    std::vector<std::string> cells = {kMapTitles[i]};
    for (const ReportRow& row : report.rows) {
      const bool paper_cols = paperColumns(row);
      const std::optional<PaperMapCost> paper = paperTable3(row.name, types[i]);
      const auto it = report.table3.find({row.name, types[i]});
      std::string s = "–", u = "–";
      if (it != report.table3.end()) {
        const MapStats& m = it->second;
        s = meanSd(m.storage_kb);
        if (m.update_median_s.n) {
          u = formatString("%.4f", m.update_median_s.mean) + " / " +
              (m.update_p95_s.n ? formatString("%.4f", m.update_p95_s.mean) : std::string("–"));
        }
      }
      cells.push_back(s);
      if (paper_cols) cells.push_back(paper ? formatString("%.1f", paper->storage_kb) : "–");
      cells.push_back(u);
      if (paper_cols) cells.push_back(paper ? formatString("%.1f", paper->update_s) : "–");
    }
    table.rows.push_back(std::move(cells));
  }
  return table;
}

std::optional<plots::HtmlTable> slamCells(const Report& report) {
  if (!report.hasTable4()) return std::nullopt;
  const SettingComparison& comparison = report.table4;
  plots::HtmlTable table;
  table.caption = "Table IV: exploration under noise and SLAM";
  table.header = {"World", "Method"};
  const std::string main = settingTitle(report.main_setting);
  for (const char* column :
       {" T98 (s)", " L98 (m)", " success", " false occupied (%)", " occupied precision"})
    table.header.push_back(main + column);
  for (const std::string& setting : comparison.settings) {
    for (const char* column : {" T98 (s)", " L98 (m)", " success", " ATE (m)", " L98 ratio",
                               " false occupied (%)", " occupied precision"})
      table.header.push_back(setting + column);
  }
  auto accuracy = [](const SettingStats& s, std::vector<std::string>& cells) {
    cells.push_back(s.false_occupied.n ? formatString("%.2f", 100.0 * s.false_occupied.mean)
                                       : std::string("–"));
    cells.push_back(s.occupied_precision.n ? formatString("%.3f", s.occupied_precision.mean)
                                           : std::string("–"));
  };
  for (const ReportRow& row : comparison.rows) {
    for (const std::string& method : comparison.methods) {
      const auto cell = comparison.cells.find({row.name, method});
      if (cell == comparison.cells.end()) continue;
      const std::map<std::string, SettingStats>& by_setting = cell->second;
      std::vector<std::string> cells = {rowTitle(row), methodLabel(method)};
      const auto main_it = by_setting.find(report.main_setting);
      const SettingStats* main_stats = main_it == by_setting.end() ? nullptr : &main_it->second;
      if (main_stats) {
        cells.push_back(meanSd(main_stats->t98_s));
        cells.push_back(meanSd(main_stats->l98_m));
        cells.push_back(successText(main_stats->successes, main_stats->episodes));
        accuracy(*main_stats, cells);
      } else {
        cells.insert(cells.end(), 5, "–");
      }
      for (const std::string& setting : comparison.settings) {
        const auto it = by_setting.find(setting);
        if (it == by_setting.end()) {
          cells.insert(cells.end(), 7, "–");
          continue;
        }
        const SettingStats& s = it->second;
        cells.push_back(meanSd(s.t98_s));
        cells.push_back(meanSd(s.l98_m));
        std::string success = successText(s.successes, s.episodes);
        if (s.diverged) success += ", " + std::to_string(s.diverged) + " diverged";
        cells.push_back(success);
        cells.push_back(meanSd(s.ate_rmse_m, "%.2f"));
        cells.push_back(s.l98_ratio ? formatString("%.2f× (%zu)", *s.l98_ratio, s.pairs)
                                    : std::string("–"));
        accuracy(s, cells);
      }
      table.rows.push_back(std::move(cells));
    }
  }
  return table;
}

std::string slamDescription() {
  return "Each method under simulated sensor noise and SLAM beside itself in the setting of "
         "Tables I-III (noise-free when the results hold it: exact ranges and the true pose). A "
         "setting names its noise profile (noise.profile: tb3, the TurtleBot3's LDS-01 laser, "
         "VLP-16 lidar and wheel odometry, or harsh, 2.5 × their noise) and its SLAM mode "
         "(slam.mode: graph, roomscout's graph SLAM, icp, MRPT's ICP-SLAM, or rbpf, its "
         "particle-filter SLAM), whose pose "
         "estimate and map the robot explores with. T98 [s] and L98 [m] are mean ± sample "
         "standard deviation over each cell's successful episodes: final exploration rate ≥ 98 % "
         "and SLAM not diverged (a run whose ATE exceeded slam.diverged_ate_m counts as a "
         "failure, however much it explored). ATE [m]: the RMSE of the estimated against the "
         "true positions over the run, mean ± sd over the cell's episodes. L98 ratio: paired as "
         "Table I is, the setting's mean L98 over that of the first columns on the (world, "
         "seed) episodes of the same method that succeeded in both (their number in brackets). "
         "False occupied: the share of reachable floor the final map calls occupied; occupied "
         "precision: the share of the map's occupied cells within one cell of a true obstacle "
         "(metrics.json map_accuracy), means over the cell's episodes.";
}

}  // namespace roomscout::experiment
