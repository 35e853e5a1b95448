#include "roomscout/experiment/report_records.hpp"

#include <algorithm>
#include <set>

#include "roomscout/core/errors.hpp"
#include "roomscout/core/format.hpp"
#include "roomscout/experiment/result_record.hpp"
#include "roomscout/experiment/results_file.hpp"
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
  if (const auto accuracy = record.find("map_accuracy");
      accuracy != record.end() && !accuracy->is_null()) {
    if (!accuracy->is_object()) throw InputError(where, "'map_accuracy' must be an object");
    const std::string w = where + ": map_accuracy";
    e.false_occupied = optionalNumber(*accuracy, "false_occupied", w);
    e.occupied_precision = optionalNumber(*accuracy, "occupied_precision", w);
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

}  // namespace roomscout::experiment
