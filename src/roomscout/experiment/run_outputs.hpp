#pragma once
// Writes the files of one exploration run into a directory (DESIGN "Outputs of one run"):
// occupancy.pgm/.yaml, trajectory.csv, metrics.json and run.png, each atomically.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "roomscout/sim/episode.hpp"

namespace roomscout::experiment {

/// Everything a run record holds besides the episode's own result.
struct RunInfo {
  std::string world;         ///< world name
  std::string world_source;  ///< "builtin:NAME" or a path
  std::string method;
  std::uint64_t seed = 0;
  nlohmann::json options;  ///< resolved options, {group: {name: value}}, strategy included
  nlohmann::json maps;     ///< what further maps hold, {map: {...}} (e.g. point count, file
                           ///< bytes); written as metrics.json's `maps` when not null
};

/// metrics.json's content: the keys documented in the README.
nlohmann::json metricsJson(const RunInfo& info, const sim::EpisodeResult& result);

/// A map with a path (blue), its start (green) and end (red) drawn, image row 0 at the top,
/// scaled up so small maps stay legible.
cv::Mat renderMapWithPath(const OccupancyGrid& grid, const std::vector<Pose2>& path);

/// renderMapWithPath of the final map and the trajectory.
cv::Mat renderRun(const sim::EpisodeResult& result);

/// Writes every output file into `directory` (created if needed). Throws InputError naming
/// the directory or file that could not be written; files already written stay complete.
void writeRunOutputs(const std::filesystem::path& directory, const RunInfo& info,
                     const sim::EpisodeResult& result);

}  // namespace roomscout::experiment
