#include "roomscout/experiment/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <sstream>
#include <tuple>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/experiment/paper_reference.hpp"
#include "roomscout/experiment/result_record.hpp"
#include "roomscout/experiment/results_file.hpp"
#include "roomscout/io/atomic_file.hpp"
#include "roomscout/sim/builtin_worlds.hpp"

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

/// "mean ± sd", "mean" for one value, "–" for none.
std::string meanSd(const Stat& s, const char* spec = "%.1f") {
  if (s.n == 0) return "–";
  std::string text = formatString(spec, s.mean);
  if (s.sd) text += " ± " + formatString(spec, *s.sd);
  return text;
}

std::string csvNumber(double v) { return formatString("%.6g", v); }
std::string csvNumber(const std::optional<double>& v) { return v ? csvNumber(*v) : ""; }

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

/// "# title\n\ndescription\n\nsources.\n\n" + the table in markdown.
std::string markdownSection(const std::string& heading, const std::string& description,
                            const std::string& sources, const plots::HtmlTable& table) {
  std::string md = heading + "\n\n" + description + "\n\n";
  if (!sources.empty()) md += sources + ".\n\n";
  return md + plots::markdownTable(table);
}

const char* kMapTitles[4] = {"2D occupancy grid", "3D point cloud", "Topological", "Semantic"};

/// Index of `name` in a record's `<what>_columns` (default columns when absent).
std::size_t columnIndex(const nlohmann::json& record, const char* columns_key,
                        const std::vector<std::string>& defaults, const std::string& name,
                        const std::string& where) {
  if (!record.contains(columns_key)) {
    const auto it = std::find(defaults.begin(), defaults.end(), name);
    return static_cast<std::size_t>(it - defaults.begin());
  }
  const nlohmann::json& columns = record[columns_key];
  if (!columns.is_array())
    throw InputError(where, std::string("'") + columns_key + "' must be an array");
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i].is_string() && columns[i].get<std::string>() == name) return i;
  }
  throw InputError(where, std::string("'") + columns_key + "' has no column '" + name + "'");
}

/// Rows of numbers `record[key]` (an array of arrays); calls visit(row) for each.
template <typename Visit>
void forEachNumberRow(const nlohmann::json& record, const char* key, std::size_t needed,
                      const std::string& where, Visit visit) {
  if (!record.contains(key) || record[key].is_null()) return;
  const nlohmann::json& rows = record[key];
  if (!rows.is_array()) throw InputError(where, std::string("'") + key + "' must be an array");
  for (const nlohmann::json& row : rows) {
    if (!row.is_array() || row.size() < needed) {
      throw InputError(where, std::string("'") + key + "' rows must be arrays of " +
                                  std::to_string(needed) + " or more numbers");
    }
    for (const nlohmann::json& v : row) {
      if (!v.is_number()) throw InputError(where, std::string("'") + key + "' holds a non-number");
    }
    visit(row);
  }
}

void readCurve(const nlohmann::json& record, const std::string& where, EpisodeSummary& e) {
  static const std::vector<std::string> kDefault = {"time_s", "length_m", "rate"};
  if (!record.contains("curve")) return;
  const std::size_t length = columnIndex(record, "curve_columns", kDefault, "length_m", where);
  const std::size_t rate = columnIndex(record, "curve_columns", kDefault, "rate", where);
  forEachNumberRow(record, "curve", std::max(length, rate) + 1, where,
                   [&](const nlohmann::json& row) {
                     e.curve.push_back({row[length].get<double>(), row[rate].get<double>()});
                   });
}

void readTrajectory(const nlohmann::json& record, const std::string& where, EpisodeSummary& e) {
  static const std::vector<std::string> kDefault = {"time_s", "x_m", "y_m", "yaw_rad"};
  if (!record.contains("trajectory")) return;
  const std::size_t x = columnIndex(record, "trajectory_columns", kDefault, "x_m", where);
  const std::size_t y = columnIndex(record, "trajectory_columns", kDefault, "y_m", where);
  forEachNumberRow(record, "trajectory", std::max(x, y) + 1, where, [&](const nlohmann::json& row) {
    e.trajectory_m.emplace_back(row[x].get<double>(), row[y].get<double>());
  });
}

/// world_spec and world_setup (see EpisodeSummary).
void readWorldAndOptions(const nlohmann::json& record, const std::string& where,
                         EpisodeSummary& e) {
  if (record.contains("world_source") && !record["world_source"].is_null()) {
    if (!record["world_source"].is_string())
      throw InputError(where, "'world_source' must be a string");
    const std::string source = record["world_source"].get<std::string>();
    const std::string builtin = "builtin:";
    e.world_spec = source.rfind(builtin, 0) == 0 ? source.substr(builtin.size()) : source;
  } else if (e.world_group == "builtin" && sim::isBuiltinWorld(e.key.world)) {
    e.world_spec = e.key.world;
  }
  nlohmann::json setup = nlohmann::json::object();
  if (record.contains("options") && record["options"].is_object()) {
    for (const char* group : {"robot", "world", "laser", "mapping", "costmap"}) {
      if (record["options"].contains(group)) setup[group] = record["options"][group];
    }
  }
  // A random start is part of the world the oracle tour is planned in.
  const auto mode = record.find("start_mode");
  if (mode != record.end() && !mode->is_string())
    throw InputError(where, "'start_mode' must be a string");
  if (mode != record.end() && *mode == "random") {
    const nlohmann::json& start = record.contains("start") ? record["start"] : nlohmann::json();
    if (!start.is_array() || start.size() != 3 ||
        !std::all_of(start.begin(), start.end(),
                     [](const nlohmann::json& v) { return v.is_number(); })) {
      throw InputError(where, "'start' must be [x, y, yaw] when 'start_mode' is 'random'");
    }
    setup["start"] = start;
  }
  if (!setup.empty()) e.world_setup = setup.dump();
  e.random_start = setup.contains("start");
}

/// The record's options <group>.<name> (a string); nullopt when the group or key is absent.
std::optional<std::string> optionText(const nlohmann::json& record, const std::string& group,
                                      const std::string& name, const std::string& where) {
  if (!record.contains("options") || !record["options"].is_object()) return std::nullopt;
  const nlohmann::json& options = record["options"];
  const auto g = options.find(group);
  if (g == options.end() || g->is_null()) return std::nullopt;
  if (!g->is_object()) throw InputError(where, "'options." + group + "' must be an object");
  const auto v = g->find(name);
  if (v == g->end() || v->is_null()) return std::nullopt;
  if (!v->is_string())
    throw InputError(where, "'options." + group + "." + name + "' must be a string");
  return v->get<std::string>();
}

/// The record's `slam` block (ate_rmse_m, diverged), and setting (see EpisodeSummary).
void readNoiseAndSlam(const nlohmann::json& record, const std::string& where, EpisodeSummary& e) {
  std::optional<std::string> slam_mode = optionText(record, "slam", "mode", where);
  const auto block = record.find("slam");
  if (block != record.end() && !block->is_null()) {
    if (!block->is_object()) throw InputError(where, "'slam' must be an object or null");
    const std::string w = where + ": slam";
    e.ate_rmse_m = optionalNumber(*block, "ate_rmse_m", w);
    const auto diverged = block->find("diverged");
    if (diverged != block->end() && !diverged->is_null()) {
      if (!diverged->is_boolean()) throw InputError(w, "'diverged' must be true or false");
      e.slam_diverged = diverged->get<bool>();
    }
    const auto mode = block->find("mode");
    if (mode != block->end() && !mode->is_null()) {
      if (!mode->is_string()) throw InputError(w, "'mode' must be a string");
      if (!slam_mode) slam_mode = mode->get<std::string>();
    }
  }
  const std::optional<std::string> noise = optionText(record, "noise", "profile", where);
  std::vector<std::string> parts;
  if (noise && !noise->empty() && *noise != "none") parts.push_back("noise " + *noise);
  if (slam_mode && !slam_mode->empty() && *slam_mode != "none")
    parts.push_back("slam " + *slam_mode);
  for (std::size_t i = 0; i < parts.size(); ++i) e.setting += (i ? ", " : "") + parts[i];
}

/// Paper worlds first, then other worlds, then groups.
void sortRows(std::vector<ReportRow>& rows) {
  std::sort(rows.begin(), rows.end(), [](const ReportRow& a, const ReportRow& b) {
    const auto rank = [](const ReportRow& r) { return r.is_group ? 200 : worldRank(r.name); };
    return std::pair(rank(a), a.name) < std::pair(rank(b), b.name);
  });
}

/// Paper order, then others by name.
std::vector<std::string> sortedMethods(const std::set<std::string>& methods) {
  std::vector<std::string> sorted(methods.begin(), methods.end());
  std::sort(sorted.begin(), sorted.end(), [](const std::string& a, const std::string& b) {
    return std::pair(methodRank(a), a) < std::pair(methodRank(b), b);
  });
  return sorted;
}

/// How a setting is named in Table IV's header.
std::string settingTitle(const std::string& setting) {
  return setting.empty() ? "noise-free" : setting;
}

/// Table IV's numbers of every (row, method) with episodes in a setting other than `main`.
SettingComparison compareSettings(const std::vector<EpisodeSummary>& episodes,
                                  const std::string& main) {
  SettingComparison table;
  struct Samples {
    std::size_t episodes = 0, successes = 0, diverged = 0;
    std::vector<double> t98, l98, ate;
  };
  std::map<std::pair<std::string, std::string>, std::map<std::string, Samples>> cells;
  std::map<std::string, std::pair<bool, std::set<std::string>>> rows;  // name -> (group, worlds)
  for (const EpisodeSummary& e : episodes) {
    const std::string row = rowNameOf(e);
    auto& r = rows[row];
    r.first = e.world_group != "builtin";
    r.second.insert(e.key.world);
    if (e.setting != main) {
      if (table.episodes[e.setting]++ == 0) table.settings.push_back(e.setting);
    }
    Samples& c = cells[{row, e.key.method}][e.setting];
    ++c.episodes;
    if (e.slam_diverged) ++c.diverged;
    if (e.succeeded()) {
      ++c.successes;
      if (e.t98_s) c.t98.push_back(*e.t98_s);
      if (e.l98_m) c.l98.push_back(*e.l98_m);
    }
    if (e.ate_rmse_m) c.ate.push_back(*e.ate_rmse_m);
  }
  std::set<std::string> row_names, methods;
  for (const auto& [key, by_setting] : cells) {
    if (by_setting.size() == 1 && by_setting.begin()->first == main) continue;
    row_names.insert(key.first);
    methods.insert(key.second);
    auto& out = table.cells[key];
    for (const auto& [setting, c] : by_setting) {
      SettingStats& s = out[setting];
      s.episodes = c.episodes;
      s.successes = c.successes;
      s.diverged = c.diverged;
      s.t98_s = Stat::of(c.t98);
      s.l98_m = Stat::of(c.l98);
      s.ate_rmse_m = Stat::of(c.ate);
    }
  }
  for (const std::string& name : row_names) {
    const auto& r = rows.at(name);
    table.rows.push_back({name, r.first, r.second.size()});
  }
  sortRows(table.rows);
  table.methods = sortedMethods(methods);
  return table;
}

/// A successful episode with the numbers Table I pairs: T98 and L98.
bool finished(const EpisodeSummary* e) { return e && e->succeeded() && e->t98_s && e->l98_m; }

/// Table I's paired numbers (see PairedRow and MethodStats) from every row's episodes by
/// (world, seed) and method; report.table1 holds a cell for every (row, method) with episodes.
void pairEpisodes(
    const std::map<std::string, std::map<std::pair<std::string, std::uint64_t>,
                                         std::map<std::string, const EpisodeSummary*>>>& by_pair,
    const std::map<std::string, std::set<std::string>>& row_methods, Report& report) {
  for (const auto& [row, pairs] : by_pair) {
    const std::set<std::string>& methods = row_methods.at(row);
    PairedRow& paired = report.paired[row];
    paired.methods = methods.size();
    paired.all_pairs = pairs.size();
    struct Samples {
      std::vector<double> t98, l98, l98_ratio, t98_ratio, oracle_ratio;
    };
    std::map<std::string, Samples> samples;
    for (const auto& [world_seed, episodes] : pairs) {
      const auto semantic = episodes.find("semantic");
      if (semantic != episodes.end() && finished(semantic->second)) {
        for (const auto& [method, e] : episodes) {
          if (method == "semantic" || !finished(e)) continue;
          MethodStats& s = report.table1.at({row, method});
          ++s.semantic_pairs;
          if (*e->l98_m < *semantic->second->l98_m) ++s.beats_semantic;
        }
      }
      if (episodes.size() != methods.size() ||
          !std::all_of(episodes.begin(), episodes.end(),
                       [](const auto& m) { return finished(m.second); }))
        continue;
      ++paired.pairs;
      const auto reference = episodes.find(report.reference);
      const EpisodeSummary* ref = reference == episodes.end() ? nullptr : reference->second;
      for (const auto& [method, e] : episodes) {
        Samples& c = samples[method];
        c.t98.push_back(*e->t98_s);
        c.l98.push_back(*e->l98_m);
        if (ref && *ref->l98_m > 0.0) c.l98_ratio.push_back(*e->l98_m / *ref->l98_m);
        if (ref && *ref->t98_s > 0.0) c.t98_ratio.push_back(*e->t98_s / *ref->t98_s);
        if (e->oracle && e->oracle->length_m > 0.0)
          c.oracle_ratio.push_back(*e->l98_m / e->oracle->length_m);
      }
    }
    for (const auto& [method, c] : samples) {
      MethodStats& s = report.table1.at({row, method});
      s.t98_s = Stat::of(c.t98);
      s.l98_m = Stat::of(c.l98);
      s.l98_reference_ratio = Stat::of(c.l98_ratio);
      s.t98_reference_ratio = Stat::of(c.t98_ratio);
      s.l98_oracle_ratio = Stat::of(c.oracle_ratio);
    }
  }
}

}  // namespace

EpisodeSummary summarizeRecord(const nlohmann::json& record, const std::string& where,
                               const fs::path& results_dir) {
  EpisodeSummary e;
  e.key = recordKey(record, where);
  e.where = where;
  if (record.contains("world_group")) {
    if (!record["world_group"].is_string())
      throw InputError(where, "'world_group' must be a string");
    e.world_group = record["world_group"].get<std::string>();
  } else {
    e.world_group = sim::isBuiltinWorld(e.key.world) ? "builtin" : "other";
  }
  const std::optional<double> rate = optionalNumber(record, "exploration_rate", where);
  if (!rate) throw InputError(where, "record has no 'exploration_rate' (a number)");
  e.exploration_rate = *rate;
  e.t98_s = optionalNumber(record, "t98_s", where);
  e.l98_m = optionalNumber(record, "l98_m", where);
  e.revisits = optionalNumber(record, "revisits", where);
  e.revisits_98 = optionalNumber(record, "revisits_98", where);
  if (record.contains("map_stats")) {
    const nlohmann::json& maps = record["map_stats"];
    if (!maps.is_object()) throw InputError(where, "'map_stats' must be an object");
    for (const auto& [type, stats] : maps.items()) {
      const std::string w = where + ": map_stats." + type;
      if (!stats.is_object()) throw InputError(w, "must be an object");
      MapSample m;
      m.storage_bytes = optionalNumber(stats, "storage_bytes", w).value_or(0.0);
      const double updates = optionalNumber(stats, "updates", w).value_or(0.0);
      if (!(updates >= 0.0 && updates <= 1e15))
        throw InputError(w, "'updates' must be a count >= 0, not " + formatDouble(updates));
      m.updates = static_cast<std::size_t>(updates);
      m.update_median_ms = optionalNumber(stats, "update_median_ms", w);
      m.update_p95_ms = optionalNumber(stats, "update_p95_ms", w);
      e.maps[type] = m;
    }
  }
  readWorldAndOptions(record, where, e);
  readNoiseAndSlam(record, where, e);
  readCurve(record, where, e);
  if (record.contains("outputs") && !record["outputs"].is_null()) {
    if (!record["outputs"].is_string())
      throw InputError(where, "'outputs' must be a string or null");
    e.outputs_dir = results_dir / record["outputs"].get<std::string>();
    readTrajectory(record, where, e);
  }
  return e;
}

ResultSet loadResults(const std::vector<fs::path>& inputs) {
  if (inputs.empty()) throw OptionError("report: no results directory given");
  ResultSet set;
  std::set<std::pair<EpisodeKey, std::string>> seen;  // (key, setting)
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
          EpisodeSummary e = summarizeRecord(record, where, file.parent_path());
          if (!seen.emplace(e.key, e.setting).second) {
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

bool EpisodeSummary::succeeded() const {
  return exploration_rate >= kSuccessRate && !slam_diverged;
}

std::string mainSetting(const std::vector<EpisodeSummary>& episodes) {
  if (episodes.empty()) return {};
  const bool noise_free = std::any_of(episodes.begin(), episodes.end(),
                                      [](const EpisodeSummary& e) { return e.setting.empty(); });
  return noise_free ? std::string() : episodes.front().setting;
}

ResultSet episodesOfSetting(const ResultSet& results, const std::string& setting) {
  ResultSet set;
  set.files = results.files;
  set.duplicates = results.duplicates;
  set.truncated = results.truncated;
  for (const EpisodeSummary& e : results.episodes) {
    if (e.setting == setting) set.episodes.push_back(e);
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

std::string rowNameOf(const EpisodeSummary& e) {
  return e.world_group == "builtin" ? e.key.world : e.world_group;
}

std::string rowTitle(const ReportRow& row) {
  if (!row.is_group) return row.name;
  return row.name + " (" + std::to_string(row.worlds) + (row.worlds == 1 ? " world)" : " worlds)");
}

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

Report buildReport(const ResultSet& results) {
  Report report;
  report.files = results.files;
  report.main_setting = mainSetting(results.episodes);
  report.table4 = compareSettings(results.episodes, report.main_setting);
  std::vector<const EpisodeSummary*> episodes;  // of the main setting
  for (const EpisodeSummary& e : results.episodes) {
    if (e.setting == report.main_setting) episodes.push_back(&e);
  }
  report.episodes = episodes.size();

  std::map<std::string, std::pair<bool, std::set<std::string>>> rows;  // name -> (group, worlds)
  std::set<std::string> methods;
  struct Samples {
    std::size_t episodes = 0, successes = 0;
    std::vector<double> own_t98, own_l98, revisits, revisits_98;
  };
  std::map<std::pair<std::string, std::string>, Samples> cells;
  // row -> (world, seed) -> method -> its episode, for pairing the methods' episodes
  std::map<std::string, std::map<std::pair<std::string, std::uint64_t>,
                                 std::map<std::string, const EpisodeSummary*>>>
      by_pair;
  std::map<std::string, std::set<std::string>> row_methods;
  // (world, method) -> distinct (final rate, T98, L98) of its seeds, and its episode count
  using Outcome = std::tuple<double, std::optional<double>, std::optional<double>>;
  std::map<std::pair<std::string, std::string>, std::pair<std::set<Outcome>, std::size_t>> outcomes;
  struct MapSamples {
    std::size_t episodes = 0;
    std::vector<double> storage_kb, median_s, p95_s;
  };
  std::map<std::pair<std::string, std::string>, MapSamples> map_cells;
  // row -> (world, world setup) -> its oracle: one per world, or with random starts one per
  // world and start
  std::map<std::string, std::map<std::pair<std::string, std::string>, OracleReference>> oracles;
  const std::vector<std::string>& types = mapTypes();

  for (const EpisodeSummary* episode : episodes) {
    const EpisodeSummary& e = *episode;
    const std::string row = rowNameOf(e);
    const bool is_group = e.world_group != "builtin";
    if (e.random_start) ++report.random_start_episodes;
    auto& r = rows[row];
    r.first = is_group;
    r.second.insert(e.key.world);
    methods.insert(e.key.method);
    row_methods[row].insert(e.key.method);
    by_pair[row][{e.key.world, e.key.seed}][e.key.method] = &e;
    Samples& c = cells[{row, e.key.method}];
    ++c.episodes;
    if (e.succeeded()) {
      ++c.successes;
      if (e.t98_s) c.own_t98.push_back(*e.t98_s);
      if (e.l98_m) c.own_l98.push_back(*e.l98_m);
    }
    if (e.revisits) c.revisits.push_back(*e.revisits);
    if (e.revisits_98) c.revisits_98.push_back(*e.revisits_98);
    auto& o = outcomes[{e.key.world, e.key.method}];
    o.first.emplace(e.exploration_rate, e.t98_s, e.l98_m);
    ++o.second;
    if (e.oracle) oracles[row].emplace(std::pair{e.key.world, e.world_setup}, *e.oracle);
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
  sortRows(report.rows);
  report.methods = sortedMethods(methods);
  if (!report.methods.empty()) {
    const bool rrt = methods.contains("rrt");
    report.reference = rrt ? std::string("rrt") : report.methods.front();
  }
  for (const auto& [key, c] : cells) {
    MethodStats& s = report.table1[key];
    s.episodes = c.episodes;
    s.successes = c.successes;
    s.own_t98_s = Stat::of(c.own_t98);
    s.own_l98_m = Stat::of(c.own_l98);
    s.revisits = Stat::of(c.revisits);
    s.revisits_98 = Stat::of(c.revisits_98);
  }
  pairEpisodes(by_pair, row_methods, report);
  // A row's cell repeats itself when each of its worlds run with several seeds had one outcome.
  std::map<std::pair<std::string, std::string>, std::pair<bool, bool>>
      repeats;  // (several, all same)
  for (const EpisodeSummary* e : episodes) {
    const auto& [distinct, count] = outcomes.at({e->key.world, e->key.method});
    if (count < 2) continue;
    auto& r = repeats.try_emplace({rowNameOf(*e), e->key.method}, false, true).first->second;
    r.first = true;
    r.second = r.second && distinct.size() == 1;
  }
  for (const auto& [key, r] : repeats) report.table1[key].same_every_seed = r.first && r.second;
  for (const auto& [key, c] : map_cells) {
    MapStats& s = report.table3[key];
    s.episodes = c.episodes;
    s.storage_kb = Stat::of(c.storage_kb);
    s.update_median_s = Stat::of(c.median_s);
    s.update_p95_s = Stat::of(c.p95_s);
  }
  for (const auto& [row, tours] : oracles) {
    std::vector<double> length, coverage, viewpoints;
    std::set<std::string> worlds;
    for (const auto& [world_and_setup, o] : tours) {
      worlds.insert(world_and_setup.first);
      length.push_back(o.length_m);
      coverage.push_back(o.coverage);
      viewpoints.push_back(static_cast<double>(o.viewpoints));
    }
    OracleRowStats& s = report.oracle[row];
    s.worlds = worlds.size();
    s.length_m = Stat::of(length);
    s.coverage = Stat::of(coverage);
    s.viewpoints = Stat::of(viewpoints);
  }
  return report;
}

bool Report::hasSemantic() const {
  return std::find(methods.begin(), methods.end(), "semantic") != methods.end();
}

std::vector<std::string> Report::methodsSameEverySeed() const {
  std::vector<std::string> out;
  for (const std::string& method : methods) {
    bool several = false, same = true;
    for (const ReportRow& row : rows) {
      const auto it = table1.find({row.name, method});
      if (it == table1.end()) continue;
      // Rows without several seeds of a world do not say either way.
      const bool repeated = it->second.same_every_seed;
      several = several || repeated;
      if (!repeated && it->second.episodes > row.worlds) same = false;
    }
    if (several && same) out.push_back(method);
  }
  return out;
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
  for (const char* column : {" T98 (s)", " L98 (m)", " success"})
    table.header.push_back(main + column);
  for (const std::string& setting : comparison.settings) {
    for (const char* column : {" T98 (s)", " L98 (m)", " success", " ATE (m)", " L98 ratio"})
      table.header.push_back(setting + column);
  }
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
      } else {
        cells.insert(cells.end(), 3, "–");
      }
      for (const std::string& setting : comparison.settings) {
        const auto it = by_setting.find(setting);
        if (it == by_setting.end()) {
          cells.insert(cells.end(), 5, "–");
          continue;
        }
        const SettingStats& s = it->second;
        cells.push_back(meanSd(s.t98_s));
        cells.push_back(meanSd(s.l98_m));
        std::string success = successText(s.successes, s.episodes);
        if (s.diverged) success += ", " + std::to_string(s.diverged) + " diverged";
        cells.push_back(success);
        cells.push_back(meanSd(s.ate_rmse_m, "%.2f"));
        const bool ratio =
            main_stats && main_stats->l98_m.n && main_stats->l98_m.mean > 0.0 && s.l98_m.n;
        cells.push_back(ratio ? formatString("%.2f", s.l98_m.mean / main_stats->l98_m.mean) + "×"
                              : "–");
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
         "(slam.mode: icp, MRPT's ICP-SLAM, or rbpf, its particle-filter SLAM), whose pose "
         "estimate and map the robot explores with. T98 [s] and L98 [m] are mean ± sample "
         "standard deviation over each cell's successful episodes: final exploration rate ≥ 98 % "
         "and SLAM not diverged (a run whose ATE exceeded slam.diverged_ate_m counts as a "
         "failure, however much it explored). ATE [m]: the RMSE of the estimated against the "
         "true positions over the run, mean ± sd over the cell's episodes; L98 ratio: the "
         "setting's mean L98 over that of the first columns, same world and method.";
}

std::string table1Markdown(const Report& report) {
  const std::string same = sameEverySeedLine(report);
  const std::string starts = startPosesLine(report);
  const std::string pairing = pairingLine(report);
  const std::string intro =
      "# Table I: exploration time and trajectory length\n\n" + table1Description() + "\n\n" +
      (pairing.empty() ? "" : pairing + "\n\n") + (same.empty() ? "" : same + "\n\n") +
      (starts.empty() ? "" : starts + "\n\n") + sourcesLine(report) + ".\n\n";
  if (report.rows.empty()) return intro + "No episodes.\n";
  plots::HtmlTable table = table1Cells(report);
  table.caption.clear();
  plots::HtmlTable revisits = revisitsCells(report);
  revisits.caption.clear();
  std::string md = intro + plots::markdownTable(table) + "\n" +
                   markdownSection("## Revisits", revisitsDescription(), "", revisits);
  if (std::optional<plots::HtmlTable> oracle = oracleCells(report)) {
    oracle->caption.clear();
    md += "\n" + markdownSection("## Oracle reference", oracleDescription(), "", *oracle);
  }
  return md;
}

std::string table1Csv(const Report& report) {
  std::ostringstream csv;
  csv << "world,is_group,worlds,method,method_label,episodes,successes,success_rate,t98_n,t98_"
         "mean_s,t98_sd_s,l98_n,l98_mean_m,l98_sd_m,revisits_n,revisits_mean,revisits_sd,paper_"
         "t_s,paper_l_m,oracle_worlds,oracle_l_mean_m,oracle_l_sd_m,l98_oracle_ratio_n,l98_"
         "oracle_ratio_mean,l98_oracle_ratio_sd,revisits_98_n,revisits_98_mean,revisits_98_sd,"
         "pairs,"
         "all_pairs,own_t98_n,own_t98_mean_s,own_t98_sd_s,own_l98_n,own_l98_mean_m,own_l98_sd_m,"
         "reference,l98_reference_ratio_n,l98_reference_ratio_mean,l98_reference_ratio_sd,t98_"
         "reference_ratio_mean,t98_reference_ratio_sd,semantic_pairs,beats_semantic\n";
  for (const ReportRow& row : report.rows) {
    const auto oracle = report.oracle.find(row.name);
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
          << ",";
      if (oracle != report.oracle.end()) {
        csv << oracle->second.worlds << "," << mean(oracle->second.length_m) << ","
            << csvNumber(oracle->second.length_m.sd);
      } else {
        csv << "0,,";
      }
      csv << "," << s.l98_oracle_ratio.n << "," << mean(s.l98_oracle_ratio) << ","
          << csvNumber(s.l98_oracle_ratio.sd) << "," << s.revisits_98.n << ","
          << mean(s.revisits_98) << "," << csvNumber(s.revisits_98.sd) << ",";
      const auto paired = report.paired.find(row.name);
      if (paired != report.paired.end()) {
        csv << paired->second.pairs << "," << paired->second.all_pairs;
      } else {
        csv << "0,0";
      }
      csv << "," << s.own_t98_s.n << "," << mean(s.own_t98_s) << "," << csvNumber(s.own_t98_s.sd)
          << "," << s.own_l98_m.n << "," << mean(s.own_l98_m) << "," << csvNumber(s.own_l98_m.sd)
          << "," << report.reference << "," << s.l98_reference_ratio.n << ","
          << mean(s.l98_reference_ratio) << "," << csvNumber(s.l98_reference_ratio.sd) << ","
          << mean(s.t98_reference_ratio) << "," << csvNumber(s.t98_reference_ratio.sd) << ","
          << s.semantic_pairs << "," << s.beats_semantic << "\n";
    }
  }
  return csv.str();
}

std::string table2Markdown(const Report& report) {
  plots::HtmlTable table = table2Cells(report);
  table.caption.clear();
  return markdownSection("# Table II: map types built", table2Description(), sourcesLine(report),
                         table);
}

std::string table3Markdown(const Report& report) {
  const std::string intro = "# Table III: storage and update time of each map\n\n" +
                            table3Description() + "\n\n" + sourcesLine(report) + ".\n\n";
  if (report.rows.empty()) return intro + "No episodes.\n";
  plots::HtmlTable table = table3Cells(report);
  table.caption.clear();
  std::string md = intro + plots::markdownTable(table) + "\nEpisodes per world:";
  const std::vector<std::string>& types = mapTypes();
  for (const ReportRow& row : report.rows) {
    std::size_t n = 0;
    for (const std::string& t : types) {
      const auto it = report.table3.find({row.name, t});
      if (it != report.table3.end()) n = std::max(n, it->second.episodes);
    }
    md += " " + rowTitle(row) + " " + std::to_string(n) + (&row == &report.rows.back() ? "." : ";");
  }
  return md + "\n";
}

std::string slamMarkdown(const Report& report) {
  std::optional<plots::HtmlTable> table = slamCells(report);
  if (!table) return {};
  table->caption.clear();
  return markdownSection("# Table IV: exploration under noise and SLAM", slamDescription(),
                         sourcesLine(report), *table);
}

std::vector<fs::path> writeReport(const Report& report, const fs::path& directory) {
  io::ensureWritableDirectory(directory);
  std::vector<std::pair<std::string, std::string>> files = {
      {"table1.md", table1Markdown(report)},
      {"table1.csv", table1Csv(report)},
      {"table2.md", table2Markdown(report)},
      {"table3.md", table3Markdown(report)},
  };
  if (report.hasTable4()) files.emplace_back("table4_slam.md", slamMarkdown(report));
  std::vector<fs::path> written;
  for (const auto& [name, text] : files) {
    io::writeFileAtomic(directory / name, text);
    written.push_back(directory / name);
  }
  return written;
}

}  // namespace roomscout::experiment
