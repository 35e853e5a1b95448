#pragma once
// `roomscout report`: tables in the layout of the paper's Tables I-III from one or more
// results.jsonl files, and Table IV, which sets each method under sensor noise and SLAM beside
// itself without. loadResults() gives every episode's key, setting, numbers, curve and (for
// runs that kept their outputs) trajectory; attachOracleTours() (oracle_references.hpp) adds
// the length of a full-knowledge tour of each world; buildReport() the per world x method
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
  std::optional<double> revisits_98;      ///< revisits up to T98 (none in older records)
  std::map<std::string, MapSample> maps;  ///< by map type (record's map_stats)
  std::string where;                      ///< "file:line" of the record
  /// What sim::loadWorld takes to load the world again: a built-in name, or the world file as
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
  /// The sensor noise and SLAM the episode ran with, e.g. "noise tb3, slam icp", "noise tb3"
  /// or "slam icp": the record's options noise.profile and slam.mode (else the mode of its
  /// `slam` block), each left out when "none" or absent. Empty for noise-free sensors and the
  /// true pose (and for records older than these options).
  std::string setting;
  /// RMSE of the SLAM pose estimate's positions against the true ones over the run [m]
  /// (record's slam.ate_rmse_m); none without SLAM.
  std::optional<double> ate_rmse_m;
  /// SLAM's error exceeded the configured bound (record's slam.diverged): not a success.
  bool slam_diverged = false;

  /// Final exploration rate >= kSuccessRate and SLAM (if any) did not diverge.
  bool succeeded() const;
};

/// The episode's numbers from a results record. Throws InputError(where, ...) when the key or
/// exploration_rate is missing or a field (also of the `slam` block and the options
/// noise.profile and slam.mode) has the wrong type. `results_dir` is the folder of the results
/// file, against which the record's `outputs` is resolved.
EpisodeSummary summarizeRecord(const nlohmann::json& record, const std::string& where,
                               const std::filesystem::path& results_dir = {});

/// Episodes merged from several results files, one per key and setting.
struct ResultSet {
  std::vector<EpisodeSummary> episodes;      ///< in input order
  std::vector<std::filesystem::path> files;  ///< the results files read
  /// Records dropped because their key and setting came earlier.
  std::size_t duplicates = 0;
  std::size_t truncated = 0;  ///< files that ended in a truncated line (ignored)
};

/// Reads each input (a bench directory, meaning its results.jsonl, or a .jsonl file) and
/// merges the records; of records with the same key and setting the first one read is kept
/// (the same world, method and seed under another setting is another episode). Throws
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
/// T98, L98 and the ratios are over the row's paired episodes (see PairedRow): the (world,
/// seed) pairs that every method of the row finished, so that each method's mean is over the
/// same runs as every other's.
struct MethodStats {
  std::size_t episodes = 0;
  std::size_t successes = 0;  ///< EpisodeSummary::succeeded(): final rate >= 98 %, not diverged
  Stat t98_s;                 ///< over the row's paired episodes
  Stat l98_m;                 ///< over the row's paired episodes
  /// T98 and L98 over this method's own successful episodes, whatever the other methods did
  /// (table1.csv only: a method that fails the hard runs looks faster here).
  Stat own_t98_s;
  Stat own_l98_m;
  /// Per paired episode, L98 (T98) over the reference method's (Report::reference) on the same
  /// world and seed; none when the reference has no episode in the row.
  Stat l98_reference_ratio;
  Stat t98_reference_ratio;
  /// The (world, seed) pairs of the row that both this method and semantic finished, and how
  /// many of them this method drove a shorter L98 on (a tie does not count); 0 for semantic
  /// itself and when semantic has no episode in the row.
  std::size_t semantic_pairs = 0;
  std::size_t beats_semantic = 0;
  Stat revisits;     ///< over the episodes that recorded it
  Stat revisits_98;  ///< revisits up to T98, over the episodes that reached 98 % and recorded it
  /// L98 / oracle tour length of the episode's world, over the row's paired episodes that have
  /// an oracle (for group rows: every plan x seed episode pooled).
  Stat l98_oracle_ratio;
  /// True when the row holds several seeds of some world and, for every such world, all its
  /// seeds gave the same run (same final rate, T98 and L98): a method without random choices
  /// on noise-free sensors. Its sd is then 0 by construction, not by luck.
  bool same_every_seed = false;
};

/// Which episodes Table I's means of a row are over: a (world, seed) pair is paired when every
/// method with episodes in the row has a successful episode (EpisodeSummary::succeeded(), with
/// T98 and L98) of that world and seed. Group rows pair per world and seed.
struct PairedRow {
  std::size_t methods = 0;    ///< methods with episodes in the row
  std::size_t pairs = 0;      ///< (world, seed) pairs every one of them finished
  std::size_t all_pairs = 0;  ///< (world, seed) pairs with an episode of some method
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

/// Table IV's numbers for one row x method in one setting. Group rows pool every world x seed
/// episode.
struct SettingStats {
  std::size_t episodes = 0;
  std::size_t successes = 0;  ///< EpisodeSummary::succeeded()
  std::size_t diverged = 0;   ///< episodes whose SLAM diverged
  Stat t98_s;                 ///< over the successful episodes
  Stat l98_m;                 ///< over the successful episodes
  Stat ate_rmse_m;            ///< over the episodes that recorded it
};

/// Table IV: each method under the settings other than the main one (see Report), beside the
/// same method in the main setting.
struct SettingComparison {
  std::vector<std::string> settings;  ///< the other settings, in order of first appearance
  std::map<std::string, std::size_t> episodes;  ///< episodes of each other setting
  std::vector<ReportRow> rows;                  ///< rows with episodes in another setting
  std::vector<std::string> methods;             ///< methods with episodes in another setting
  /// (row, method) -> setting -> numbers, for the (row, method) pairs with episodes in another
  /// setting; the main setting is there too when that pair has episodes in it.
  std::map<std::pair<std::string, std::string>, std::map<std::string, SettingStats>> cells;
};

/// Tables I-III, the figures and every count are of the episodes of the main setting: the
/// noise-free one ("") when some episode has it, else the setting of the first episode. Table
/// IV compares the other settings with it.
struct Report {
  std::vector<ReportRow> rows;       ///< paper worlds first, then other worlds, then groups
  std::vector<std::string> methods;  ///< paper order, then others by name
  std::map<std::pair<std::string, std::string>, MethodStats> table1;  ///< (row, method)
  std::map<std::string, PairedRow> paired;                            ///< by row
  /// The method Table I's ratios are to: rrt when some episode has it, else the first of
  /// `methods`; empty without episodes.
  std::string reference;
  std::map<std::pair<std::string, std::string>, MapStats> table3;  ///< (row, map type)
  std::map<std::string, std::array<bool, 4>> map_types;  ///< method -> maps recorded (Table II)
  std::map<std::string, OracleRowStats> oracle;  ///< by row; rows whose worlds have an oracle
  std::size_t episodes = 0;                      ///< of the main setting
  std::size_t random_start_episodes = 0;  ///< episodes started at a pose drawn from their seed
  std::vector<std::filesystem::path> files;
  std::string main_setting;  ///< EpisodeSummary::setting of the episodes of Tables I-III
  SettingComparison table4;  ///< empty when every episode is of the main setting

  /// True when semantic is one of the methods: Table I then shows how often each method
  /// beats it.
  bool hasSemantic() const;
  /// True when some episode has an oracle: Table I then shows L98 / oracle.
  bool hasOracle() const { return !oracle.empty(); }
  /// True when some episode is of another setting than the main one: Table IV exists.
  bool hasTable4() const { return !table4.settings.empty(); }
  /// Methods whose every row with several seeds of a world has same_every_seed, in
  /// `methods` order.
  std::vector<std::string> methodsSameEverySeed() const;
};

/// Success threshold of Table I's success rate (final exploration rate).
inline constexpr double kSuccessRate = 0.98;

/// The main setting of these episodes (see Report).
std::string mainSetting(const std::vector<EpisodeSummary>& episodes);

/// The episodes of one setting, in order, with the files and counts of `results`.
ResultSet episodesOfSetting(const ResultSet& results, const std::string& setting);

Report buildReport(const ResultSet& results);

/// The report's tables as cells, shared by the markdown files and the HTML page: Table I
/// (method rows, per world T98, paper T, L98, paper L (T98 and L98 over the row's paired
/// episodes, "no shared pair" when there are none), L98 and T98 over the reference's, L98 /
/// oracle when known, the share of pairs that beat semantic when semantic is there, success),
/// the revisits, the oracle reference (rows with an oracle; none when there is none),
/// Table II and Table III, and Table IV (none when every episode is of the main setting).
plots::HtmlTable table1Cells(const Report& report);
plots::HtmlTable revisitsCells(const Report& report);
std::optional<plots::HtmlTable> oracleCells(const Report& report);
plots::HtmlTable table2Cells(const Report& report);
plots::HtmlTable table3Cells(const Report& report);
/// Table IV: a line per row x method with episodes in another setting; World, Method, then the
/// main setting's T98, L98 and success, then per other setting (in order of first appearance)
/// its T98, L98, success (with the diverged runs counted when there are any), ATE and L98
/// ratio (its mean L98 over the main setting's).
std::optional<plots::HtmlTable> slamCells(const Report& report);

/// The text that explains each table (also on the HTML page).
std::string table1Description();
/// Which episodes Table I's means are over in this report: per row the paired (world, seed)
/// pairs out of all, the reference method of the ratios, what "beats semantic" counts.
std::string pairingLine(const Report& report);
std::string revisitsDescription();
std::string oracleDescription();
std::string table2Description();
std::string table3Description();
std::string slamDescription();
/// "N episodes from `file`, ...", and how many episodes of other settings Table IV holds.
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
/// Table IV's heading, description, sources and table; empty when there is no Table IV.
std::string slamMarkdown(const Report& report);

/// Writes table1.md, table1.csv, table2.md, table3.md and, when the report has other settings,
/// table4_slam.md into `directory` (created if needed), each atomically; returns their paths.
/// Throws InputError when it cannot write.
std::vector<std::filesystem::path> writeReport(const Report& report,
                                               const std::filesystem::path& directory);

}  // namespace roomscout::experiment
