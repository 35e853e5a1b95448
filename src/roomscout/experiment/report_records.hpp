#pragma once
// The records `roomscout report` reads: each episode of one or more results.jsonl files, as
// the numbers the tables and figures use (key, setting, rates, curve, map costs and, for runs
// that kept their outputs, trajectory). report.hpp aggregates them.

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "roomscout/core/geometry.hpp"
#include "roomscout/experiment/episode_key.hpp"

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
  /// The final map's map_accuracy.false_occupied and .occupied_precision (none in records
  /// older than them).
  std::optional<double> false_occupied;
  std::optional<double> occupied_precision;

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

/// Success threshold of Table I's success rate (final exploration rate).
inline constexpr double kSuccessRate = 0.98;

/// The main setting of these episodes, the one Tables I-III are of: the noise-free one ("") when
/// some episode has it, else the setting of the first episode.
std::string mainSetting(const std::vector<EpisodeSummary>& episodes);

/// The episodes of one setting, in order, with the files and counts of `results`.
ResultSet episodesOfSetting(const ResultSet& results, const std::string& setting);

}  // namespace roomscout::experiment
