#include "roomscout/experiment/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "roomscout/core/errors.hpp"
#include "roomscout/experiment/paper_reference.hpp"
#include "roomscout/experiment/result_record.hpp"
#include "roomscout/experiment/results_file.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/io/builtin_worlds.hpp"

namespace roomscout::experiment {
namespace fs = std::filesystem;
namespace {

std::optional<double> optionalNumber(const nlohmann::json& record, const char* key,
                                     const std::string& where) {
  if (!record.contains(key) || record[key].is_null()) return std::nullopt;
  if (!record[key].is_number())
    throw InputError(where, std::string("'") + key + "' must be a number or null");
  return record[key].get<double>();
}

std::string format(const char* spec, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, v);
  return buf;
}

/// "mean ± sd", "mean" for one value, "–" for none.
std::string meanSd(const Stat& s, const char* spec = "%.1f") {
  if (s.n == 0) return "–";
  std::string text = format(spec, s.mean);
  if (s.sd) text += " ± " + format(spec, *s.sd);
  return text;
}

std::string csvNumber(double v) { return format("%.6g", v); }
std::string csvNumber(const std::optional<double>& v) { return v ? csvNumber(*v) : ""; }

/// The row an episode belongs to: its world when built in, else its world's group.
std::pair<std::string, bool> rowOf(const EpisodeSummary& e) {
  if (e.world_group == "builtin") return {e.key.world, false};
  return {e.world_group, true};
}

std::string rowTitle(const ReportRow& row) {
  if (!row.is_group) return row.name;
  return row.name + " (" + std::to_string(row.worlds) + (row.worlds == 1 ? " world)" : " worlds)");
}

std::string sourcesLine(const Report& report) {
  std::string text = std::to_string(report.episodes) + " episodes from ";
  for (std::size_t i = 0; i < report.files.size(); ++i) {
    text += (i ? ", " : "") + std::string("`") + report.files[i].string() + "`";
  }
  return text;
}

const char* kMapTitles[4] = {"2D occupancy grid", "3D point cloud", "Topological", "Semantic"};

}  // namespace

EpisodeSummary summarizeRecord(const nlohmann::json& record, const std::string& where) {
  EpisodeSummary e;
  e.key = recordKey(record, where);
  e.where = where;
  if (record.contains("world_group")) {
    if (!record["world_group"].is_string())
      throw InputError(where, "'world_group' must be a string");
    e.world_group = record["world_group"].get<std::string>();
  } else {
    e.world_group = io::isBuiltinWorld(e.key.world) ? "builtin" : "other";
  }
  const std::optional<double> rate = optionalNumber(record, "exploration_rate", where);
  if (!rate) throw InputError(where, "record has no 'exploration_rate' (a number)");
  e.exploration_rate = *rate;
  e.t98_s = optionalNumber(record, "t98_s", where);
  e.l98_m = optionalNumber(record, "l98_m", where);
  e.revisits = optionalNumber(record, "revisits", where);
  if (record.contains("map_stats")) {
    const nlohmann::json& maps = record["map_stats"];
    if (!maps.is_object()) throw InputError(where, "'map_stats' must be an object");
    for (const auto& [type, stats] : maps.items()) {
      const std::string w = where + ": map_stats." + type;
      if (!stats.is_object()) throw InputError(w, "must be an object");
      MapSample m;
      m.storage_bytes = optionalNumber(stats, "storage_bytes", w).value_or(0.0);
      m.updates = static_cast<std::size_t>(optionalNumber(stats, "updates", w).value_or(0.0));
      m.update_median_ms = optionalNumber(stats, "update_median_ms", w);
      m.update_p95_ms = optionalNumber(stats, "update_p95_ms", w);
      e.maps[type] = m;
    }
  }
  return e;
}

ResultSet loadResults(const std::vector<fs::path>& inputs) {
  if (inputs.empty()) throw OptionError("report: no results directory given");
  ResultSet set;
  std::set<EpisodeKey> seen;
  for (const fs::path& input : inputs) {
    std::error_code ec;
    const fs::path file = fs::is_directory(input, ec) ? input / "results.jsonl" : input;
    if (!fs::exists(file, ec)) {
      throw InputError(file.string(),
                       fs::is_directory(input, ec)
                           ? "no results.jsonl in this directory (run `roomscout bench` first)"
                           : "file not found");
    }
    const ResultsScan scan =
        forEachRecord(file, [&](const nlohmann::json& record, const std::string& where) {
          EpisodeSummary e = summarizeRecord(record, where);
          if (!seen.insert(e.key).second) {
            ++set.duplicates;
            return;
          }
          set.episodes.push_back(std::move(e));
        });
    if (scan.truncated_tail) ++set.truncated;
    set.files.push_back(file);
  }
  return set;
}

Stat Stat::of(const std::vector<double>& values) {
  Stat s;
  s.n = values.size();
  if (s.n == 0) return s;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n >= 2) {
    double ss = 0.0;
    for (double v : values) ss += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(ss / static_cast<double>(s.n - 1));
  }
  return s;
}

Report buildReport(const ResultSet& results) {
  Report report;
  report.episodes = results.episodes.size();
  report.files = results.files;

  std::map<std::string, std::pair<bool, std::set<std::string>>> rows;  // name -> (group, worlds)
  std::set<std::string> methods;
  struct Samples {
    std::size_t episodes = 0, successes = 0;
    std::vector<double> t98, l98, revisits;
  };
  std::map<std::pair<std::string, std::string>, Samples> cells;
  struct MapSamples {
    std::size_t episodes = 0;
    std::vector<double> storage_kb, median_s, p95_s;
  };
  std::map<std::pair<std::string, std::string>, MapSamples> map_cells;
  const std::vector<std::string>& types = mapTypes();

  for (const EpisodeSummary& e : results.episodes) {
    const auto [row, is_group] = rowOf(e);
    auto& r = rows[row];
    r.first = is_group;
    r.second.insert(e.key.world);
    methods.insert(e.key.method);
    Samples& c = cells[{row, e.key.method}];
    ++c.episodes;
    if (e.exploration_rate >= kSuccessRate) ++c.successes;
    if (e.t98_s) c.t98.push_back(*e.t98_s);
    if (e.l98_m) c.l98.push_back(*e.l98_m);
    if (e.revisits) c.revisits.push_back(*e.revisits);
    auto& built = report.map_types[e.key.method];
    for (std::size_t i = 0; i < types.size(); ++i) {
      const auto it = e.maps.find(types[i]);
      if (it == e.maps.end()) continue;
      const MapSample& m = it->second;
      if (m.storage_bytes > 0.0 || m.updates > 0) built[i] = true;
      MapSamples& mc = map_cells[{row, types[i]}];
      ++mc.episodes;
      mc.storage_kb.push_back(m.storage_bytes / 1024.0);
      if (m.update_median_ms) mc.median_s.push_back(*m.update_median_ms / 1000.0);
      if (m.update_p95_ms) mc.p95_s.push_back(*m.update_p95_ms / 1000.0);
    }
  }

  for (const auto& [name, r] : rows) report.rows.push_back({name, r.first, r.second.size()});
  std::sort(report.rows.begin(), report.rows.end(), [](const ReportRow& a, const ReportRow& b) {
    const auto rank = [](const ReportRow& r) { return r.is_group ? 200 : worldRank(r.name); };
    return std::pair(rank(a), a.name) < std::pair(rank(b), b.name);
  });
  report.methods.assign(methods.begin(), methods.end());
  std::sort(report.methods.begin(), report.methods.end(),
            [](const std::string& a, const std::string& b) {
              return std::pair(methodRank(a), a) < std::pair(methodRank(b), b);
            });
  for (const auto& [key, c] : cells) {
    MethodStats& s = report.table1[key];
    s.episodes = c.episodes;
    s.successes = c.successes;
    s.t98_s = Stat::of(c.t98);
    s.l98_m = Stat::of(c.l98);
    s.revisits = Stat::of(c.revisits);
  }
  for (const auto& [key, c] : map_cells) {
    MapStats& s = report.table3[key];
    s.episodes = c.episodes;
    s.storage_kb = Stat::of(c.storage_kb);
    s.update_median_s = Stat::of(c.median_s);
    s.update_p95_s = Stat::of(c.p95_s);
  }
  return report;
}

std::string table1Markdown(const Report& report) {
  std::ostringstream md;
  md << "# Table I: exploration time and trajectory length\n\n"
     << "T98 [s] and L98 [m]: simulated time and distance driven when the exploration rate first "
        "reached 98 %, mean ± sample standard deviation over the episodes that reached it. "
        "Success: episodes whose final exploration rate is ≥ 98 %. *Paper*: the paper's Table I "
        "(T s, L m). A group of worlds (world files of one folder, e.g. houseexpo) pools every "
        "world × seed episode.\n\n"
     << sourcesLine(report) << ".\n\n";
  if (report.rows.empty()) return md.str() + "No episodes.\n";

  md << "| Method |";
  std::string rule = "|---|";
  for (const ReportRow& row : report.rows) {
    const bool paper = !row.is_group && worldRank(row.name) < 100;
    const std::string t = rowTitle(row);
    md << " " << t << " T98 (s) |" << (paper ? " paper T |" : "") << " " << t << " L98 (m) |"
       << (paper ? " paper L |" : "") << " " << t << " success |";
    rule += paper ? "---:|---:|---:|---:|---:|" : "---:|---:|---:|";
  }
  md << "\n" << rule << "\n";
  for (const std::string& method : report.methods) {
    md << "| " << methodLabel(method) << " |";
    for (const ReportRow& row : report.rows) {
      const bool paper_cols = !row.is_group && worldRank(row.name) < 100;
      const auto it = report.table1.find({row.name, method});
      const std::optional<PaperTimeLength> paper = paperTable1(row.name, method);
      const std::string paper_t = paper ? format("%.0f", paper->t_s) : "–";
      const std::string paper_l = paper ? format("%.0f", paper->l_m) : "–";
      if (it == report.table1.end()) {
        md << " – |" << (paper_cols ? " " + paper_t + " |" : "") << " – |"
           << (paper_cols ? " " + paper_l + " |" : "") << " – |";
        continue;
      }
      const MethodStats& s = it->second;
      md << " " << meanSd(s.t98_s) << " |" << (paper_cols ? " " + paper_t + " |" : "") << " "
         << meanSd(s.l98_m) << " |" << (paper_cols ? " " + paper_l + " |" : "") << " "
         << s.successes << "/" << s.episodes << " ("
         << format("%.0f",
                   100.0 * static_cast<double>(s.successes) / static_cast<double>(s.episodes))
         << " %) |";
    }
    md << "\n";
  }

  md << "\n## Revisits\n\nEntries into a ground-truth room that had been entered before, mean ± "
        "sample standard deviation over all episodes.\n\n| Method |";
  rule = "|---|";
  for (const ReportRow& row : report.rows) {
    md << " " << rowTitle(row) << " |";
    rule += "---:|";
  }
  md << "\n" << rule << "\n";
  for (const std::string& method : report.methods) {
    md << "| " << methodLabel(method) << " |";
    for (const ReportRow& row : report.rows) {
      const auto it = report.table1.find({row.name, method});
      md << " " << (it == report.table1.end() ? std::string("–") : meanSd(it->second.revisits))
         << " |";
    }
    md << "\n";
  }
  return md.str();
}

std::string table1Csv(const Report& report) {
  std::ostringstream csv;
  csv << "world,is_group,worlds,method,method_label,episodes,successes,success_rate,t98_n,t98_mean_"
         "s,"
         "t98_sd_s,l98_n,l98_mean_m,l98_sd_m,revisits_n,revisits_mean,revisits_sd,paper_t_s,paper_"
         "l_m\n";
  for (const ReportRow& row : report.rows) {
    for (const std::string& method : report.methods) {
      const auto it = report.table1.find({row.name, method});
      if (it == report.table1.end()) continue;
      const MethodStats& s = it->second;
      const std::optional<PaperTimeLength> paper = paperTable1(row.name, method);
      std::string label = methodLabel(method);
      if (label.find_first_of(",\"") != std::string::npos) label = "\"" + label + "\"";
      const auto mean = [](const Stat& st) { return st.n ? csvNumber(st.mean) : std::string(); };
      csv << row.name << "," << (row.is_group ? 1 : 0) << "," << row.worlds << "," << method << ","
          << label << "," << s.episodes << "," << s.successes << ","
          << csvNumber(static_cast<double>(s.successes) / static_cast<double>(s.episodes)) << ","
          << s.t98_s.n << "," << mean(s.t98_s) << "," << csvNumber(s.t98_s.sd) << "," << s.l98_m.n
          << "," << mean(s.l98_m) << "," << csvNumber(s.l98_m.sd) << "," << s.revisits.n << ","
          << mean(s.revisits) << "," << csvNumber(s.revisits.sd) << ","
          << (paper ? csvNumber(paper->t_s) : "") << "," << (paper ? csvNumber(paper->l_m) : "")
          << "\n";
    }
  }
  return csv.str();
}

std::string table2Markdown(const Report& report) {
  std::ostringstream md;
  md << "# Table II: map types built\n\n"
     << "M1: 2D occupancy grid, M2: 3D point cloud, M3: topological map, M4: semantic map. Above "
        "the line: the paper's Table II (its survey of earlier work, and its own method). Below: "
        "each method of these results, ✓ when its episodes recorded that map (stored bytes or "
        "updates). In roomscout every method's episode builds all four maps; the strategies "
        "decide on the occupancy grid, and the semantic ones also read the rooms.\n\n"
     << sourcesLine(report) << ".\n\n"
     << "| Method | M1 | M2 | M3 | M4 |\n|---|:-:|:-:|:-:|:-:|\n";
  const auto row = [&](const std::string& name, const std::array<bool, 4>& maps) {
    md << "| " << name << " |";
    for (bool m : maps) md << (m ? " ✓ |" : "  |");
    md << "\n";
  };
  for (const PaperMapTypesRow& r : paperTable2()) row(r.work, r.maps);
  md << "| **roomscout** | | | | |\n";
  for (const std::string& method : report.methods) {
    const auto it = report.map_types.find(method);
    row(methodLabel(method) + " (`" + method + "`)",
        it == report.map_types.end() ? std::array<bool, 4>{} : it->second);
  }
  return md.str();
}

std::string table3Markdown(const Report& report) {
  std::ostringstream md;
  md << "# Table III: storage and update time of each map\n\n"
     << "S: storage [KB = 1024 bytes] of the map's data files at the end of an episode "
        "(occupancy: occupancy.pgm + occupancy.yaml; point cloud: pointcloud.pcd, "
        "binary_compressed; topological: topology.json; semantic: semantic.json + "
        "semantic_labels.png; pictures such as run.png are not counted), mean over episodes. "
        "U: update time [s] as median / p95 of one episode's updates, each averaged over "
        "episodes (occupancy: one laser scan; point cloud: one keyframe, ray cast + insert; "
        "topological and semantic: one rebuild). Every method's episodes of a world are pooled. "
        "*Paper*: the paper's Table III (S KB, U s).\n\n"
     << sourcesLine(report) << ".\n\n";
  if (report.rows.empty()) return md.str() + "No episodes.\n";
  md << "| Map type |";
  std::string rule = "|---|";
  for (const ReportRow& row : report.rows) {
    const bool paper = !row.is_group && worldRank(row.name) < 100;
    const std::string t = rowTitle(row);
    md << " " << t << " S (KB) |" << (paper ? " paper S |" : "") << " " << t
       << " U median / p95 (s) |" << (paper ? " paper U |" : "");
    rule += paper ? "---:|---:|---:|---:|" : "---:|---:|";
  }
  md << "\n" << rule << "\n";
  const std::vector<std::string>& types = mapTypes();
  for (std::size_t i = 0; i < types.size(); ++i) {
    md << "| " << kMapTitles[i] << " |";
    for (const ReportRow& row : report.rows) {
      const bool paper_cols = !row.is_group && worldRank(row.name) < 100;
      const std::optional<PaperMapCost> paper = paperTable3(row.name, types[i]);
      const auto it = report.table3.find({row.name, types[i]});
      std::string s = "–", u = "–";
      if (it != report.table3.end()) {
        const MapStats& m = it->second;
        s = meanSd(m.storage_kb);
        if (m.update_median_s.n) {
          u = format("%.4f", m.update_median_s.mean) + " / " +
              (m.update_p95_s.n ? format("%.4f", m.update_p95_s.mean) : std::string("–"));
        }
      }
      md << " " << s << " |"
         << (paper_cols ? " " + (paper ? format("%.1f", paper->storage_kb) : "–") + " |" : "")
         << " " << u << " |"
         << (paper_cols ? " " + (paper ? format("%.1f", paper->update_s) : "–") + " |" : "");
    }
    md << "\n";
  }
  md << "\nEpisodes per world:";
  for (const ReportRow& row : report.rows) {
    std::size_t n = 0;
    for (const std::string& t : types) {
      const auto it = report.table3.find({row.name, t});
      if (it != report.table3.end()) n = std::max(n, it->second.episodes);
    }
    md << " " << rowTitle(row) << " " << n << (&row == &report.rows.back() ? "." : ";");
  }
  md << "\n";
  return md.str();
}

std::vector<fs::path> writeReport(const Report& report, const fs::path& directory) {
  io::ensureWritableDirectory(directory);
  const std::vector<std::pair<std::string, std::string>> files = {
      {"table1.md", table1Markdown(report)},
      {"table1.csv", table1Csv(report)},
      {"table2.md", table2Markdown(report)},
      {"table3.md", table3Markdown(report)},
  };
  std::vector<fs::path> written;
  for (const auto& [name, text] : files) {
    io::writeFileAtomic(directory / name, text);
    written.push_back(directory / name);
  }
  return written;
}

}  // namespace roomscout::experiment
