#pragma once
// `roomscout report`: tables in the layout of the paper's Tables I-III from one or more
// results.jsonl files. Figures can be added on top: loadResults() gives every episode's key
// and numbers, forEachRecord() (results_file.hpp) every full record with curves and
// trajectory, and buildReport() the per world x method statistics.

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "roomscout/experiment/episode_key.hpp"

namespace roomscout::experiment {

/// One map's numbers in one episode.
struct MapSample {
  double storage_bytes = 0.0;
  std::size_t updates = 0;
  std::optional<double> update_median_ms;
  std::optional<double> update_p95_ms;
};

/// The numbers of one recorded episode that the tables use.
struct EpisodeSummary {
  EpisodeKey key;
  std::string world_group;  ///< "builtin" or the folder of the world file
  double exploration_rate = 0.0;
  std::optional<double> t98_s;
  std::optional<double> l98_m;
  std::optional<double> revisits;
  std::map<std::string, MapSample> maps;  ///< by map type (record's map_stats)
  std::string where;                      ///< "file:line" of the record
};

/// The episode's numbers from a results record. Throws InputError(where, ...) when the key or
/// exploration_rate is missing or a field has the wrong type.
EpisodeSummary summarizeRecord(const nlohmann::json& record, const std::string& where);

/// Episodes merged from several results files, one per key.
struct ResultSet {
  std::vector<EpisodeSummary> episodes;      ///< in input order
  std::vector<std::filesystem::path> files;  ///< the results files read
  std::size_t duplicates = 0;                ///< records dropped because their key came earlier
  std::size_t truncated = 0;                 ///< files that ended in a truncated line (ignored)
};

/// Reads each input (a bench directory, meaning its results.jsonl, or a .jsonl file) and
/// merges the records; of records with the same key the first one read is kept. Throws
/// InputError naming the file (and line) that is missing or malformed.
ResultSet loadResults(const std::vector<std::filesystem::path>& inputs);

/// Mean and sample standard deviation (n - 1) of some values.
struct Stat {
  std::size_t n = 0;
  double mean = 0.0;
  std::optional<double> sd;  ///< nullopt when n < 2
  static Stat of(const std::vector<double>& values);
};

/// A row of the tables: a world of its own, or a group of worlds summarised together (worlds
/// that are not built-in, grouped by the folder of their file, e.g. 50 HouseExpo plans).
struct ReportRow {
  std::string name;  ///< world name or group name
  bool is_group = false;
  std::size_t worlds = 1;  ///< distinct worlds in the row
};

/// Table I's numbers for one row x method. Group rows pool every world x seed episode.
struct MethodStats {
  std::size_t episodes = 0;
  std::size_t successes = 0;  ///< final exploration rate >= 98 %
  Stat t98_s;                 ///< over the episodes that reached 98 %
  Stat l98_m;
  Stat revisits;  ///< over the episodes that recorded it
};

/// Table III's numbers for one row x map type, over every episode of the row (all methods).
struct MapStats {
  std::size_t episodes = 0;
  Stat storage_kb;       ///< KB = 1024 bytes
  Stat update_median_s;  ///< of the per-episode medians
  Stat update_p95_s;     ///< of the per-episode 95th percentiles
};

struct Report {
  std::vector<ReportRow> rows;       ///< paper worlds first, then other worlds, then groups
  std::vector<std::string> methods;  ///< paper order, then others by name
  std::map<std::pair<std::string, std::string>, MethodStats> table1;  ///< (row, method)
  std::map<std::pair<std::string, std::string>, MapStats> table3;     ///< (row, map type)
  std::map<std::string, std::array<bool, 4>> map_types;  ///< method -> maps recorded (Table II)
  std::size_t episodes = 0;
  std::vector<std::filesystem::path> files;
};

/// Success threshold of Table I's success rate (final exploration rate).
inline constexpr double kSuccessRate = 0.98;

Report buildReport(const ResultSet& results);

std::string table1Markdown(const Report& report);
std::string table1Csv(const Report& report);
std::string table2Markdown(const Report& report);
std::string table3Markdown(const Report& report);

/// Writes table1.md, table1.csv, table2.md and table3.md into `directory` (created if
/// needed), each atomically; returns their paths. Throws InputError when it cannot write.
std::vector<std::filesystem::path> writeReport(const Report& report,
                                               const std::filesystem::path& directory);

}  // namespace roomscout::experiment
