#include "roomscout/experiment/result_record.hpp"

#include <cmath>
#include <map>

namespace roomscout::experiment {
namespace {

/// `v` rounded to `decimals` decimal places (dividing by a power of ten keeps the JSON short).
double rounded(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(v * scale) / scale;
}

/// The files holding each map's data (visualisations such as run.png or semantic.png are not
/// the map, so they do not count towards its storage).
const std::map<std::string, std::vector<std::string>>& mapDataFiles() {
  static const std::map<std::string, std::vector<std::string>> files = {
      {"occupancy", {"occupancy.pgm", "occupancy.yaml"}},
      {"pointcloud", {"pointcloud.pcd"}},
      {"topological", {"topology.json"}},
      {"semantic", {"semantic.json", "semantic_labels.png"}},
  };
  return files;
}

}  // namespace

nlohmann::json makeResultRecord(const BenchWorld& world, const RecordedEpisode& episode,
                                const RecordContext& context, double trajectory_period_s) {
  nlohmann::json record = episode.metrics;
  record["schema"] = kResultRecordSchema;
  record["world"] = world.name;
  record["world_group"] = world.group;
  record["version"] = context.version;
  record["host"] = context.host;
  record["recorded_at"] = context.recorded_at;
  record["outputs"] =
      context.outputs.empty() ? nlohmann::json(nullptr) : nlohmann::json(context.outputs);

  // The trajectory at about one pose per period: the first pose, then the first pose at least a
  // period after the last one kept, and always the last pose.
  nlohmann::json trajectory = nlohmann::json::array();
  const std::vector<sim::TrajectorySample>& samples = episode.result.trajectory;
  double next_s = -1e300;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const sim::TrajectorySample& s = samples[i];
    if (s.time_s + 1e-9 < next_s && i + 1 != samples.size()) continue;
    trajectory.push_back({rounded(s.time_s, 3), rounded(s.pose.x_m, 4), rounded(s.pose.y_m, 4),
                          rounded(s.pose.yaw_rad, 4)});
    next_s = s.time_s + trajectory_period_s;
  }
  record["start_mode"] = context.start_mode;
  if (!samples.empty()) {
    const Pose2& p = samples.front().pose;
    record["start"] = {rounded(p.x_m, 4), rounded(p.y_m, 4), rounded(p.yaw_rad, 4)};
  }
  record["trajectory_columns"] = {"time_s", "x_m", "y_m", "yaw_rad"};
  record["trajectory"] = std::move(trajectory);

  nlohmann::json file_bytes = nlohmann::json::object();
  for (const auto& [name, bytes] : episode.file_bytes) {
    // metrics.json's size varies with the digits of its timings: not a property of the run.
    if (name != "metrics.json") file_bytes[name] = bytes;
  }
  record["file_bytes"] = file_bytes;

  nlohmann::json map_stats = nlohmann::json::object();
  const nlohmann::json& update_ms = episode.metrics.at("update_ms");
  for (const std::string& type : mapTypes()) {
    nlohmann::json stats;
    std::uintmax_t storage = 0;
    nlohmann::json files = nlohmann::json::array();
    for (const std::string& f : mapDataFiles().at(type)) {
      files.push_back(f);
      const auto it = episode.file_bytes.find(f);
      if (it != episode.file_bytes.end()) storage += it->second;
    }
    stats["files"] = files;
    stats["storage_bytes"] = storage;
    if (update_ms.contains(type)) {
      stats["updates"] = update_ms[type].at("count");
      stats["update_median_ms"] = update_ms[type].at("median");
      stats["update_p95_ms"] = update_ms[type].at("p95");
    } else {
      stats["updates"] = 0;
      stats["update_median_ms"] = nullptr;
      stats["update_p95_ms"] = nullptr;
    }
    map_stats[type] = stats;
  }
  record["map_stats"] = map_stats;
  return record;
}

std::vector<nlohmann::json::json_pointer> timingFields(const nlohmann::json& record) {
  using Ptr = nlohmann::json::json_pointer;
  std::vector<Ptr> fields;
  for (const char* key : {"wall_time_s", "recorded_at", "host", "version"}) {
    if (record.contains(key)) fields.push_back(Ptr() / key);
  }
  struct Timed {
    const char* group;
    std::vector<const char*> quantiles;
  };
  static const Timed kTimed[] = {{"update_ms", {"median", "p95", "by_known_area"}},
                                 {"map_stats", {"update_median_ms", "update_p95_ms"}}};
  for (const Timed& t : kTimed) {
    if (!record.contains(t.group) || !record[t.group].is_object()) continue;
    for (const auto& [name, stats] : record[t.group].items()) {
      for (const char* q : t.quantiles) {
        if (stats.is_object() && stats.contains(q)) fields.push_back(Ptr() / t.group / name / q);
      }
    }
  }
  return fields;
}

nlohmann::json withoutTimingFields(nlohmann::json record) {
  for (const nlohmann::json::json_pointer& p : timingFields(record)) {
    record[p.parent_pointer()].erase(p.back());
  }
  return record;
}

}  // namespace roomscout::experiment
