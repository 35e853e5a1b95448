#pragma once
// `roomscout report`: tables in the layout of the paper's Tables I-III from one or more
// results.jsonl files. loadResults() gives every episode's key, numbers, curve and (for runs
// that kept their outputs) trajectory; attachOracleTours() (oracle_references.hpp) adds the
// length of a full-knowledge tour of each world; buildReport() the per world x method
// statistics. report_figures.hpp draws the figures, report_writer.hpp writes everything.

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "roomscout/core/geometry.hpp"
#include "roomscout/experiment/episode_key.hpp"
#include "roomscout/plots/html_report.hpp"

namespace roomscout::experiment {

/// One map's numbers in one episode.
struct MapSample {
  double storage_bytes = 0.0;
  std::size_t updates = 0;
  std::optional<double> update_median_ms;
  std::optional<double> update_p95_ms;
};

/// One row of an episode's exploration curve.
struct CurvePoint {
  double length_m = 0.0;  ///< trajectory length driven so far [m]
  double rate = 0.0;      ///< exploration rate, in [0, 1]
};

/// The full-knowledge reference tour of an episode's world (sim/oracle_tour.hpp), planned with
/// the episode's options.
struct OracleReference {
  double length_m = 0.0;       ///< tour length [m]
  double coverage = 0.0;       ///< fraction of the reachable free space it sees, [0, 1]
  std::size_t viewpoints = 0;  ///< viewpoints visited
};

/// The numbers of one recorded episode that the tables and figures use.
struct EpisodeSummary {
  EpisodeKey key;
  std::string world_group;  ///< "builtin" or the folder of the world file
  double exploration_rate = 0.0;
  std::optional<double> t98_s;
  std::optional<double> l98_m;
  std::optional<double> revisits;
  std::optional<double> revisits_98;  ///< revisits up to T98 (none in older records)
  std::map<std::string, MapSample> maps;  ///< by map type (record's map_stats)
  std::string where;                      ///< "file:line" of the record
  /// What io::loadWorld takes to load the world again: a built-in name, or the world file as
  /// the bench was given it (a relative path is relative to where the bench ran). From the
  /// record's world_source ("builtin:NAME" or a path); for records without one, the world's
  /// name when it is a built-in world; else empty.
  std::string world_spec;
  /// The record's option groups that shape the world model and the oracle tour (robot,
  /// world, laser, mapping, costmap) and, for a random start (start_mode "random"), "start":
  /// [x, y, yaw], as compact JSON; empty when the record has neither.
  std::string world_setup;
  bool random_start = false;  ///< the record's start_mode is "random" (bench --random-starts)
  /// The folder with the full outputs of `explore` (seed 1 of a bench): the record's
  /// `outputs` against its results file's folder; empty when the record has none.
  std::filesystem::path outputs_dir;
  std::vector<CurvePoint> curve;   ///< rate against length (record's curve), in order
  std::vector<Vec2> trajectory_m;  ///< positions (map frame), kept only for records with outputs
  std::optional<OracleReference> oracle;  ///< set by attachOracleTours()
};

/// The episode's numbers from a results record. Throws InputError(where, ...) when the key or
/// exploration_rate is missing or a field has the wrong type. `results_dir` is the folder of
/// the results file, against which the record's `outputs` is resolved.
EpisodeSummary summarizeRecord(const nlohmann::json& record, const std::string& where,
                               const std::filesystem::path& results_dir = {});

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
  Stat revisits_98;  ///< revisits up to T98, over the episodes that reached 98 % and recorded it
  /// L98 / oracle tour length of the episode's world, over the episodes that reached 98 %
  /// and have an oracle (for group rows: every plan x seed episode pooled).
  Stat l98_oracle_ratio;
  /// True when the row holds several seeds of some world and, for every such world, all its
  /// seeds gave the same run (same final rate, T98 and L98): a method without random choices
  /// on noise-free sensors. Its sd is then 0 by construction, not by luck.
  bool same_every_seed = false;
};

/// The oracle tour lengths of a row's worlds (one value per world, or with random starts per
/// world and start).
struct OracleRowStats {
  std::size_t worlds = 0;  ///< worlds of the row with an oracle
  Stat length_m;           ///< over those tours
  Stat coverage;
  Stat viewpoints;
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
  std::map<std::string, OracleRowStats> oracle;  ///< by row; rows whose worlds have an oracle
  std::size_t episodes = 0;
  std::size_t random_start_episodes = 0;  ///< episodes started at a pose drawn from their seed
  std::vector<std::filesystem::path> files;

  /// True when some episode has an oracle: Table I then shows L98 / oracle.
  bool hasOracle() const { return !oracle.empty(); }
  /// Methods whose every row with several seeds of a world has same_every_seed, in
  /// `methods` order.
  std::vector<std::string> methodsSameEverySeed() const;
};

/// Success threshold of Table I's success rate (final exploration rate).
inline constexpr double kSuccessRate = 0.98;

Report buildReport(const ResultSet& results);

/// The report's tables as cells, shared by the markdown files and the HTML page: Table I
/// (method rows, per world T98, paper T, L98, paper L, L98 / oracle when known, success),
/// the revisits, the oracle reference (rows with an oracle; none when there is none),
/// Table II and Table III.
plots::HtmlTable table1Cells(const Report& report);
plots::HtmlTable revisitsCells(const Report& report);
std::optional<plots::HtmlTable> oracleCells(const Report& report);
plots::HtmlTable table2Cells(const Report& report);
plots::HtmlTable table3Cells(const Report& report);

/// The text that explains each table (also on the HTML page).
std::string table1Description();
std::string revisitsDescription();
std::string oracleDescription();
std::string table2Description();
std::string table3Description();
/// "N episodes from `file`, ...".
std::string sourcesLine(const Report& report);
/// Names the methods of methodsSameEverySeed() and why their sd is 0; empty when none.
std::string sameEverySeedLine(const Report& report);
/// The sentence saying that (some) episodes started at poses drawn from their seed, or empty.
std::string startPosesLine(const Report& report);

/// The row an episode belongs to: its world when built in, else its world's group.
std::string rowNameOf(const EpisodeSummary& episode);

/// A row's title in tables and figures: the world, or "group (N worlds)".
std::string rowTitle(const ReportRow& row);

std::string table1Markdown(const Report& report);
std::string table1Csv(const Report& report);
std::string table2Markdown(const Report& report);
std::string table3Markdown(const Report& report);

/// Writes table1.md, table1.csv, table2.md and table3.md into `directory` (created if
/// needed), each atomically; returns their paths. Throws InputError when it cannot write.
std::vector<std::filesystem::path> writeReport(const Report& report,
                                               const std::filesystem::path& directory);

}  // namespace roomscout::experiment
