#pragma once
// The results.jsonl record of one bench episode: metrics.json's keys plus what a later
// analysis needs without the run's files (README "Benchmarks" lists every field).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "roomscout/experiment/bench_plan.hpp"
#include "roomscout/experiment/recorded_episode.hpp"

namespace roomscout::experiment {

/// Version of the record layout; bumped when a field changes meaning.
inline constexpr int kResultRecordSchema = 1;

/// The four map types of the paper (Tables II and III), in its order.
inline const std::vector<std::string>& mapTypes() {
  static const std::vector<std::string> types = {"occupancy", "pointcloud", "topological",
                                                 "semantic"};
  return types;
}

/// Where the record came from besides the episode itself.
struct RecordContext {
  std::string version;      ///< gitRevision()
  std::string host;         ///< hostName()
  std::string recorded_at;  ///< utcTimestamp()
  std::string outputs;      ///< the run's directory relative to the bench directory, or empty
  std::string start_mode = "world";  ///< "world": the world's start; "random": randomStartPose()
};

/// The record of `episode` of `world`: every key of metrics.json (with `world` set to the
/// bench name of the world), plus schema, world_group, version, host, recorded_at, outputs,
/// start_mode, start (the first pose: x, y [m], yaw [rad]), trajectory (decimated to one pose
/// per `trajectory_period_s`), map_stats and file_bytes.
nlohmann::json makeResultRecord(const BenchWorld& world, const RecordedEpisode& episode,
                                const RecordContext& context, double trajectory_period_s = 1.0);

/// JSON pointers of the fields that depend on the machine, its load or the clock rather than on
/// the episode's inputs: wall_time_s, recorded_at, host, version, and the median and p95 of
/// every update time (update_ms/<kind>/median|p95, map_stats/<map>/update_median_ms|
/// update_p95_ms). Everything else is a function of (world, method, seed, options).
std::vector<nlohmann::json::json_pointer> timingFields(const nlohmann::json& record);

/// `record` without its timingFields().
nlohmann::json withoutTimingFields(nlohmann::json record);

}  // namespace roomscout::experiment
