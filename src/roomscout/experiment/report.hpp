#pragma once
// The statistics of `roomscout report`: per row (a world, or a group of worlds) and method,
// Table I's times and lengths over the episodes every method finished, the revisits, the
// oracle tours, Table II's map types, Table III's map costs and Table IV's comparison of
// settings, built from the records of report_records.hpp. report_tables.hpp lays them out as
// tables; report_markdown.hpp, report_csv.hpp and report_html.hpp render them.

#include <array>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "roomscout/experiment/report_records.hpp"

namespace roomscout::experiment {

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
  Stat false_occupied;        ///< map_accuracy, over the episodes that recorded it
  Stat occupied_precision;    ///< map_accuracy, over the episodes that recorded it
  /// Paired with the main setting: the (world, seed) episodes of the same method that
  /// succeeded in both, and this setting's mean L98 over the main setting's on them.
  std::size_t pairs = 0;
  std::optional<double> l98_ratio;
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

Report buildReport(const ResultSet& results);

/// The row an episode belongs to: its world when built in, else its world's group.
std::string rowNameOf(const EpisodeSummary& episode);

/// A row's title in tables and figures: the world, or "group (N worlds)".
std::string rowTitle(const ReportRow& row);

}  // namespace roomscout::experiment
